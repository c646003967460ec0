#!/usr/bin/env bash
# How long a new user waits (issue 42): `make demo`, then `make test`, in a fresh clone of this
# repository's HEAD, with ccache off (a new machine has none filled). Prints the wall and CPU (user+sys,
# all processes) seconds of each run, then their medians beside the goals: make demo <= 3 min wall, make
# test <= 4 min wall (on 2 cores, the Debian packages installed).
#
#   bash bench/bench_build.sh [RUNS] [JOBS]     RUNS clones and builds (default 3), make's JOBS (default nproc)
#
# Variables: BENCH_KEEP=1 keeps the clones (in $TMPDIR), BENCH_CCACHE=1 leaves ccache on,
# BENCH_CMAKE_FLAGS passes CMAKE_FLAGS to make (-DSPHDECK_UNITY_BUILD=OFF to compare), BENCH_ONLY_DEMO=1
# stops after make demo. The machine's load average is printed before each step: wall times are only
# comparable on an idle machine; CPU seconds also hold on a busy one.
set -euo pipefail
runs=${1:-3}
jobs=${2:-$(nproc)}
repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
goal_demo=180
goal_test=240
[ "${BENCH_CCACHE:-0}" = 1 ] || export CCACHE_DISABLE=1

# One timed step: "wall cpu" on stdout, its output in $log.
timed() {
    local log=$1; shift
    local t
    t=$(mktemp)
    /usr/bin/time -f "%e %U %S" -o "$t" "$@" >"$log" 2>&1 || { echo "failed: $* (see $log)" >&2; tail -20 "$log" >&2; exit 1; }
    awk '{printf "%.1f %.1f\n", $1, $2 + $3}' "$t"
    rm -f "$t"
}

median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

demo_wall=() demo_cpu=() test_wall=() test_cpu=()
echo "sphdeck $(git -C "$repo" rev-parse --short HEAD), $(nproc) cores, make -j$jobs, $runs run(s), ccache ${BENCH_CCACHE:+on}${BENCH_CCACHE:-off}"
for run in $(seq "$runs"); do
    dir=$(mktemp -d "${TMPDIR:-/tmp}/sphdeck-bench-build.XXXXXX")
    git clone -q "$repo" "$dir/sphdeck"
    echo "run $run: load average $(cut -d' ' -f1-3 /proc/loadavg) before make demo"
    timed "$dir/demo.log" make -C "$dir/sphdeck" demo JOBS="$jobs" CMAKE_FLAGS="${BENCH_CMAKE_FLAGS:-}" >"$dir/demo.time"
    read -r wall cpu <"$dir/demo.time"
    demo_wall+=("$wall") demo_cpu+=("$cpu")
    echo "run $run: make demo  wall ${wall} s, cpu ${cpu} s"
    if [ "${BENCH_ONLY_DEMO:-0}" != 1 ]; then
        echo "run $run: load average $(cut -d' ' -f1-3 /proc/loadavg) before make test"
        timed "$dir/test.log" make -C "$dir/sphdeck" test JOBS="$jobs" CMAKE_FLAGS="${BENCH_CMAKE_FLAGS:-}" >"$dir/test.time"
        read -r wall cpu <"$dir/test.time"
        test_wall+=("$wall") test_cpu+=("$cpu")
        echo "run $run: make test  wall ${wall} s, cpu ${cpu} s"
    fi
    [ "${BENCH_KEEP:-0}" = 1 ] && echo "kept $dir" || rm -rf "$dir"
done

report() {  # name goal walls... -- cpus...
    local name=$1 goal=$2; shift 2
    local walls=() cpus=() side=w
    for v in "$@"; do
        if [ "$v" = -- ]; then side=c; continue; fi
        if [ $side = w ]; then walls+=("$v"); else cpus+=("$v"); fi
    done
    local mw mc verdict
    mw=$(printf '%s\n' "${walls[@]}" | median)
    mc=$(printf '%s\n' "${cpus[@]}" | median)
    verdict=$(awk -v w="$mw" -v g="$goal" 'BEGIN {print (w <= g) ? "met" : "not met"}')
    printf '%-10s median wall %7.1f s (goal %d s: %s), median cpu %7.1f s\n' "$name" "$mw" "$goal" "$verdict" "$mc"
}
echo
report "make demo" $goal_demo "${demo_wall[@]}" -- "${demo_cpu[@]}"
[ ${#test_wall[@]} -eq 0 ] || report "make test" $goal_test "${test_wall[@]}" -- "${test_cpu[@]}"
