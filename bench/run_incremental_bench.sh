#!/usr/bin/env bash
# Big decks in the editor (issue 29 item 5, issue 45): bench_incremental's profile of one check and its
# figures beside the issue 45 goals (open <= 700 ms, edit outside the bulk blocks <= 50 ms, inside
# <= 100 ms, 10,000-line deck edit <= 10 ms, a burst of 200 changes: the last -> diagnostics <= 1 s),
# wall and CPU medians.
#
#   bash bench/run_incremental_bench.sh BUILD_DIR      (about 30 s on 16 idle cores; BENCH_RUNS=3)
#
# The goals hold where dynareadout reads the 1M-particle deck in about 0.3 s (issue 45): with
# DYNAREADOUT_SRC or DYNAREADOUT_PEER (bench/dynareadout_peer.sh) that read is timed first and printed
# with the factor to scale the goals by on this machine.
# Builds nothing: BUILD_DIR must hold bench_incremental and gen_big_deck. Generates bench/out/big.k
# (1,000,000 particles) and bench/out/lsp_10k_lines.k (4,988 particles, 10,000 lines) when missing,
# the decks bench_lsp.py uses. Prints the machine's core count and OMP_NUM_THREADS first.
# Exit status: 0 when the measurements ran (goals met or not), 1 when a run failed, 2 on a set-up error.
set -euo pipefail

if [ $# -ne 1 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
for tool in bench_incremental gen_big_deck; do
  if [ ! -x "$build/$tool" ]; then
    echo "run_incremental_bench: $build/$tool is missing; build it first (cmake --build $1 --target $tool)" >&2
    exit 2
  fi
done
mkdir -p bench/out
make_deck() {  # PATH PARTICLES: generated unless a deck of that particle count is there
  if [ ! -f "$1" ] || ! head -n 1 "$1" | grep -q "gen_big_deck: $2 SPH particles"; then
    "$build/gen_big_deck" "$1.tmp" "$2" >/dev/null && mv "$1.tmp" "$1"
  fi
}
make_deck bench/out/big.k 1000000
make_deck bench/out/lsp_10k_lines.k 4988
# `sphdeck lsp` runs with OMP_WAIT_POLICY=passive unless told otherwise (cli/cmd_lsp.cpp): so does
# the in-process benchmark of it.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
echo "cores: $(nproc), OMP_NUM_THREADS=${OMP_NUM_THREADS:-(unset)}, OMP_WAIT_POLICY=$OMP_WAIT_POLICY"
source bench/dynareadout_peer.sh
peer=$(dynareadout_peer)
if [ -n "$peer" ]; then
  cat bench/out/big.k >/dev/null  # in the page cache, as for the server's reads
  walls=() cpus=()
  for _ in $(seq "${BENCH_RUNS:-3}"); do
    /usr/bin/time -f "%e %U %S" -o bench/out/peer.time "$peer" bench/out/big.k >/dev/null
    read -r wall user sys <bench/out/peer.time
    walls+=("$wall") cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')")
  done
  median_of() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
  read_wall=$(median_of "${walls[@]}") read_cpu=$(median_of "${cpus[@]}")
  # The smaller of the two scales the goals the least: CPU seconds, unless the wall is shorter.
  read_s=$(awk -v w="$read_wall" -v c="$read_cpu" 'BEGIN { print (c < w ? c : w) }')
  echo "dynareadout reads bench/out/big.k in $read_wall s wall, $read_cpu s CPU (medians of ${#walls[@]}):" \
    "the goals below hold where it takes about 0.3 s; here scale them by" \
    "$(awk -v s="$read_s" 'BEGIN { printf "%.2f", s / 0.3 }') (by the shorter of the two)"
else
  echo "dynareadout: no peer (DYNAREADOUT_SRC or DYNAREADOUT_PEER, bench/dynareadout_peer.sh): the goals are" \
    "those of a machine where it reads the deck in about 0.3 s"
fi
"$build/bench_incremental" bench/out/big.k bench/out/lsp_10k_lines.k "${BENCH_RUNS:-3}" || exit 1
