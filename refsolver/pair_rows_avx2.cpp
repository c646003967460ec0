// The pair loop's fast path with AVX2 and FMA, 4 lanes (pair_rows.hpp). CMakeLists.txt compiles
// this unit alone with -mavx2 -mfma; best_pair_rows() calls it only on a CPU that has both.
#include "refsolver/pair_rows.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>

namespace sphdeck::refsolver {
namespace {

constexpr int lanes = 4;
using V = double __attribute__((vector_size(32)));
using M = long long __attribute__((vector_size(32)));
inline V vsqrt(V v) { return _mm256_sqrt_pd(v); }

// The 12 fields of 4 packed particles as 12 vectors: two fields of two particles per 256-bit
// load pair, then an unpack (PackedParticle is 12 doubles, so every pair of fields is 16 bytes).
inline void gather(const PackedParticle* nb, const std::uint32_t* j, V field[12]) {
    const double *p0 = &nb[j[0]].x, *p1 = &nb[j[1]].x, *p2 = &nb[j[2]].x, *p3 = &nb[j[3]].x;
    for (int f = 0; f < 12; f += 2) {
        const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0 + f)), _mm_loadu_pd(p2 + f), 1);
        const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1 + f)), _mm_loadu_pd(p3 + f), 1);
        field[f] = _mm256_unpacklo_pd(a, b), field[f + 1] = _mm256_unpackhi_pd(a, b);
    }
}

// x y z h of 4 particles (32 bytes each) as 4 vectors, the same way.
inline void gather_position(const double* positions, const std::uint32_t* j, V& x, V& y, V& z, V& h) {
    const double *p0 = positions + 4 * std::size_t{j[0]}, *p1 = positions + 4 * std::size_t{j[1]};
    const double *p2 = positions + 4 * std::size_t{j[2]}, *p3 = positions + 4 * std::size_t{j[3]};
    const __m256d xy02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0)), _mm_loadu_pd(p2), 1);
    const __m256d xy13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1)), _mm_loadu_pd(p3), 1);
    const __m256d zh02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0 + 2)), _mm_loadu_pd(p2 + 2), 1);
    const __m256d zh13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1 + 2)), _mm_loadu_pd(p3 + 2), 1);
    x = _mm256_unpacklo_pd(xy02, xy13), y = _mm256_unpackhi_pd(xy02, xy13);
    z = _mm256_unpacklo_pd(zh02, zh13), h = _mm256_unpackhi_pd(zh02, zh13);
}

}  // namespace
}  // namespace sphdeck::refsolver

#include "refsolver/pair_rows_kernel.hpp"

namespace sphdeck::refsolver {
PairRowsFunction pair_rows_avx2() { return &rows_for_deck; }
}  // namespace sphdeck::refsolver

#else
namespace sphdeck::refsolver {
PairRowsFunction pair_rows_avx2() { return nullptr; }
}  // namespace sphdeck::refsolver
#endif
