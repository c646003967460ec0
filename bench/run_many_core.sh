#!/usr/bin/env bash
# The figures that need many cores, in one run on a lent machine (issue 40: the 10M-particle deck on
# every core, output identical at 1, 2 and N threads, spare minutes to the fuzz targets; issue 41
# item 6: the pair loop's parallel efficiency with the split of a step by phase).
#
#   bash bench/run_many_core.sh BIN OUT [FUZZ_SECONDS]
#
# BIN holds built programs (nothing is compiled here: the lent machine may lack the packages):
#   sphdeck gen_big_deck measure_command profile_check bench_refsolver bench_cores [bench_refsolver_before]
#   fuzz/fuzz_<target> (or fuzz/fuzz_<target>.xz) and fuzz/<target>.dict for the deck targets;
#   lib/ (shared libraries the programs need, put first on LD_LIBRARY_PATH).
# OUT receives the logs. Sections run in turn and a failed one does not stop the next.
# BENCH_SECTIONS (default "info cores solver check identical fuzz") picks sections; REFSOLVER_THREADS the
# thread counts of the solver's scaling ("1 2 4 8 16", capped at the cores); FUZZ_SECONDS (120) the
# fuzz campaign's length, all deck targets at once, -fork workers sharing the cores.
set -uo pipefail

if [ $# -lt 2 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BIN OUT [FUZZ_SECONDS]" >&2
  exit 2
fi
bin=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
fuzz_seconds=${3:-120}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
[ -d "$bin/lib" ] && export LD_LIBRARY_PATH="$bin/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
cores=$(nproc)
sections=${BENCH_SECTIONS:-info cores solver check identical fuzz}
stamp() { echo "== $(date -u +%H:%M:%S) $*"; }
wants() { [[ " $sections " == *" $1 "* ]]; }

if wants info; then
  stamp "machine"
  lscpu | grep -E "^(Model name|CPU\(s\)|Thread|Core|Socket|NUMA node\(s\)|L2|L3)" || true
  free -g | head -2
  for p in sphdeck bench_refsolver; do
    [ -x "$bin/$p" ] && ldd "$bin/$p" | grep -i "not found" && echo "missing libraries for $p"
  done
  "$bin/sphdeck" --version
fi

if wants cores && [ -x "$bin/bench_cores" ]; then
  stamp "the machine's own scaling: compute in registers, memory bandwidth (bench_cores)"
  timeout 120 "$bin/bench_cores"
fi

if wants solver; then
  counts=""
  for t in ${REFSOLVER_THREADS:-1 2 4 8 16}; do [ "$t" -le "$cores" ] && counts="$counts $t"; done
  if [ -x "$bin/bench_refsolver_before" ]; then
    stamp "pair loop, the binary before (one thread count a run)"
    for t in $counts; do
      OMP_PROC_BIND=close OMP_PLACES=cores BENCH_THREADS=$t BENCH_LOADED=0 timeout 120 \
        "$bin/bench_refsolver_before" 40 3 | grep -E "^threads"
    done
  fi
  stamp "pair loop, this binary:$counts threads"
  OMP_PROC_BIND=close OMP_PLACES=cores BENCH_THREADS="$counts" BENCH_LOADED=0 timeout 300 "$bin/bench_refsolver" 40 3
fi

if wants check; then
  stamp "check of the 10M-particle deck on $cores threads (run_perf_bench.sh BENCH_MANY=1)"
  BENCH_MANY=1 BENCH_RUNS=${BENCH_RUNS:-5} timeout 400 bash bench/run_perf_bench.sh "$bin"
fi

if wants identical; then
  # The same findings at 1, 2 and every thread: the benchmark decks and every deck of decks/.
  stamp "output at 1, 2 and $cores threads"
  [ -f bench/out/big.k ] || { mkdir -p bench/out && "$bin/gen_big_deck" bench/out/big.k 1000000 > /dev/null; }
  # The time a check took is the one thing that differs (JSON and the summary line on stderr).
  unclocked() { sed -E -e 's/"seconds": [-+0-9.eE]+/"seconds": N/' -e 's/ in [0-9.]+ s$/ in N s/'; }
  for deck in bench/out/big.k bench/out/big10m.k; do
    [ -f "$deck" ] || continue
    sums=""
    for t in 1 2 "$cores"; do
      sums="$sums $(OMP_NUM_THREADS=$t "$bin/sphdeck" check --format json "$deck" 2>&1 | unclocked | md5sum | cut -c1-12)"
    done
    echo "$deck:$sums"
  done
  differ=0 total=0
  while IFS= read -r deck; do
    total=$((total + 1))
    one=$(OMP_NUM_THREADS=1 "$bin/sphdeck" check --format json "$deck" 2>&1 | unclocked)
    many=$(OMP_NUM_THREADS=$cores "$bin/sphdeck" check --format json "$deck" 2>&1 | unclocked)
    [ "$one" = "$many" ] || { differ=$((differ + 1)); echo "differs: $deck"; }
  done < <(find decks -type f \( -name '*.k' -o -name '*.key' -o -name '*.dyn' -o -name '*_0000.rad' \) | sort)
  echo "decks/: $differ of $total decks print differently at 1 and $cores threads"
fi

if wants fuzz && [ -d "$bin/fuzz" ]; then
  targets="dyna_read radioss_read dyna_check radioss_check format_dyna"
  workers=$(( cores / 5 > 0 ? cores / 5 : 1 ))
  stamp "fuzz: $targets, $fuzz_seconds s, $workers workers each"
  export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0:abort_on_error=1:symbolize=0"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" OMP_NUM_THREADS=1
  work=$(mktemp -d)
  for t in $targets; do
    exe=$bin/fuzz/fuzz_$t
    if [ ! -x "$exe" ] && [ -f "$exe.xz" ]; then
      python3 -c "import lzma, sys; open(sys.argv[2], 'wb').write(lzma.open(sys.argv[1]).read())" "$exe.xz" "$work/fuzz_$t"
      chmod +x "$work/fuzz_$t"
      exe=$work/fuzz_$t
    fi
    mkdir -p "$work/new/$t" "$work/seeds/$t" "$out/artifacts_$t"
    case $t in
      *radioss*) find decks -type f -name '*.rad' -size -8k -exec cp {} "$work/seeds/$t/" \; ;;
      *) find decks -type f \( -name '*.k' -o -name '*.inc' -o -name '*.key' \) -size -8k -exec cp {} "$work/seeds/$t/" \; ;;
    esac
    folders=()  # the inputs kept in the tree: the target's own, and the read targets take the check targets'
    for kept in "fuzz/corpus/$t" "fuzz/corpus/${t%_read}_check"; do
      [ -d "$kept" ] && [[ " ${folders[*]-} " != *" $root/$kept "* ]] && folders+=("$root/$kept")
    done
    schedule=""
    case $t in dyna_read|radioss_read|dyna_check|radioss_check) schedule="-entropic=0" ;; esac
    (cd "$work" && "$exe" "$work/new/$t" ${folders[@]+"${folders[@]}"} "$work/seeds/$t" \
      -dict="$bin/fuzz/$t.dict" -fork="$workers" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=8192 \
      -artifact_prefix="$out/artifacts_$t/" $schedule > "$work/$t.log" 2>&1) &
  done
  wait
  for t in $targets; do
    # -fork prints "#N: cov: ... exec/s: ... " lines; the last one holds the campaign's executions.
    last=$(grep -E "^#[0-9]+" "$work/$t.log" | tail -1)
    crashes=$(ls "$out/artifacts_$t" 2>/dev/null | wc -l)
    echo "fuzz_$t: ${last:-no progress line} | artifacts: $crashes"
    { echo "== fuzz_$t"; tail -c 3000 "$work/$t.log"; } >> "$out/fuzz_tails.txt"
  done
fi
stamp "done"
