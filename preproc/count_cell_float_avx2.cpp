// The neighbour counts in float lanes with AVX2 (count_cell_float.hpp). CMakeLists.txt compiles this unit
// alone with -mavx2 and -ffp-contract=off (the exact re-test computes as nearest_neighbours.cpp does);
// count_cell_float() calls it only on a CPU that has AVX2.
#include "preproc/count_cell_float.hpp"

#if defined(__AVX2__)
#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace sphdeck::preproc {

namespace {

constexpr std::uint32_t lanes = 8;
// Sentinels after each run of buffered points: a step that starts inside a run reads no point of the
// next one. Far from every buffered point (those are within 2^20 of the cell's first, scaled).
constexpr std::uint32_t padding = lanes;
constexpr float sentinel = 1e15f;
constexpr double unit = 0x1p-24;  // float's unit roundoff

// Why the float test decides as the double one does.
//
// Coordinates are taken relative to o, the cell's first point, and scaled by s, a power of two near
// 1 / cell: v = (x - o) * s in double (the multiplication exact), u = float(v). With |v| <= M over the
// buffered points, |u - (x - o) s| <= d := M 2^-24 (1 + 2^-27) + 2^-149 (2^-149: a float below its normal
// range). A float difference of two such values, dx = fl(u_k - u_j) (exact when subnormal), is within
// e0 + 2^-24 |D| of D = (x_k - x_j) s, the true scaled difference, where e0 = 2 d (1 + 2^-24). With
// R = |(Dx, Dy, Dz)| and e = e0 + 2^-24 R, each |dx^2 - Dx^2| <= e (2 |Dx| + e), so the exact sum of the
// float squares is within 3 e (2 R + e) of S = R^2; the two float roundings of the squares and two of the
// sum add a relative g3 = 3 u / (1 - 3 u) (u = 2^-24) and 2^-146 at most where they underflow. The
// double loop's r2d (the same expression in double) is within 2^-50 of S relatively (its cell at least
// 2^-400, so its own underflow is far below the float terms). So |r2f - r2d s^2| <= F(S) with
//   F(S) = 3 e (2 R + e) (1 + g3) + (g3 + 2^-50) S + 2^-146,
// increasing in S. With T = support^2 s^2 (the double loop counts r2d < support^2):
// - r2d s^2 < T gives S < T (1 + 2^-49), so r2f < T + F(T (1 + 2^-49)): a float distance above that
//   (`out_above`) is a pair the double loop leaves out.
// - r2d s^2 >= T gives S >= T1 = T (1 - 2^-49), so r2f >= S (1 - 2^-50) - F(S), which increases with S
//   once sqrt(S) >= 1e4 e0 (its derivative is then above 1 - 1e-3): r2f >= T1 (1 - 2^-50) - F(T1). A
//   float distance below that (`in_below`, with F(T) >= F(T1) taken) is a pair the double loop counts.
// - r2d <= tol2 (a close pair) gives r2f <= C + F(C (1 + 2^-49)), C = tol2 s^2 (`close_up_to`).
// Every other float distance is tested again in double. The bounds are widened by 1 % and by 2^-40
// relatively (their own rounding in double), then rounded outwards to float.
struct Thresholds {
    float in_below, out_above, close_up_to;
};

float rounded_down(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float rounded_up(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// False when the bound does not serve: scaled values beyond 2^20, a support too short for the monotony
// above (against the cell's size: a far stray point clamped into the block, or supports much shorter
// than the largest tolerance), thresholds beyond 2^40.
bool thresholds(double most, double t2s, double tol2s, Thresholds& th) {
    if (!(most <= 0x1p20) || !(t2s <= 0x1p40) || !(tol2s >= 0 && tol2s <= 0x1p40)) return false;
    const double d = most * unit * (1 + 0x1p-20) + 0x1p-140;
    const double e0 = 2 * d * (1 + unit);
    const double g3 = 3 * unit / (1 - 3 * unit);
    const auto bound = [&](double s2) {
        const double r = std::sqrt(s2), e = e0 + unit * r;
        return 1.01 * (3 * e * (2 * r + e) * (1 + g3) + (g3 + 0x1p-50) * s2 + 0x1p-146) + 0x1p-40 * s2;
    };
    const double t1 = t2s * (1 - 0x1p-49);
    if (!(std::sqrt(t1) >= 1e4 * e0)) return false;
    const double below = t1 * (1 - 0x1p-50) - bound(t2s);
    if (!(below > 0)) return false;
    th.in_below = rounded_down(below);
    th.out_above = rounded_up(t2s + bound(t2s * (1 + 0x1p-49)));
    th.close_up_to = rounded_up(tol2s + bound(tol2s * (1 + 0x1p-49)));
    return true;
}

// Consecutive sorted points [sorted, sorted + size) buffered from position `at`.
struct Piece {
    std::uint32_t at, sorted, size;
};

inline std::int32_t lane_sum(__m256i v) {
    __m128i s = _mm_add_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0x4E));
    s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0xB1));
    return _mm_cvtsi128_si32(s);
}

bool count_cell_avx2(const NeighbourGrid& g, double support, std::uint32_t first, std::uint32_t last,
                     std::span<const NeighbourGrid::Range> ranges, double tol2, std::uint32_t* count,
                     std::vector<std::uint32_t>& close_points, const NeighbourGrid::BlockBounds& box,
                     FloatCellScratch& s) {
    const double cell = g.cell_size();
    if (!(cell >= 0x1p-400 && cell <= 0x1p400) || ranges.size() != std::size(count_half_rows)) {
        ++s.declined;
        return false;
    }
    const double *gx = g.x().data(), *gy = g.y().data(), *gz = g.z().data();
    // The buffer: run 0 the cell's points then the rest of its row (ranges[0]), runs 1-4 the other rows,
    // each followed by sentinels.
    std::size_t total = (last - first) + 5 * padding;
    for (const auto& [b, e] : ranges) total += e - b;
    if (s.x.size() < total) s.x.resize(total), s.y.resize(total), s.z.resize(total), s.count.resize(total);
    float *fx = s.x.data(), *fy = s.y.data(), *fz = s.z.data();
    const double scale = std::ldexp(1.0, -std::ilogb(cell));
    const double ox = gx[first], oy = gy[first], oz = gz[first];
    const __m256d vox = _mm256_set1_pd(ox), voy = _mm256_set1_pd(oy), voz = _mm256_set1_pd(oz);
    const __m256d vscale = _mm256_set1_pd(scale), limit = _mm256_set1_pd(0x1p20);
    const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7FFFFFFFFFFFFFFFLL));
    __m256d most = _mm256_setzero_pd(), fine = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    double most_tail = 0;
    bool fine_tail = true;
    std::array<Piece, 6> pieces{};
    std::size_t piece_count = 0;
    std::uint32_t at = 0;
    const auto append = [&](std::uint32_t b, std::uint32_t e) {
        pieces[piece_count++] = {at, b, e - b};
        std::uint32_t j = b;
        for (; j + 4 <= e; j += 4, at += 4) {
            const __m256d vx = (_mm256_loadu_pd(gx + j) - vox) * vscale;
            const __m256d vy = (_mm256_loadu_pd(gy + j) - voy) * vscale;
            const __m256d vz = (_mm256_loadu_pd(gz + j) - voz) * vscale;
            const __m256d m = _mm256_max_pd(_mm256_and_pd(vx, magnitude),
                                            _mm256_max_pd(_mm256_and_pd(vy, magnitude), _mm256_and_pd(vz, magnitude)));
            fine = _mm256_and_pd(fine, _mm256_cmp_pd(m, limit, _CMP_LE_OQ));  // false for NaN
            most = _mm256_max_pd(most, m);
            _mm_storeu_ps(fx + at, _mm256_cvtpd_ps(vx));
            _mm_storeu_ps(fy + at, _mm256_cvtpd_ps(vy));
            _mm_storeu_ps(fz + at, _mm256_cvtpd_ps(vz));
        }
        for (; j < e; ++j, ++at) {
            const double vx = (gx[j] - ox) * scale, vy = (gy[j] - oy) * scale, vz = (gz[j] - oz) * scale;
            const double m = std::max({std::abs(vx), std::abs(vy), std::abs(vz)});
            fine_tail = fine_tail && m <= 0x1p20;
            most_tail = std::max(most_tail, m);
            fx[at] = static_cast<float>(vx), fy[at] = static_cast<float>(vy), fz[at] = static_cast<float>(vz);
        }
    };
    const auto pad = [&] {
        for (std::uint32_t p = 0; p < padding; ++p, ++at) fx[at] = fy[at] = fz[at] = sentinel;
    };
    std::array<std::uint32_t, 5> run_begin{}, run_end{};
    append(first, last);
    if (ranges[0].first != ranges[0].second) append(ranges[0].first, ranges[0].second);
    run_end[0] = at;
    pad();
    for (std::size_t r = 1; r < ranges.size(); ++r) {
        run_begin[r] = at;
        if (ranges[r].first != ranges[r].second) append(ranges[r].first, ranges[r].second);
        run_end[r] = at;
        pad();
    }
    alignas(32) double lane_most[4];
    _mm256_store_pd(lane_most, most);
    const double biggest = std::max({lane_most[0], lane_most[1], lane_most[2], lane_most[3], most_tail});
    Thresholds th{};
    const double t2 = support * support;  // the double loop's threshold
    if (_mm256_movemask_pd(fine) != 0xF || !fine_tail ||
        !thresholds(biggest, t2 * scale * scale, tol2 * scale * scale, th)) {
        ++s.declined;
        return false;
    }
    ++s.cells;
    std::fill_n(s.count.data(), at, 0);
    std::int32_t* gained = s.count.data();
    const auto sorted_at = [&](std::uint32_t p) {
        for (std::size_t q = 0;; ++q)
            if (p < pieces[q].at + pieces[q].size) return pieces[q].sorted + (p - pieces[q].at);
    };
    const __m256 in_below = _mm256_set1_ps(th.in_below), out_above = _mm256_set1_ps(th.out_above);
    const __m256 close_up_to = _mm256_set1_ps(th.close_up_to);
    const double reach2 = std::max(t2, tol2) * (1 + 1e-9);  // count_cell's, uniform
    for (std::uint32_t k = first; k < last; ++k) {
        const std::uint32_t i = k - first;
        const __m256 px = _mm256_set1_ps(fx[i]), py = _mm256_set1_ps(fy[i]), pz = _mm256_set1_ps(fz[i]);
        __m256i within = _mm256_setzero_si256();
        std::int32_t fixed = 0;
        std::uint32_t close = 0;
        __m256 undecided_any = _mm256_setzero_ps();  // any lane of the first pass left to the second
        // One run of candidates [b, e): eight a step, the lanes past e sentinels. First pass: the lanes decided
        // in float counted, the undecided ones noted; second pass (a point with undecided lanes, rare): the
        // same float values again (the same operations on the same values), the undecided lanes decided in
        // double.
        const auto scan = [&](std::uint32_t b, std::uint32_t e, auto second) {
            for (std::uint32_t j = b; j < e; j += lanes) {
                const __m256 dx = px - _mm256_loadu_ps(fx + j), dy = py - _mm256_loadu_ps(fy + j),
                             dz = pz - _mm256_loadu_ps(fz + j);
                const __m256 r2 = dx * dx + dy * dy + dz * dz;
                const __m256 in = _mm256_cmp_ps(r2, in_below, _CMP_LT_OQ);
                const __m256 near = _mm256_cmp_ps(r2, out_above, _CMP_LE_OQ);
                const __m256 maybe_close = _mm256_cmp_ps(r2, close_up_to, _CMP_LE_OQ);
                // `in` implies `near`: their difference is the undecided lanes.
                const __m256 undecided = _mm256_or_ps(_mm256_xor_ps(in, near), maybe_close);
                if constexpr (!decltype(second)::value) {
                    const __m256i add = _mm256_castps_si256(in);  // -1 where counted
                    within = _mm256_sub_epi32(within, add);
                    auto* c = reinterpret_cast<__m256i*>(gained + j);
                    _mm256_storeu_si256(c, _mm256_sub_epi32(_mm256_loadu_si256(c), add));
                    undecided_any = _mm256_or_ps(undecided_any, undecided);
                } else {
                    const int lanes_undecided = _mm256_movemask_ps(undecided);
                    if (!lanes_undecided) continue;
                    const int counted = _mm256_movemask_ps(in);
                    for (std::uint32_t l = 0; l < lanes; ++l) {
                        if (!((lanes_undecided >> l) & 1)) continue;
                        const std::uint32_t q = sorted_at(j + l);
                        const double ex = gx[k] - gx[q], ey = gy[k] - gy[q], ez = gz[k] - gz[q];
                        const double exact = ex * ex + ey * ey + ez * ez;
                        const std::int32_t change = std::int32_t{exact < t2} - ((counted >> l) & 1);
                        fixed += change, gained[j + l] += change;
                        close += exact <= tol2;
                        ++s.retests;
                    }
                }
            }
        };
        // Not a structured binding: clang 14 cannot capture one in a lambda.
        const std::pair<bool, bool> skip = corner_rows_out_of_reach(g, box, gy[k], gz[k], reach2);
        const bool skip_low = skip.first, skip_high = skip.second;
        const auto pass = [&](auto second) {
            scan(i + 1, run_end[0], second);
            for (std::size_t r = 1; r < ranges.size(); ++r)
                if (!((r == 2 && skip_low) || (r == 4 && skip_high))) scan(run_begin[r], run_end[r], second);
        };
        pass(std::false_type{});
        if (_mm256_movemask_ps(undecided_any)) [[unlikely]]
            pass(std::true_type{});
        gained[i] += lane_sum(within) + fixed;
        if (close) close_points.push_back(k);
    }
    // A point's gain in a cell may be negative (the re-tests took back float counts): added modulo 2^32, the
    // sum is its count all the same.
    for (std::size_t q = 0; q < piece_count; ++q)
        for (std::uint32_t t = 0; t < pieces[q].size; ++t)
            count[pieces[q].sorted + t] += static_cast<std::uint32_t>(gained[pieces[q].at + t]);
    return true;
}

}  // namespace

CountCellFloat count_cell_float_avx2() { return count_cell_avx2; }

}  // namespace sphdeck::preproc

#else

namespace sphdeck::preproc {
CountCellFloat count_cell_float_avx2() { return nullptr; }
}  // namespace sphdeck::preproc

#endif
