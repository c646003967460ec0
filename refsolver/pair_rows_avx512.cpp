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

// The support filter in single precision: 16 lanes.
constexpr int filter_lanes = 16;
using VF = float __attribute__((vector_size(64)));
using MF = int __attribute__((vector_size(64)));

// The kept indices by a register compress, then one store (a compress straight to memory is slow
// on some CPUs).
inline std::size_t compact_f(std::uint32_t* out, const std::uint32_t* j, MF in) {
    const __mmask16 keep = _mm512_test_epi32_mask(reinterpret_cast<__m512i>(in), reinterpret_cast<__m512i>(in));
    const __m512i indices = _mm512_loadu_si512(j);
    _mm512_mask_storeu_epi32(out, 0xFFFF, _mm512_maskz_compress_epi32(keep, indices));
    return static_cast<std::size_t>(__builtin_popcount(keep));
}

// x y z h of 16 particles (16 bytes each) as 4 vectors: particles l, l + 4, l + 8, l + 12 in the
// four 128-bit lanes of four registers, then a 4x4 transpose in each lane (masked forms: GCC 12).
inline void gather_position_f(const float* positions, const std::uint32_t* j, VF& x, VF& y, VF& z, VF& h) {
    const auto at = [&](int l) { return _mm_loadu_ps(positions + 4 * std::size_t{j[l]}); };
    const auto row = [&](int l) {
        __m512 r = _mm512_castps128_ps512(at(l));
        r = _mm512_insertf32x4(r, at(l + 4), 1), r = _mm512_insertf32x4(r, at(l + 8), 2);
        return _mm512_insertf32x4(r, at(l + 12), 3);
    };
    const __m512 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    const __m512 t0 = _mm512_mask_unpacklo_ps(r0, 0xFFFF, r0, r1), t1 = _mm512_mask_unpackhi_ps(r0, 0xFFFF, r0, r1);
    const __m512 t2 = _mm512_mask_unpacklo_ps(r2, 0xFFFF, r2, r3), t3 = _mm512_mask_unpackhi_ps(r2, 0xFFFF, r2, r3);
    x = reinterpret_cast<VF>(_mm512_mask_shuffle_ps(t0, 0xFFFF, t0, t2, 0x44));
    y = reinterpret_cast<VF>(_mm512_mask_shuffle_ps(t0, 0xFFFF, t0, t2, 0xEE));
    z = reinterpret_cast<VF>(_mm512_mask_shuffle_ps(t1, 0xFFFF, t1, t3, 0x44));
    h = reinterpret_cast<VF>(_mm512_mask_shuffle_ps(t1, 0xFFFF, t1, t3, 0xEE));
}

// The five shares of 8 partners added to their received sums: the first four of each lane as one
// 256-bit add (a 4x8 transpose: unpacks, then two-source permutes pairing the 128-bit halves), the
// fifth alone. Each partner appears once in a row.
inline void add_shares(double* received, const std::uint32_t* j, std::size_t count, const V share[5]) {
    const __m512d t0 = _mm512_mask_unpacklo_pd(share[0], 0xFF, share[0], share[1]);  // lanes 0 2 4 6 of s0 s1
    const __m512d t1 = _mm512_mask_unpackhi_pd(share[0], 0xFF, share[0], share[1]);  // lanes 1 3 5 7
    const __m512d t2 = _mm512_mask_unpacklo_pd(share[2], 0xFF, share[2], share[3]);
    const __m512d t3 = _mm512_mask_unpackhi_pd(share[2], 0xFF, share[2], share[3]);
    const __m512i low = _mm512_set_epi64(11, 10, 3, 2, 9, 8, 1, 0), high = _mm512_set_epi64(15, 14, 7, 6, 13, 12, 5, 4);
    const __m512d pairs[4] = {_mm512_permutex2var_pd(t0, low, t2), _mm512_permutex2var_pd(t1, low, t3),
                              _mm512_permutex2var_pd(t0, high, t2), _mm512_permutex2var_pd(t1, high, t3)};
    alignas(64) double lane[8][4];  // lane l's four shares; pairs[] hold lanes 0 2 | 1 3 | 4 6 | 5 7
    constexpr int first_lane[4] = {0, 1, 4, 5};
    for (int q = 0; q < 4; ++q) {
        // Zero-masked extracts: the plain ones' undefined sources trip GCC 12's -Wmaybe-uninitialized.
        _mm256_store_pd(lane[first_lane[q]], _mm512_maskz_extractf64x4_pd(0xF, pairs[q], 0));
        _mm256_store_pd(lane[first_lane[q] + 2], _mm512_maskz_extractf64x4_pd(0xF, pairs[q], 1));
    }
    for (std::size_t l = 0; l < count; ++l) {
        double* r = received + 5 * std::size_t{j[l]};
        _mm256_storeu_pd(r, _mm256_add_pd(_mm256_loadu_pd(r), _mm256_load_pd(lane[l])));
        r[4] += share[4][l];
    }
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
