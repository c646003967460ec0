// The pair loop's fast path with AVX-512F, 8 lanes (pair_rows.hpp). CMakeLists.txt compiles this
// unit alone with -mavx512f; best_pair_rows() calls it only on a CPU (and OS) that has it.
#include "refsolver/pair_rows.hpp"

#if defined(__AVX512F__) && defined(__FMA__)
#include <immintrin.h>

namespace sphdeck::refsolver {
namespace {

constexpr int lanes = 8;
using V = double __attribute__((vector_size(64)));
using M = long long __attribute__((vector_size(64)));
// Masked with every lane on: _mm512_sqrt_pd's undefined source trips GCC 12's -Wmaybe-uninitialized.
inline V vsqrt(V v) { return _mm512_mask_sqrt_pd(v, 0xFF, v); }

// The 12 fields of 8 packed particles, lane by lane (the compiler builds the vectors).
inline void gather(const PackedParticle* nb, const std::uint32_t* j, V field[12]) {
    double lane[12][lanes];
    for (int l = 0; l < lanes; ++l) {
        const double* p = &nb[j[l]].x;
        for (int f = 0; f < 12; ++f) lane[f][l] = p[f];
    }
    for (int f = 0; f < 12; ++f) __builtin_memcpy(&field[f], lane[f], sizeof(V));
}

inline void gather_position(const double* positions, const std::uint32_t* j, V& x, V& y, V& z, V& h) {
    double lane[4][lanes];
    for (int l = 0; l < lanes; ++l)
        for (int f = 0; f < 4; ++f) lane[f][l] = positions[4 * std::size_t{j[l]} + static_cast<std::size_t>(f)];
    __builtin_memcpy(&x, lane[0], sizeof(V)), __builtin_memcpy(&y, lane[1], sizeof(V));
    __builtin_memcpy(&z, lane[2], sizeof(V)), __builtin_memcpy(&h, lane[3], sizeof(V));
}

}  // namespace
}  // namespace sphdeck::refsolver

#include "refsolver/pair_rows_kernel.hpp"

namespace sphdeck::refsolver {
PairRowsFunction pair_rows_avx512() { return &rows_for_deck; }
}  // namespace sphdeck::refsolver

#else
namespace sphdeck::refsolver {
PairRowsFunction pair_rows_avx512() { return nullptr; }
}  // namespace sphdeck::refsolver
#endif
