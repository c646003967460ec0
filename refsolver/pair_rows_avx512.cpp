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

// Two consecutive doubles (offset f) of 8 records as two vectors: 16-byte loads into the four
// 128-bit lanes of two vectors (records 0 2 4 6 and 1 3 5 7), then an unpack, as the AVX2 unit does
// (lane by lane through memory stalls on store forwarding).
inline void gather_two(const double* const p[8], int f, V& first, V& second) {
    const auto two = [&](int a, int b) {
        return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p[a] + f)), _mm_loadu_pd(p[b] + f), 1);
    };
    // The masked forms with every lane on: the plain ones' undefined sources trip GCC 12's
    // -Wmaybe-uninitialized.
    const __m512d low = _mm512_castpd256_pd512(two(0, 2)), high = _mm512_castpd256_pd512(two(1, 3));
    const __m512d even = _mm512_mask_insertf64x4(low, 0xFF, low, two(4, 6), 1);
    const __m512d odd = _mm512_mask_insertf64x4(high, 0xFF, high, two(5, 7), 1);
    first = _mm512_mask_unpacklo_pd(even, 0xFF, even, odd), second = _mm512_mask_unpackhi_pd(odd, 0xFF, even, odd);
}

// The 8 fields of 8 pair records as 8 vectors.
inline void gather(const PairRecord* records, const std::uint32_t* j, V field[8]) {
    const double* p[8];
    for (int l = 0; l < lanes; ++l) p[l] = &records[j[l]].vx;
    for (int f = 0; f < 8; f += 2) gather_two(p, f, field[f], field[f + 1]);
}

inline void gather_position(const double* positions, const std::uint32_t* j, V& x, V& y, V& z, V& h) {
    const double* p[8];
    for (int l = 0; l < lanes; ++l) p[l] = positions + 4 * std::size_t{j[l]};
    gather_two(p, 0, x, y), gather_two(p, 2, z, h);
}

// The kept indices by a register compress (then one store: a compress straight to memory is slow
// on some CPUs).
inline std::size_t compact(std::uint32_t* out, const std::uint32_t* j, M in) {
    const __mmask8 keep = _mm512_test_epi64_mask(reinterpret_cast<__m512i>(in), reinterpret_cast<__m512i>(in));
    const __m512i indices = _mm512_castsi256_si512(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(j)));
    _mm512_mask_storeu_epi32(out, 0x00FF, _mm512_maskz_compress_epi32(keep, indices));
    return static_cast<std::size_t>(__builtin_popcount(keep));
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
