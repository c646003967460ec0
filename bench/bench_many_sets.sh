#!/usr/bin/env bash
# Many small sets: `sphdeck check` on decks with one *SET_NODE_LIST and one *INITIAL_VELOCITY per
# particle (as some pre-processors write them), at N and 4N particles. Linear work gives a time
# ratio near 4; a rule that scans every set for every card gives near 16 (before the fix, 6.1 s
# and 129 s for 10,000 and 40,000 particles on the project's 2-core VM).
#
#   bash bench/bench_many_sets.sh BUILD_DIR        (part of `make bench`; builds nothing)
set -euo pipefail
if [ $# -ne 1 ] || [ ! -x "$1/sphdeck" ] || [ ! -x "$1/measure_command" ]; then
  echo "usage: $0 BUILD_DIR (holding sphdeck and measure_command)" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mkdir -p "$root/bench/out"
runs=${BENCH_RUNS:-3}
declare -A seconds
for side in 100 200; do
  deck="$root/bench/out/velocity_sets_$side.k"
  python3 "$root/bench/make_velocity_sets_deck.py" "$side" > "$deck"
  line=$(env OMP_NUM_THREADS=1 "$build/measure_command" "$runs" -- "$build/sphdeck" check "$deck" | tail -n 1)
  seconds[$side]=$(sed -n 's/.*median_seconds=\([0-9.]*\).*/\1/p' <<<"$line")
  echo "many sets: $((side * side)) particles, one set and one *INITIAL_VELOCITY each: check ${seconds[$side]} s (median of $runs)"
done
awk -v a="${seconds[100]}" -v b="${seconds[200]}" 'BEGIN {
  r = b / a; printf "many sets: 4x the particles took %.1fx the time (linear: about 4; quadratic: about 16): %s\n",
  r, (r < 8 ? "linear" : "NOT linear") }'
