# Sourced by the benchmarks that compare with dynareadout (run_perf_bench.sh, run_incremental_bench.sh):
# `peer=$(dynareadout_peer)` is the peer's path, or empty when there is none. The peer
# (bench/dynareadout_peer.c) is compiled into bench/out/ when DYNAREADOUT_SRC names a checkout of
# https://github.com/PucklaJ/dynareadout (its src/ folder, cc -O3); DYNAREADOUT_PEER names one built already.
dynareadout_peer() {
  if [ -n "${DYNAREADOUT_PEER:-}" ]; then
    echo "$DYNAREADOUT_PEER"
  elif [ -n "${DYNAREADOUT_SRC:-}" ]; then
    local src=$DYNAREADOUT_SRC/src
    if ${CC:-cc} -O3 -DNDEBUG -I"$src" bench/dynareadout_peer.c "$src"/key.c "$src"/line.c "$src"/path.c \
      "$src"/path_view.c "$src"/string_builder.c "$src"/extra_string.c "$src"/multi_file.c "$src"/sync.c \
      "$src"/include_transform.c "$src"/binary_search.c -lm -lpthread -o bench/out/dynareadout_peer >&2; then
      echo bench/out/dynareadout_peer
    else
      echo "dynareadout_peer: the peer did not compile (see above): left out" >&2
    fi
  fi
}
