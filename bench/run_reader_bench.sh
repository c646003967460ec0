#!/usr/bin/env bash
# Reader benchmark: how fast `sphdeck check` reads a big deck, compared with `wc -l` on the same file.
#
#   bash bench/run_reader_bench.sh BUILD_DIR          (what `make bench` runs)
#
# Builds nothing: BUILD_DIR must already hold sphdeck, gen_big_deck and measure_command. Generates
# bench/out/big.k (BENCH_NODES particles, default 1000000, ~106 MB) when it is missing or was made for
# another particle count, then runs each command BENCH_RUNS times (default 5) and prints medians.
# MB means 2^20 bytes throughout (ru_maxrss is reported in KiB). Exit status: 0 when the measurements
# ran (goals met or not; set BENCH_STRICT=1 to exit 1 on a missed goal), 1 when a run failed, 2 on a
# usage or set-up error.
set -euo pipefail

if [ $# -ne 1 ]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
if [ ! -d "$1" ]; then
  echo "run_reader_bench: build directory '$1' not found (configure and build first, e.g. 'make build')" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

runs=${BENCH_RUNS:-5}
nodes=${BENCH_NODES:-1000000}
goal_mb_s=150
deck=bench/out/big.k

for tool in sphdeck gen_big_deck measure_command; do
  if [ ! -x "$build/$tool" ]; then
    echo "run_reader_bench: $build/$tool is missing; build it first (cmake --build $1)" >&2
    exit 2
  fi
done

# The first line of a generated deck names its particle count: regenerate when it differs.
mkdir -p bench/out
if [ -f "$deck" ] && ! head -n 1 "$deck" | grep -q "gen_big_deck: $nodes SPH particles"; then
  echo "$deck was generated for another particle count; regenerating"
  rm -f "$deck"
fi
if [ ! -f "$deck" ]; then
  echo "generating $deck ($nodes particles)..."
  start=$(date +%s.%N)
  "$build/gen_big_deck" "$deck.tmp" "$nodes"
  mv "$deck.tmp" "$deck"
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "generated in %.2f s\n", b - a }'
fi

bytes=$(stat -c %s "$deck")
size_mb=$(awk -v b="$bytes" 'BEGIN { printf "%.1f", b / 1048576 }')
echo "deck: $deck, $size_mb MB ($bytes bytes, $(wc -l < "$deck") lines)"
cat "$deck" > /dev/null   # warm the page cache so that every run reads from memory

# measure LABEL CMD ARGS...: prints the per-run lines, sets median_s and median_rss.
measure() {
  local label=$1 out
  shift
  echo
  echo "== $label: $runs runs of: $*"
  if ! out=$("$build/measure_command" "$runs" -- "$@"); then
    echo "$out"
    echo "run_reader_bench: '$label' failed (see above)" >&2
    exit 1
  fi
  echo "$out"
  local last=${out##*$'\n'}
  if [[ ! $last =~ ^median_seconds=([0-9.]+)\ median_peak_rss_mb=([0-9.]+)$ ]]; then
    echo "run_reader_bench: cannot parse measure_command output: $last" >&2
    exit 1
  fi
  median_s=${BASH_REMATCH[1]}
  median_rss=${BASH_REMATCH[2]}
}

# The reader goal is measured on what reads: `check --no-geometry` reads, decodes every card, builds
# the model and runs every rule but the neighbour-based ones. The full check is printed beside it.
measure "sphdeck check --no-geometry" "$build/sphdeck" check --no-geometry "$deck"
check_s=$median_s
check_rss=$median_rss
measure "sphdeck check (all rules)" "$build/sphdeck" check "$deck"
full_s=$median_s
full_rss=$median_rss
measure "wc -l" wc -l "$deck"
wc_s=$median_s
wc_rss=$median_rss

echo
awk -v size="$size_mb" -v cs="$check_s" -v cr="$check_rss" -v fs="$full_s" -v fr="$full_rss" \
    -v ws="$wc_s" -v wr="$wc_rss" -v goal="$goal_mb_s" -v strict="${BENCH_STRICT:-0}" '
function rate(s) { return s > 0 ? size / s : 0 }
function verdict(ok) { return ok ? "met" : "NOT MET" }
BEGIN {
  c = rate(cs); f = rate(fs); w = rate(ws)
  printf "%-30s %12s %10s %14s\n", "command", "median s", "MB/s", "peak RSS MB"
  printf "%-30s %12.4f %10.1f %14.1f\n", "sphdeck check --no-geometry", cs, c, cr
  printf "%-30s %12.4f %10.1f %14.1f\n", "sphdeck check (all rules)", fs, f, fr
  printf "%-30s %12.4f %10.1f %14.1f\n", "wc -l", ws, w, wr
  printf "\nreader (check --no-geometry) at %.3f of the speed of wc -l (wc -l is %.1fx faster)\n", \
         (w > 0 ? c / w : 0), (c > 0 ? w / c : 0)
  printf "peak RSS of the reader: %.1f MB = %.2f x the deck size (%.1f MB); all rules: %.2f x\n\n", \
         cr, cr / size, size, fr / size
  speed_ok = c >= goal
  rss_ok = cr <= 2 * size
  printf "goal: %-36s %10.1f MB/s  %s\n", sprintf("reader >= %d MB/s", goal), c, verdict(speed_ok)
  printf "goal: %-36s %10.1f MB    %s\n", sprintf("peak RSS <= 2 x deck = %.1f MB", 2 * size), cr, verdict(rss_ok)
  exit (strict == 1 && !(speed_ok && rss_ok)) ? 1 : 0
}'
