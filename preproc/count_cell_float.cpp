#include "preproc/count_cell_float.hpp"

namespace sphdeck::preproc {

// In count_cell_float_avx2.cpp, compiled alone with -mavx2 (null elsewhere than x86-64).
CountCellFloat count_cell_float_avx2();

CountCellFloat count_cell_float() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    static const CountCellFloat chosen = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") ? count_cell_float_avx2() : nullptr;
    }();
    return chosen;
#else
    return nullptr;
#endif
}

}  // namespace sphdeck::preproc
