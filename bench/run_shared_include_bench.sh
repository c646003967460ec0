#!/usr/bin/env bash
# Shared-include benchmark (issue 33 item 2): BENCH_DECKS load-case decks (default 32) that include one
# 100 MB mesh, checked together by one `sphdeck check`, against one of those decks alone.
#
#   bash bench/run_shared_include_bench.sh BUILD_DIR
#
# Builds nothing: BUILD_DIR must hold sphdeck, gen_big_deck and measure_command. Writes the decks under
# bench/out/shared/ (git-ignored): mesh.k is the *NODE and *ELEMENT_SPH blocks of gen_big_deck's
# 1,000,000-particle deck (BENCH_NODES), case_NN.k its header, a *CONTROL_TERMINATION of their own and
# *INCLUDE mesh.k. Prints wall-clock medians (measure_command) beside the goals:
#   - the decks together on one core (`taskset` to one CPU, --jobs 1, OMP_NUM_THREADS=1) against one deck
#     alone on one core: at most 2x;
#   - the decks together on N cores (--jobs N, N CPUs) for each N of BENCH_CORES (default: 1 2 4 8 16, those
#     the machine has): the speed-up against one core, near N.
#   - on a shared machine the steadier figure: CPU seconds (user + sys, /usr/bin/time) of one deck alone
#     and of the decks together on one core, run in turns BENCH_CPU_RUNS times (default 5; 0 skips),
#     their medians and the ratio of the medians.
# BENCH_RUNS (default 3) runs of each command, BENCH_RUNS_MANY (default 1) of the 32 decks on one core;
# BENCH_ARGS adds options to every check (e.g. --no-geometry). Exit status: 0 when the measurements ran,
# 1 when a run failed, 2 on a usage or set-up error.
set -euo pipefail

if [ $# -ne 1 ] || [ ! -d "$1" ]; then
  echo "usage: $0 BUILD_DIR (a built build directory)" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
for tool in sphdeck gen_big_deck measure_command; do
  if [ ! -x "$build/$tool" ]; then
    echo "run_shared_include_bench: $build/$tool is missing; build it first" >&2
    exit 2
  fi
done

nodes=${BENCH_NODES:-1000000}
decks=${BENCH_DECKS:-32}
runs=${BENCH_RUNS:-3}
runs_many=${BENCH_RUNS_MANY:-1}
cpu_runs=${BENCH_CPU_RUNS:-5}
extra=${BENCH_ARGS:-}
cpus=$(nproc)
cores_list=${BENCH_CORES:-"1 2 4 8 16"}
out=bench/out/shared

# The decks: regenerated when the particle count or the number of decks differs.
stamp="$nodes particles, $decks decks"
if [ ! -f "$out/stamp" ] || [ "$(cat "$out/stamp")" != "$stamp" ]; then
  echo "writing $out ($stamp)..."
  rm -rf "$out" && mkdir -p "$out"
  "$build/gen_big_deck" "$out/big.tmp" "$nodes" >/dev/null
  node_line=$(grep -n -m1 '^\*NODE' "$out/big.tmp" | cut -d: -f1)
  head -n $((node_line - 1)) "$out/big.tmp" > "$out/header.tmp"
  tail -n +"$node_line" "$out/big.tmp" | grep -v '^\*END' > "$out/mesh.k"
  for i in $(seq 1 "$decks"); do
    { cat "$out/header.tmp"
      printf '*CONTROL_TERMINATION\n$#  endtim\n%10.4f\n*INCLUDE\nmesh.k\n*END\n' "$(awk -v i="$i" 'BEGIN { print i / 1000 }')"
    } > "$out/$(printf 'case_%02d.k' "$i")"
  done
  rm -f "$out/big.tmp" "$out/header.tmp"
  echo "$stamp" > "$out/stamp"
fi
cat "$out/mesh.k" > /dev/null  # in the page cache: every run reads from memory
echo "mesh: $out/mesh.k, $(awk -v b="$(stat -c %s "$out/mesh.k")" 'BEGIN { printf "%.1f MB", b / 1048576 }'), $decks decks"

# measure LABEL RUNS CMD...: sets median_s.
measure() {
  local label=$1 n=$2 text
  shift 2
  if ! text=$("$build/measure_command" "$n" -- "$@"); then
    echo "$text"
    echo "run_shared_include_bench: '$label' failed" >&2
    exit 1
  fi
  local last=${text##*$'\n'}
  [[ $last =~ ^median_seconds=([0-9.]+) ]] || { echo "cannot parse: $last" >&2; exit 1; }
  median_s=${BASH_REMATCH[1]}
  printf '%-44s %8.3f s  (%d runs, %s)\n' "$label" "$median_s" "$n" "${last#*median_peak_rss_mb=} MB peak RSS"
}

# One core: the CPU this script may use first.
first_cpu=$(taskset -pc $$ | sed 's/.*: //; s/[-,].*//')
on_cpus() {  # on_cpus N: the prefix that runs a command on N CPUs (from the first), N OpenMP threads
  echo "env OMP_NUM_THREADS=$1 taskset -c $first_cpu-$((first_cpu + $1 - 1))"
}
# shellcheck disable=SC2086
measure "one deck alone, 1 core" "$runs" $(on_cpus 1) "$build/sphdeck" check --format concise --alone $extra "$out/case_01.k"
alone=$median_s
# shellcheck disable=SC2086
measure "$decks decks together, 1 core (--jobs 1)" "$runs_many" $(on_cpus 1) "$build/sphdeck" check --format concise --jobs 1 $extra "$out"
one_core=$median_s
awk -v a="$one_core" -v b="$alone" 'BEGIN { r = a / b; printf "  ratio to one deck alone: %.2fx (goal: at most 2x: %s)\n", r, r <= 2 ? "met" : "not met" }'
for n in $cores_list; do
  [ "$n" -le 1 ] && continue
  if [ "$n" -gt "$cpus" ]; then
    echo "($n cores: the machine has $cpus; skipped)"
    continue
  fi
  # shellcheck disable=SC2086
  measure "$decks decks together, $n cores (--jobs $n)" "$runs" $(on_cpus "$n") "$build/sphdeck" check --format concise --jobs "$n" $extra "$out"
  awk -v a="$one_core" -v b="$median_s" -v n="$n" \
    'BEGIN { s = a / b; printf "  speed-up over 1 core: %.2fx of %d (goal: near-linear; efficiency %.0f %%)\n", s, n, 100 * s / n }'
done

# CPU seconds, one deck alone and the decks together taking turns (the load then weighs on both alike).
cpu_of() {  # cpu_of CMD...: prints the command's user + sys seconds
  local times
  times=$(mktemp)
  /usr/bin/time -f '%U %S' -o "$times" "$@" >/dev/null 2>&1 || true
  awk '{ print $1 + $2 }' "$times"
  rm -f "$times"
}
if [ "$cpu_runs" -gt 0 ] && [ -x /usr/bin/time ]; then
  alone_cpu=() many_cpu=()
  for _ in $(seq 1 "$cpu_runs"); do
    # shellcheck disable=SC2046,SC2086
    alone_cpu+=("$(cpu_of $(on_cpus 1) "$build/sphdeck" check --format concise --alone $extra "$out/case_01.k")")
    # shellcheck disable=SC2046,SC2086
    many_cpu+=("$(cpu_of $(on_cpus 1) "$build/sphdeck" check --format concise --jobs 1 $extra "$out")")
  done
  median_of() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
  a=$(median_of "${alone_cpu[@]}") b=$(median_of "${many_cpu[@]}")
  echo "CPU (user + sys), 1 core, $cpu_runs runs each in turns: one deck alone ${a} s (${alone_cpu[*]}), $decks decks ${b} s (${many_cpu[*]})"
  awk -v a="$b" -v b="$a" 'BEGIN { r = a / b; printf "  ratio of the CPU medians: %.2fx (goal: at most 2x: %s)\n", r, r <= 2 ? "met" : "not met" }'
fi
