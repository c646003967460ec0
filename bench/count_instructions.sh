#!/usr/bin/env bash
# Instructions executed by `sphdeck check` on the 1M-particle deck, with every rule and with --no-geometry,
# beside dynareadout's streaming reader: valgrind's cachegrind counts them exactly, the same on every run,
# where wall and CPU times on a shared virtual machine move by a third between runs (bench/README.md, stop 68).
# A count is not a time (a division or a cache miss costs more than an addition), but a change that removes
# work shows here at once, where timing it would take dozens of paired runs.
#
#   bash bench/count_instructions.sh BUILD_DIR [DECK]
#
# DECK: bench/out/big.k by default (generated with BUILD_DIR/gen_big_deck when missing; BENCH_NODES particles,
# 1000000). DYNAREADOUT_PEER names a built peer (bench/dynareadout_peer.sh); without it the peer is left out.
# Each command runs once on one thread (cachegrind runs it 30-60 times slower: about a minute each).
# Exit status: 0 when the counts ran, 1 when a run failed, 2 on a set-up error (valgrind or a tool missing).
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BUILD_DIR [DECK]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
command -v valgrind >/dev/null || { echo "count_instructions: valgrind is missing (apt install valgrind)" >&2; exit 2; }
[ -x "$build/sphdeck" ] || { echo "count_instructions: $build/sphdeck is missing; build it first" >&2; exit 2; }
deck=${2:-$root/bench/out/big.k}
if [ ! -f "$deck" ]; then
  [ -x "$build/gen_big_deck" ] || { echo "count_instructions: no $deck and no $build/gen_big_deck" >&2; exit 2; }
  mkdir -p "$(dirname "$deck")"
  "$build/gen_big_deck" "$deck" "${BENCH_NODES:-1000000}" >/dev/null
fi
# The deck's folder gets an empty configuration, so that no sphdeck.toml above it changes the rules.
folder=$(cd "$(dirname "$deck")" && pwd)
[ -f "$folder/.sphdeck.toml" ] || : >"$folder/.sphdeck.toml"
export OMP_NUM_THREADS=1

# count LABEL CMD...: prints the label and the instructions (millions) the command executed.
count() {
  local label=$1 log
  shift
  log=$(mktemp)
  if ! (cd "$folder" && valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$@") \
    >/dev/null 2>"$log"; then
    # sphdeck exits 1 on findings: only a missing count is a failure.
    grep -q "I *refs" "$log" || { cat "$log" >&2; rm -f "$log"; echo "count_instructions: '$label' failed" >&2; exit 1; }
  fi
  instructions=$(sed -n 's/.*I *refs: *\([0-9,]*\).*/\1/p' "$log" | tr -d ,)
  rm -f "$log"
  printf '  %-36s %8.0f M instructions\n' "$label" "$(awk -v n="$instructions" 'BEGIN { print n / 1e6 }')"
}

echo "== instructions, $(basename "$deck") ($(du -m "$deck" | cut -f1) MB), 1 thread (cachegrind)"
peer=""
if [ -n "${DYNAREADOUT_PEER:-}" ] && [ -x "$DYNAREADOUT_PEER" ]; then
  count "dynareadout (peer)" "$DYNAREADOUT_PEER" "$deck"
  peer=$instructions
fi
count "check --no-geometry" "$build/sphdeck" check --no-geometry "$deck"
no_geometry=$instructions
count "check, every rule" "$build/sphdeck" check "$deck"
every_rule=$instructions
if [ -n "$peer" ]; then
  awk -v p="$peer" -v a="$no_geometry" -v b="$every_rule" 'BEGIN {
    printf "  the peer'"'"'s instructions / check --no-geometry'"'"'s   %5.2fx  (its goal, 2.0x, is on time)\n", p / a
    printf "  the peer'"'"'s instructions / check'"'"'s                 %5.2fx  (its goal, 1.0x, is on time)\n", p / b
  }'
fi
