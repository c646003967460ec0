#!/usr/bin/env bash
# The sphdeck demo (`make demo`): `sphdeck check` on a deck with typical SPH mistakes, then the
# smoothing-length preview of the clean dam break deck.
# Usage: decks/demo/run_demo.sh [path/to/sphdeck]   (default: $SPHDECK, else build/sphdeck)
# Exits 0 when both steps ran as expected: the check finds the mistakes (its exit 1 is the point
# of the demo) and the preview of the clean deck succeeds.
set -u
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sphdeck="${1:-${SPHDECK:-$root/build/sphdeck}}"
if [ ! -x "$sphdeck" ]; then
    echo "run_demo.sh: no sphdeck binary at '$sphdeck' (build it first: make build)" >&2
    exit 2
fi
sphdeck="$(cd "$(dirname "$sphdeck")" && pwd)/$(basename "$sphdeck")"
cd "$root" || exit 2  # deck paths in the output stay short: decks/demo/...

echo "==> sphdeck check decks/demo/sph_mistakes_2d.k    (a deck with typical mistakes)"
echo
"$sphdeck" check --no-config decks/demo/sph_mistakes_2d.k
status=$?
if [ "$status" -ne 1 ]; then
    echo "run_demo.sh: expected 'sphdeck check' to find errors (exit 1), got exit $status" >&2
    exit 1
fi

echo
echo "==> sphdeck smooth decks/demo/dam_break_2d.k    (the clean deck: smoothing length, neighbours, time step)"
echo
"$sphdeck" smooth decks/demo/dam_break_2d.k || exit 1
