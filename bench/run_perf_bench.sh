#!/usr/bin/env bash
# Issue 30 benchmark: `sphdeck check` with every rule against the streaming reader dynareadout,
# printing each figure beside its goal.
#
#   bash bench/run_perf_bench.sh BUILD_DIR                 the 1M-particle deck: 1 core, 2 threads, RSS, smooth
#   BENCH_MANY=1 bash bench/run_perf_bench.sh BUILD_DIR    the many-core figures (10M-particle deck), under 60 s,
#                                                          and profile_check's split on every core when built
#
# BENCH_RUNS (5; 3 with BENCH_MANY), BENCH_NODES (1000000), BENCH_MANY_NODES (10000000: the big deck),
# BENCH_STRICT (0).
# Builds nothing of sphdeck: BUILD_DIR must hold sphdeck, gen_big_deck and measure_command. The peer
# (bench/dynareadout_peer.c) is compiled into bench/out/ when DYNAREADOUT_SRC names a checkout of
# https://github.com/PucklaJ/dynareadout (its src/ folder is compiled with cc -O3); DYNAREADOUT_PEER
# names a peer built already. Without either the peer's figure is left out (the goal is printed
# against the issue's 0.29 s, measured on another host). MB is 2^20 bytes. Exit status: 0 when the
# measurements ran (BENCH_STRICT=1: 1 on a missed goal), 1 when a run failed, 2 on a set-up error.
set -euo pipefail

if [ $# -ne 1 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BUILD_DIR (an existing build directory)" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
runs=${BENCH_RUNS:-5}
for tool in sphdeck gen_big_deck measure_command; do
  [ -x "$build/$tool" ] || { echo "run_perf_bench: $build/$tool is missing; build it first" >&2; exit 2; }
done
mkdir -p bench/out

# deck NAME PARTICLES: generates bench/out/NAME unless it holds that many particles; prints the seconds taken.
deck() {
  local path=bench/out/$1 nodes=$2
  if [ -f "$path" ] && head -n 1 "$path" | grep -q "gen_big_deck: $nodes SPH particles"; then
    echo 0
    return
  fi
  local start
  start=$(date +%s.%N)
  "$build/gen_big_deck" "$path.tmp" "$nodes" >/dev/null
  mv "$path.tmp" "$path"
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f\n", b - a }'
}

# measure LABEL CMD...: median_s and median_rss of $runs runs (the file in the page cache).
measure() {
  local label=$1 out last
  shift
  if ! out=$("$build/measure_command" "$runs" -- "$@"); then
    echo "$out"
    echo "run_perf_bench: '$label' failed" >&2
    exit 1
  fi
  last=${out##*$'\n'}
  [[ $last =~ ^median_seconds=([0-9.]+)\ median_peak_rss_mb=([0-9.]+)$ ]] || { echo "cannot parse: $last" >&2; exit 1; }
  median_s=${BASH_REMATCH[1]}
  median_rss=${BASH_REMATCH[2]}
  # The CPU split (measure_command's line before the last): the system time is mostly the kernel zeroing
  # first-touched pages, which on a VM moves by up to 10x between runs; the user time holds.
  local split
  split=$(grep '^median_user_seconds=' <<<"$out" || true)
  [[ $split =~ ^median_user_seconds=([0-9.]+)\ median_system_seconds=([0-9.]+)$ ]] || { echo "cannot parse: $split" >&2; exit 1; }
  median_user=${BASH_REMATCH[1]}
  median_system=${BASH_REMATCH[2]}
  printf '  %-48s %8.3f s  %7.1f MB  (user %.3f s, system %.3f s)\n' "$label" "$median_s" "$median_rss" \
    "$median_user" "$median_system"
}

size_mb() { awk -v b="$(stat -c %s "$1")" 'BEGIN { printf "%.1f", b / 1048576 }'; }
missed=0
# row FIGURE VALUE GOAL-TEXT OK(0/1)
row() {
  local verdict=met
  [ "$4" = 2 ] && verdict=""
  [ "$4" = 1 ] || [ "$4" = 2 ] || { verdict="NOT MET"; missed=1; }
  printf '%-52s %12s   goal %-24s %s\n' "$1" "$2" "$3" "$verdict"
}
sphdeck=$build/sphdeck

if [ "${BENCH_MANY:-0}" = 1 ]; then
  # The many-core figures: the coordinator's device run. Runs 3 by default to stay under 60 s.
  runs=${BENCH_RUNS:-3}
  cores=$(nproc)
  echo "== many-core figures on $cores cores, $runs runs each (medians)"
  many_nodes=${BENCH_MANY_NODES:-10000000}
  tag=$(awk -v n="$many_nodes" 'BEGIN { printf (n % 1000000 ? "%gk" : "%gM"), (n % 1000000 ? n / 1000 : n / 1000000) }')
  gen10=$(deck big10m.k "$many_nodes")
  gen1=$(deck big.k 1000000)
  cat bench/out/big10m.k bench/out/big.k >/dev/null
  big10=$(size_mb bench/out/big10m.k)
  echo "  $tag deck $big10 MB (generated in ${gen10} s; 0 = already there)"
  measure "check, every rule, $tag deck, $cores threads" env OMP_NUM_THREADS="$cores" "$sphdeck" check --alone bench/out/big10m.k
  many10_s=$median_s many10_rss=$median_rss
  measure "check --no-geometry, $tag deck, $cores threads" env OMP_NUM_THREADS="$cores" "$sphdeck" check --alone --no-geometry bench/out/big10m.k
  nogeo10_s=$median_s
  measure "check, every rule, 1M deck, 1 thread" env OMP_NUM_THREADS=1 "$sphdeck" check --alone bench/out/big.k
  one1_s=$median_s
  measure "check, every rule, 1M deck, $cores threads" env OMP_NUM_THREADS="$cores" "$sphdeck" check --alone bench/out/big.k
  many1_s=$median_s
  echo
  row "$tag deck generated (s)" "$gen10" "<= 60 s (0: reused)" "$(awk -v g="$gen10" 'BEGIN { print (g <= 60) }')"
  row "check, every rule, $tag deck, $cores threads (s)" "$(printf %.3f "$many10_s")" "<= 1 s" "$(awk -v s="$many10_s" 'BEGIN { print (s <= 1) }')"
  row "peak RSS / deck, $tag, $cores threads" "$(awk -v r="$many10_rss" -v d="$big10" 'BEGIN { printf "%.2f", r / d }')" \
      "<= 1.0" "$(awk -v r="$many10_rss" -v d="$big10" 'BEGIN { print (r <= d) }')"
  printf '%-52s %12.3f   (the reading and decoding alone)\n' "check --no-geometry, $tag deck, $cores threads (s)" "$nogeo10_s"
  printf '%-52s %12s\n' "1M deck: 1 thread / $cores threads" "$(awk -v a="$one1_s" -v b="$many1_s" 'BEGIN { printf "%.2fx", a / b }')"
  if [ -x "$build/profile_check" ]; then  # where the time goes on every core: the serial phases show here
    echo
    echo "== the split of one check of the $tag deck on $cores threads (profile_check, 1 run)"
    OMP_NUM_THREADS="$cores" "$build/profile_check" bench/out/big10m.k 1
  fi
  [ "${BENCH_STRICT:-0}" = 1 ] && [ "$missed" = 1 ] && exit 1
  exit 0
fi

gen=$(deck big.k "${BENCH_NODES:-1000000}")
file=bench/out/big.k
cat "$file" >/dev/null
size=$(size_mb "$file")
echo "== 1M-particle deck $file, $size MB (generated in ${gen} s; 0 = already there), $runs runs each (medians)"

source bench/dynareadout_peer.sh
peer=$(dynareadout_peer)
peer_s=
if [ -n "$peer" ]; then
  measure "dynareadout (peer), 1 thread" "$peer" "$file"
  peer_s=$median_s peer_user=$median_user
fi
measure "check --no-geometry, 1 thread" env OMP_NUM_THREADS=1 "$sphdeck" check --alone --no-geometry "$file"
nogeo_s=$median_s nogeo_rss=$median_rss nogeo_user=$median_user
measure "check, every rule, 1 thread" env OMP_NUM_THREADS=1 "$sphdeck" check --alone "$file"
one_s=$median_s one_rss=$median_rss one_user=$median_user
measure "check, every rule, 2 threads" env OMP_NUM_THREADS=2 "$sphdeck" check --alone "$file"
two_s=$median_s two_rss=$median_rss
measure "smooth --format json" "$sphdeck" smooth --format json "$file"
smooth_s=$median_s

echo
peer_ref=${peer_s:-0.29}
peer_note=$([ -n "$peer_s" ] && echo "" || echo " (the issue's 0.29 s: no peer built)")
row "check every rule, 1 thread, speed / dynareadout" \
    "$(awk -v p="$peer_ref" -v s="$one_s" 'BEGIN { printf "%.2fx", p / s }')" ">= 1.0x$peer_note" \
    "$(awk -v p="$peer_ref" -v s="$one_s" 'BEGIN { print (p / s >= 1.0) }')"
row "check --no-geometry, 1 thread, speed / dynareadout" \
    "$(awk -v p="$peer_ref" -v s="$nogeo_s" 'BEGIN { printf "%.2fx", p / s }')" ">= 2.0x (issue 40)" \
    "$(awk -v p="$peer_ref" -v s="$nogeo_s" 'BEGIN { print (p / s >= 2.0) }')"
if [ -n "$peer_s" ]; then  # the same on user CPU alone: what the code decides, the page zeroing left out
  row "  the same on user CPU: every rule" "$(awk -v p="$peer_user" -v s="$one_user" 'BEGIN { printf "%.2fx", p / s }')" \
      "(the goals are on wall)" 2
  row "  the same on user CPU: --no-geometry" \
      "$(awk -v p="$peer_user" -v s="$nogeo_user" 'BEGIN { printf "%.2fx", p / s }')" "(the goals are on wall)" 2
fi
row "peak RSS / deck, every rule, 1 thread" "$(awk -v r="$one_rss" -v d="$size" 'BEGIN { printf "%.2f", r / d }')" \
    "<= 1.0" "$(awk -v r="$one_rss" -v d="$size" 'BEGIN { print (r <= d) }')"
row "peak RSS / deck, every rule, 2 threads" "$(awk -v r="$two_rss" -v d="$size" 'BEGIN { printf "%.2f", r / d }')" \
    "<= 1.0" "$(awk -v r="$two_rss" -v d="$size" 'BEGIN { print (r <= d) }')"
row "peak RSS / deck, --no-geometry" "$(awk -v r="$nogeo_rss" -v d="$size" 'BEGIN { printf "%.2f", r / d }')" \
    "(<= 1.0, issue 19)" "$(awk -v r="$nogeo_rss" -v d="$size" 'BEGIN { print (r <= d) }')"
row "check every rule: 2 threads speed-up" "$(awk -v a="$one_s" -v b="$two_s" 'BEGIN { printf "%.2fx", a / b }')" \
    ">= 1.8x" "$(awk -v a="$one_s" -v b="$two_s" 'BEGIN { print (a / b >= 1.8) }')"
row "smooth (s)" "$(printf %.3f "$smooth_s")" "<= 0.6 s" "$(awk -v s="$smooth_s" 'BEGIN { print (s <= 0.6) }')"
echo "wall-clock medians: on a loaded machine only the ratios of commands run together mean something"
[ "${BENCH_STRICT:-0}" = 1 ] && [ "$missed" = 1 ] && exit 1
exit 0
