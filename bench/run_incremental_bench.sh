#!/usr/bin/env bash
# Big decks in the editor (issue 29 item 5, issue 45): bench_incremental's profile of one check and its
# figures beside the issue 45 goals (open <= 700 ms, edit outside the bulk blocks <= 50 ms, inside
# <= 100 ms, 10,000-line deck edit <= 10 ms, a burst of 200 changes: the last -> diagnostics <= 1 s),
# wall and CPU medians.
#
#   bash bench/run_incremental_bench.sh BUILD_DIR      (about 30 s on 16 idle cores; BENCH_RUNS=3)
#
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
"$build/bench_incremental" bench/out/big.k bench/out/lsp_10k_lines.k "${BENCH_RUNS:-3}" || exit 1
