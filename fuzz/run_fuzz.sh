#!/usr/bin/env bash
# Runs the libFuzzer targets (ASan + UBSan), one after the other, each for a bounded time, on top
# of the inputs kept in fuzz/corpus/<target>/ and seeds copied from decks/. Fails on any crash,
# leak, timeout or out-of-memory and keeps the input that reproduces it. See fuzz/README.md.
set -euo pipefail
usage() {
  cat <<'USAGE'
usage: fuzz/run_fuzz.sh [-t SECONDS] [-n RUNS] [-B BUILD] [-o OUT] [-u] [TARGET...]
  -t SECONDS  fuzzing time per target (default 60)
  -n RUNS     stop a target after RUNS executions (with -t: whichever comes first)
  -B BUILD    build folder (default build-fuzz; configured with clang++-14 and built when missing)
  -o OUT      work folder for seeds, new inputs, logs and crashing inputs (default BUILD/fuzz-out)
  -u          merge the new inputs that add coverage into fuzz/corpus/<target>/ (the tree)
  -s          skip building: use the targets already in BUILD
  TARGET      dyna_read radioss_read dyna_check radioss_check keyword_arguments expression lsp_messages
              format_dyna (default: all)
Environment: FUZZ_FLAGS adds libFuzzer flags, after the script's own (so -entropic=1 restores the
entropic schedule on the deck targets, which run with -entropic=0: see fuzz/README.md "Speed").
USAGE
}
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=60 runs=-1 build="$root/build-fuzz" out="" update=0 skip_build=0
while getopts "t:n:B:o:ush" opt; do
  case $opt in
    t) seconds=$OPTARG ;;
    n) runs=$OPTARG ;;
    B) build=$(cd "$OPTARG" 2>/dev/null && pwd || echo "$OPTARG") ;;
    o) out=$OPTARG ;;
    u) update=1 ;;
    s) skip_build=1 ;;
    h) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(dyna_read radioss_read dyna_check radioss_check keyword_arguments expression lsp_messages format_dyna)
out=${out:-$build/fuzz-out}

if [ "$skip_build" -eq 0 ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="${CXX:-clang++-14}" \
      -DSPHDECK_FUZZ=ON
  fi
  cmake --build "$build" -j "${JOBS:-$(nproc)}" --target fuzz_dictionary $(printf 'fuzz_%s ' "${targets[@]}")
fi

# Seeds: the small decks of decks/ (large ones only slow each execution down), by format.
seeds_for() {
  case $1 in
    dyna_read|dyna_check|format_dyna) find "$root/decks" -type f \( -name '*.k' -o -name '*.inc' -o -name '*.key' \) -size -8k ;;
    radioss_read|radioss_check) find "$root/decks" -type f -name '*.rad' -size -8k ;;
    *) ;;
  esac
}

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0:abort_on_error=1:symbolize=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export OMP_NUM_THREADS=1  # big blocks decode on threads; fuzz inputs are small, one thread is enough

failed=()
summary=()
for t in "${targets[@]}"; do
  bin="$build/fuzz/fuzz_$t"
  [ -x "$bin" ] || { echo "run_fuzz: no target '$t'" >&2; exit 2; }
  kept="$root/fuzz/corpus/$t" found="$out/corpus/$t" seeds="$out/seeds/$t" artifacts="$out/artifacts/$t"
  mkdir -p "$kept" "$found" "$seeds" "$artifacts"
  seeds_for "$t" | while read -r f; do cp "$f" "$seeds/"; done
  "$build/fuzz/fuzz_dictionary" "$t" > "$out/$t.dict"
  # The read targets take the decks their check targets take: those targets' kept inputs seed them too.
  shared=()
  case $t in dyna_read|radioss_read) [ -d "$root/fuzz/corpus/${t%_read}_check" ] && shared=("$root/fuzz/corpus/${t%_read}_check") ;; esac
  log="$out/$t.log"
  echo "== fuzz_$t: ${seconds} s$( [ "$runs" -ge 0 ] && echo ", at most $runs runs"), log $log"
  # The deck targets reach tens of thousands of features, and clang 14's entropic schedule scans
  # its list of rare features once per feature of every execution: three fifths of the time.
  schedule=""
  case $t in dyna_read|radioss_read|dyna_check|radioss_check) schedule="-entropic=0" ;; esac
  status=0
  # New inputs go to the first folder ($found), never into the tree unless -u merges them.
  "$bin" "$found" "$kept" ${shared[@]+"${shared[@]}"} "$seeds" -dict="$out/$t.dict" -max_total_time="$seconds" -runs="$runs" \
    -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=8192 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" $schedule ${FUZZ_FLAGS:-} > "$log" 2>&1 || status=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  summary+=("fuzz_$t: ${execs:-?} executions, ${rate:-?} exec/s, exit $status")
  if [ "$status" -ne 0 ]; then
    failed+=("$t")
    grep -E "^(==[0-9]+==ERROR|SUMMARY|.*runtime error|.*Test unit written to|ALARM|MS: )" "$log" | head -20 >&2 || true
    # The stack of the first report, from its first frame: a clean CI machine keeps nothing else of it.
    awk '/^==[0-9]+==ERROR|runtime error/ { on = 1 } on && /^ +#[0-9]+ / { print; if (++n == 24) exit }' "$log" >&2 || true
    echo "fuzz_$t FAILED: reproducing input(s) in $artifacts/ (replay: $bin FILE)" >&2
    # Each input as base64 too (inputs are at most 8 KiB): 'base64 -d > crash' rebuilds it where the folder is gone.
    for a in "$artifacts"/*; do
      [ -f "$a" ] || continue
      echo "$(basename "$a") ($(wc -c < "$a") bytes), base64:" >&2
      base64 -w 120 "$a" >&2
    done
  elif [ "$update" -eq 1 ]; then
    "$bin" -merge=1 "$kept" "$found" > "$out/$t.merge.log" 2>&1
    echo "   merged into fuzz/corpus/$t: $(ls -1 "$kept" | wc -l) inputs"
  fi
done
printf '%s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "run_fuzz: findings in: ${failed[*]}" >&2
  exit 1
fi
