#include "refsolver/pair_rows.hpp"

namespace sphdeck::refsolver {

namespace {

PairRowsPath choose(bool avx512) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    // libgcc and compiler-rt report AVX-512 and AVX only when the OS saves their registers (XCR0).
    if (avx512 && __builtin_cpu_supports("avx512f"))
        if (PairRowsFunction f = pair_rows_avx512()) return {f, "avx512"};
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        if (PairRowsFunction f = pair_rows_avx2()) return {f, "avx2"};
#endif
    return {};
}

}  // namespace

PairRowsPath best_pair_rows(bool avx512) {
    static const PairRowsPath widest = choose(true), avx2 = choose(false);
    return avx512 ? widest : avx2;
}

}  // namespace sphdeck::refsolver
