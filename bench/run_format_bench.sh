#!/usr/bin/env bash
# Format benchmark (issue 27 item 6): `sphdeck format` of the 1M-particle benchmark deck against
# `sphdeck check --no-geometry` on the same deck; goals: `format --check` within 0.5x of check (issue 40
# item 5), `format` in place and `format --diff` of a deck whose every line changes within 2x (issue 27).
#
#   bash bench/run_format_bench.sh BUILD_DIR
#
# Builds nothing: BUILD_DIR must hold sphdeck, gen_big_deck and measure_command. Uses bench/out/big.k
# (generated as run_reader_bench.sh does when missing). Runs each command BENCH_RUNS times (default 5)
# and prints the medians, their ratio and the goal. Two formats are timed: `format --check` (reads,
# lays out every line, writes nothing) and `format` of a copy of the deck (writes the file when a line
# changes: on a deck laid out already, nothing is written). A third deck, every value left-aligned,
# times the case where every card line changes (`format --diff > /dev/null`, the whole diff printed).
# Exit status: 0 when the measurements ran (goal met or not; BENCH_STRICT=1: exit 1 on a missed goal),
# 1 when a run failed, 2 on a usage or set-up error.
set -euo pipefail

if [ $# -ne 1 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BUILD_DIR (an existing build directory)" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
runs=${BENCH_RUNS:-5}
nodes=${BENCH_NODES:-1000000}
deck=bench/out/big.k
for tool in sphdeck gen_big_deck measure_command; do
  if [ ! -x "$build/$tool" ]; then
    echo "run_format_bench: $build/$tool is missing; build it first (cmake --build $1)" >&2
    exit 2
  fi
done
mkdir -p bench/out
if [ -f "$deck" ] && ! head -n 1 "$deck" | grep -q "gen_big_deck: $nodes SPH particles"; then rm -f "$deck"; fi
if [ ! -f "$deck" ]; then
  echo "generating $deck ($nodes particles)..."
  "$build/gen_big_deck" "$deck.tmp" "$nodes"
  mv "$deck.tmp" "$deck"
fi
# The same deck with every number of its *NODE and *ELEMENT_SPH lines moved to the left of its field.
left=bench/out/big_left.k
if [ ! -f "$left" ] || [ "$left" -ot "$deck" ]; then
  awk '/^\*/ { block = $1 } /^[ 0-9.eE+-]+$/ && (block == "*NODE" || block == "*ELEMENT_SPH") {
         out = ""; n = split($0, v, " "); w = (block == "*NODE") ? "8 16 16 16" : "8 8 16";
         split(w, width, " ");
         for (i = 1; i <= n; i++) out = out sprintf("%-" (i <= 4 ? width[i] : 8) "s", v[i]);
         sub(/ +$/, "", out); print out; next } { print }' "$deck" > "$left.tmp"
  mv "$left.tmp" "$left"
fi
cat "$deck" "$left" > /dev/null  # warm the page cache

measure() {
  local label=$1 out
  shift
  echo
  echo "== $label: $runs runs of: $*"
  if ! out=$("$build/measure_command" "$runs" -- "$@"); then
    echo "$out"
    echo "run_format_bench: '$label' failed" >&2
    exit 1
  fi
  echo "$out"
  local last=${out##*$'\n'}
  [[ $last =~ ^median_seconds=([0-9.]+)\ median_peak_rss_mb=([0-9.]+)$ ]] || { echo "cannot parse: $last" >&2; exit 1; }
  median_s=${BASH_REMATCH[1]}
}

measure "check --no-geometry" "$build/sphdeck" check --no-geometry --format concise "$deck"
check_s=$median_s
measure "format --check" "$build/sphdeck" format --check "$deck"
format_check_s=$median_s
cp "$deck" bench/out/big_copy.k
measure "format (in place)" "$build/sphdeck" format bench/out/big_copy.k
format_s=$median_s
measure "check --no-geometry (left-aligned deck)" "$build/sphdeck" check --no-geometry --format concise "$left"
check_left_s=$median_s
measure "format --diff (left-aligned deck: every card line changes)" sh -c "exec '$build/sphdeck' format --diff '$left' > /dev/null"
format_left_s=$median_s
rm -f bench/out/big_copy.k

echo
printf '%-46s %9s %9s %7s %s\n' "figure" "check s" "format s" "ratio" "goal"
missed=0
row() {  # NAME CHECK_S FORMAT_S GOAL (the largest ratio format / check)
  local ratio
  ratio=$(awk -v a="$3" -v b="$2" 'BEGIN { printf "%.2f", a / b }')
  local verdict=met
  awk -v r="$ratio" -v g="$4" 'BEGIN { exit !(r <= g) }' || { verdict=missed; missed=1; }
  printf '%-46s %9s %9s %6sx %s\n' "$1" "$2" "$3" "$ratio" "<= $4x ($verdict)"
}
row "format --check vs check --no-geometry" "$check_s" "$format_check_s" 0.50
row "format (in place) vs check --no-geometry" "$check_s" "$format_s" 2.00
row "format --diff, every line changes" "$check_left_s" "$format_left_s" 2.00
if [ "${BENCH_STRICT:-0}" = 1 ] && [ $missed = 1 ]; then exit 1; fi
