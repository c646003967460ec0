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

// The 8 fields of 4 pair records as 8 vectors: two fields of two particles per 256-bit load pair,
// then an unpack (every pair of fields is 16 bytes).
inline void gather(const PairRecord* records, const std::uint32_t* j, V field[8]) {
    const double *p0 = &records[j[0]].vx, *p1 = &records[j[1]].vx, *p2 = &records[j[2]].vx, *p3 = &records[j[3]].vx;
    for (int f = 0; f < 8; f += 2) {
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

// For each 4-bit mask of kept lanes, the byte shuffle that moves the kept 32-bit indices to the
// front, in order (0x80: a zero byte; those entries are past the count).
struct CompactTable {
    alignas(16) unsigned char shuffle[16][16];
};
constexpr CompactTable compact_table() {
    CompactTable t{};
    for (int mask = 0; mask < 16; ++mask) {
        int kept = 0;
        for (int l = 0; l < 4; ++l)
            if (mask >> l & 1) {
                for (int b = 0; b < 4; ++b) t.shuffle[mask][4 * kept + b] = static_cast<unsigned char>(4 * l + b);
                ++kept;
            }
        for (int b = 4 * kept; b < 16; ++b) t.shuffle[mask][b] = 0x80;
    }
    return t;
}
constexpr CompactTable compact_shuffles = compact_table();

// The indices j[0..3] whose bit is set in `mask`, in order, at `out` (writes 4 entries).
inline std::size_t compact_four(std::uint32_t* out, const std::uint32_t* j, int mask) {
    const __m128i indices = _mm_loadu_si128(reinterpret_cast<const __m128i*>(j));
    const __m128i order = _mm_load_si128(reinterpret_cast<const __m128i*>(compact_shuffles.shuffle[mask]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_shuffle_epi8(indices, order));
    return static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
}

// The support filter in single precision: 8 lanes.
constexpr int filter_lanes = 8;
using VF = float __attribute__((vector_size(32)));
using MF = int __attribute__((vector_size(32)));

inline std::size_t compact_f(std::uint32_t* out, const std::uint32_t* j, MF in) {
    const int mask = _mm256_movemask_ps(reinterpret_cast<__m256>(in));
    const std::size_t low = compact_four(out, j, mask & 15);
    return low + compact_four(out + low, j + 4, mask >> 4);
}

// x y z h of 8 particles (16 bytes each) as 4 vectors: particles l and l + 4 in the two halves of
// four registers, then a 4x4 transpose in each half.
inline void gather_position_f(const float* positions, const std::uint32_t* j, VF& x, VF& y, VF& z, VF& h) {
    const auto row = [&](int l) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(positions + 4 * std::size_t{j[l]})),
                                    _mm_loadu_ps(positions + 4 * std::size_t{j[l + 4]}), 1);
    };
    const __m256 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);  // x0 x1 y0 y1, z0 z1 h0 h1
    const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
    x = reinterpret_cast<VF>(_mm256_shuffle_ps(t0, t2, 0x44)),
    y = reinterpret_cast<VF>(_mm256_shuffle_ps(t0, t2, 0xEE));
    z = reinterpret_cast<VF>(_mm256_shuffle_ps(t1, t3, 0x44)),
    h = reinterpret_cast<VF>(_mm256_shuffle_ps(t1, t3, 0xEE));
}

// The five shares of 4 partners added to their received sums: the first four of each lane as one
// 256-bit add (a 4x4 transpose), the fifth alone. Each partner appears once in a row.
inline void add_shares(double* received, const std::uint32_t* j, std::size_t count, const V share[5]) {
    const __m256d t0 = _mm256_unpacklo_pd(share[0], share[1]), t1 = _mm256_unpackhi_pd(share[0], share[1]);
    const __m256d t2 = _mm256_unpacklo_pd(share[2], share[3]), t3 = _mm256_unpackhi_pd(share[2], share[3]);
    const __m256d lane[4] = {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
                             _mm256_permute2f128_pd(t0, t2, 0x31), _mm256_permute2f128_pd(t1, t3, 0x31)};
    for (std::size_t l = 0; l < count; ++l) {
        double* r = received + 5 * std::size_t{j[l]};
        _mm256_storeu_pd(r, _mm256_add_pd(_mm256_loadu_pd(r), lane[l]));
        r[4] += share[4][l];
    }
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
