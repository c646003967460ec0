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

# Figures of issue 19, each beside today's baseline (the issue and bench/README.md, measured on the
# 2-core project VM before the reader work): `check` with every rule on one thread, `--no-geometry`
# on one thread, every rule on two threads, `smooth`, and the peak RSS against the deck size.
base_full_mb_s=${BENCH_BASE_FULL:-180}      # check, all rules, 1 thread (0.59 s)
base_nogeo_mb_s=${BENCH_BASE_NOGEO:-212}    # check --no-geometry, 1 thread (0.468-0.483 s)
base_smooth_s=${BENCH_BASE_SMOOTH:-1.15}    # smooth on the 1M-particle deck
base_full_rss=3.41                          # peak RSS / deck size, all rules
base_nogeo_rss=1.98                         # peak RSS / deck size, --no-geometry
# The same old binary measured on the current (slower, shared) host, old and new runs interleaved:
# the fair comparison there. Seconds and MB; override with BENCH_HOST_* for another host.
host_full_s=${BENCH_HOST_FULL:-1.45}        # check, all rules, 1 thread
host_nogeo_s=${BENCH_HOST_NOGEO:-0.89}      # check --no-geometry, 1 thread
host_two_s=${BENCH_HOST_TWO:-1.69}          # check, all rules, 2 threads
host_smooth_s=${BENCH_HOST_SMOOTH:-2.60}    # smooth
host_full_rss=${BENCH_HOST_FULL_RSS:-353}   # peak RSS MB, all rules
host_nogeo_rss=${BENCH_HOST_NOGEO_RSS:-206} # peak RSS MB, --no-geometry

# OMP_NUM_THREADS goes through env(1): measure_command runs the command as given.
measure "sphdeck check --no-geometry, 1 thread" env OMP_NUM_THREADS=1 "$build/sphdeck" check --no-geometry "$deck"
check_s=$median_s
check_rss=$median_rss
measure "sphdeck check (all rules), 1 thread" env OMP_NUM_THREADS=1 "$build/sphdeck" check "$deck"
full_s=$median_s
full_rss=$median_rss
measure "sphdeck check (all rules), 2 threads" env OMP_NUM_THREADS=2 "$build/sphdeck" check "$deck"
two_s=$median_s
measure "sphdeck smooth" "$build/sphdeck" smooth --format json "$deck"
smooth_s=$median_s
measure "wc -l" wc -l "$deck"
wc_s=$median_s
wc_rss=$median_rss

echo
awk -v size="$size_mb" -v cs="$check_s" -v cr="$check_rss" -v fs="$full_s" -v fr="$full_rss" -v ts="$two_s" \
    -v ss="$smooth_s" -v ws="$wc_s" -v wr="$wc_rss" -v bf="$base_full_mb_s" -v bn="$base_nogeo_mb_s" \
    -v bs="$base_smooth_s" -v bfr="$base_full_rss" -v bnr="$base_nogeo_rss" -v strict="${BENCH_STRICT:-0}" \
    -v hf="$host_full_s" -v hn="$host_nogeo_s" -v ht="$host_two_s" -v hs="$host_smooth_s" -v hfr="$host_full_rss" \
    -v hnr="$host_nogeo_rss" '
function rate(s) { return s > 0 ? size / s : 0 }
function verdict(ok) { return ok ? "met" : "NOT MET" }
BEGIN {
  c = rate(cs); f = rate(fs); t = rate(ts); w = rate(ws)
  printf "%-38s %10s %10s %8s   %s\n", "figure", "baseline", "now", "ratio", "goal"
  ok1 = f >= 3 * bf;  ok2 = c >= 2 * bn;  ok3 = t >= 1.6 * f
  ok4 = fr <= size;   ok5 = cr <= size;   ok6 = ss <= 0.6
  printf "%-38s %10.1f %10.1f %7.2fx   >= 3x (%.0f MB/s): %s\n", "check, all rules, 1 thread (MB/s)", bf, f, f / bf, 3 * bf, verdict(ok1)
  printf "%-38s %10.1f %10.1f %7.2fx   >= 2x (%.0f MB/s): %s\n", "check --no-geometry, 1 thread (MB/s)", bn, c, c / bn, 2 * bn, verdict(ok2)
  printf "%-38s %10s %10.1f %7.2fx   >= 1.6x 1 thread: %s\n", "check, all rules, 2 threads (MB/s)", "-", t, (f > 0 ? t / f : 0), verdict(ok3)
  printf "%-38s %10.2f %10.2f %7.2fx   <= 1.0x deck: %s\n", "peak RSS / deck, all rules", bfr, fr / size, (fr / size) / bfr, verdict(ok4)
  printf "%-38s %10.2f %10.2f %7.2fx   <= 1.0x deck: %s\n", "peak RSS / deck, --no-geometry", bnr, cr / size, (cr / size) / bnr, verdict(ok5)
  printf "%-38s %10.2f %10.3f %7.2fx   <= 0.6 s: %s\n", "smooth (s)", bs, ss, ss / bs, verdict(ok6)
  printf "%-38s %10s %10.1f %8s   the floor: reading the bytes alone\n", "wc -l (MB/s)", "-", w, ""
  printf "\nbeside the old binary on this host (seconds, MB; ratio old/new, above 1 is faster or smaller)\n"
  printf "%-38s %10s %10s %8s\n", "figure", "old here", "now", "ratio"
  printf "%-38s %10.2f %10.2f %7.2fx   goal 3x\n", "check, all rules, 1 thread (s)", hf, fs, (fs > 0 ? hf / fs : 0)
  printf "%-38s %10.2f %10.2f %7.2fx   goal 2x\n", "check --no-geometry, 1 thread (s)", hn, cs, (cs > 0 ? hn / cs : 0)
  printf "%-38s %10.2f %10.2f %7.2fx   goal: 1.6x of 1 thread now (%.2fx)\n", "check, all rules, 2 threads (s)", ht, ts, \
         (ts > 0 ? ht / ts : 0), (ts > 0 ? fs / ts : 0)
  printf "%-38s %10.2f %10.2f %7.2fx\n", "smooth (s)", hs, ss, (ss > 0 ? hs / ss : 0)
  printf "%-38s %10.0f %10.0f %7.2fx   goal <= %.0f MB (deck)\n", "peak RSS, all rules (MB)", hfr, fr, (fr > 0 ? hfr / fr : 0), size
  printf "%-38s %10.0f %10.0f %7.2fx   goal <= %.0f MB (deck)\n", "peak RSS, --no-geometry (MB)", hnr, cr, (cr > 0 ? hnr / cr : 0), size
  printf "\nreader (check --no-geometry, 1 thread) at %.3f of the speed of wc -l (wc -l is %.1fx faster)\n", \
         (w > 0 ? c / w : 0), (c > 0 ? w / c : 0)
  printf "deck %.1f MB; peak RSS %.1f MB (all rules), %.1f MB (--no-geometry)\n", size, fr, cr
  printf "wall-clock medians: rerun on an idle machine (load average below 1) before comparing with the baseline\n"
  exit (strict == 1 && !(ok1 && ok2 && ok3 && ok4 && ok5 && ok6)) ? 1 : 0
}'
