// The body of the SIMD pair loop (pair_rows.hpp), included by each per-ISA unit after it has
// defined, in an unnamed namespace of sphdeck::refsolver:
// - `lanes`, the vector types V (double) and M (64-bit integer) of that many lanes, vsqrt(V),
//   gather(records, indices, V field[8]) (the 8 PairRecord fields of `lanes` particles),
//   gather_position(positions, indices, x, y, z, h), and add_shares(received, indices, count,
//   V share[5]) (adds share[0..4] of lane l to received[5 j_l .. 5 j_l + 4], l < count);
// - for the support filter, `filter_lanes`, VF (float) and MF (32-bit integer) of that many lanes,
//   gather_position_f(positions_f, indices, x, y, z, h) and compact_f(out, indices, MF in) (stores
//   the indices of the lanes set in `in`, in order, at `out`; may write `filter_lanes` entries;
//   returns how many were set).
// Everything here has internal linkage, so nothing compiled with that unit's instruction set can
// stand in for another unit's code.
// The arithmetic of a pair is rates.cpp's pair_terms, add_to and add_reverse, term for term, except
// that the five divisions of a pair come from one (reciprocals(), below): equal to round-off.
#pragma once

namespace sphdeck::refsolver {
namespace {

inline V splat(double x) {
    V v = {};
    for (int l = 0; l < lanes; ++l) v[l] = x;
    return v;
}
inline V select(M mask, V yes, V no) { return (V)(((M)yes & mask) | ((M)no & ~mask)); }
inline double lane_sum(V v) {
    double s = 0;
    for (int l = 0; l < lanes; ++l) s += v[l];
    return s;
}

// Sums over a particle's partners, one per lane: m_j A_ij g_ij, V_j v_ij . g_ij, energy.
struct OwnSums {
    V ax = {}, ay = {}, az = {}, drho = {}, de = {};
};

// 1/a .. 1/e of positive a .. e from one division and 12 multiplications (a vector division costs
// about as much as 30 multiplications, and a pair needs five): the products a, ab, abc, abcd,
// abcde, one reciprocal, then back down the chain. A few ulps each. The product of a pair's
// factors scales as h^4 rho^3: far inside the range of a double in any consistent units.
struct Reciprocals {
    V a, b, c, d, e;
};
inline Reciprocals reciprocals(V a, V b, V c, V d, V e) {
    const V ab = a * b, abc = ab * c, abcd = abc * d;
    V rest = splat(1.0) / (abcd * e);  // 1 / abcde
    Reciprocals r;
    r.e = rest * abcd, rest *= e;  // rest = 1 / abcd
    r.d = rest * abc, rest *= d;
    r.c = rest * ab, rest *= c;
    r.b = rest * a, r.a = rest * b;
    return r;
}

inline VF splat_f(float x) {
    VF v = {};
    for (int l = 0; l < filter_lanes; ++l) v[l] = x;
    return v;
}

// The partners of particle i in list[first, last) that may lie within the support, written to
// `inside`; returns their count. `filter_lanes` candidates at a time in single precision from
// positions_f (16 bytes per candidate: the lists hold about three times the pairs within the
// support, so this filter reads more than the pair terms do), with a margin for the rounding: it
// keeps every pair within the support and a few just outside, which the pair terms drop (their
// exact test). Branch-free; the indices kept by a compress or shuffle instruction (compact_f).
// May write `filter_lanes` entries past the count.
inline std::size_t within_support(const PairRows& p, std::size_t i, const std::uint32_t* list, std::uint32_t first,
                                  std::uint32_t last, std::uint32_t* inside) {
    std::size_t n = 0;
    const float* me = p.positions_f + 4 * i;
    const VF x = splat_f(me[0]), y = splat_f(me[1]), z = splat_f(me[2]), h = splat_f(me[3]);
    const VF margin = splat_f(p.margin), slack = splat_f(1.0f + 0x1p-18f);
    std::uint32_t k = first;
    for (; k + filter_lanes <= last; k += filter_lanes) {
        VF ox, oy, oz, oh;
        gather_position_f(p.positions_f, list + k, ox, oy, oz, oh);
        const VF dx = x - ox, dy = y - oy, dz = z - oz, reach = (h + oh) + margin;  // 2 h_ij + margin
        n += compact_f(inside + n, list + k, (MF)(dx * dx + dy * dy + dz * dz < slack * reach * reach));
    }
    const double* at = p.positions + 4 * i;
    for (; k < last; ++k) {  // the rest exactly
        const std::uint32_t j = list[k];
        const double* o = p.positions + 4 * static_cast<std::size_t>(j);
        const double dx = at[0] - o[0], dy = at[1] - o[1], dz = at[2] - o[2], hij = 0.5 * (at[3] + o[3]);
        inside[n] = j;
        n += static_cast<std::size_t>(!(dx * dx + dy * dy + dz * dz >= 4 * hij * hij));
    }
    return n;
}

// The pairs of particle i within the support: its forward partners, then its ghosts, as one
// stream of `lanes` pairs at a time (one partly filled batch per particle rather than two); the
// forward partners receive their shares too (ghosts act on real particles only: one-sided).
template <int Dimension, bool Renormalise>
void row(const PairRows& p, std::size_t i, OwnSums& own) {
    const PairRecord& me = p.records[i];
    const double* at = p.positions + 4 * i;  // x y z h of particle i
    std::uint32_t* inside = p.inside;
    const std::size_t forward = within_support(p, i, p.forward, p.forward_offsets[i], p.forward_offsets[i + 1], inside);
    const std::size_t n =
        forward + within_support(p, i, p.ghost, p.ghost_offsets[i], p.ghost_offsets[i + 1], inside + forward);
    if (n == 0) return;
    for (std::size_t k = n; k < n + lanes; ++k) inside[k] = inside[n - 1];  // padding lanes, masked below

    const V x = splat(at[0]), y = splat(at[1]), z = splat(at[2]), vx = splat(me.vx), vy = splat(me.vy),
            vz = splat(me.vz);
    // s6, s7: p / rho and V under FORM 1, p V^2 and 1 / m under FORM 0 (packed_particle.hpp).
    const V h = splat(at[3]), m = splat(me.m), rho = splat(me.rho), c = splat(me.c), s6 = splat(me.s6);
    const V s7 = splat(me.s7), own_work = s6 * s7, norm = splat(p.norm), q1 = splat(p.q1), q2 = splat(p.q2);
    const V half = splat(0.5), one = splat(1.0), zero = {};
    V lane_index = {};
    for (int l = 0; l < lanes; ++l) lane_index[l] = l;
    [[maybe_unused]] const double* ci = Renormalise ? p.correction + 6 * i : nullptr;

    for (std::size_t k = 0; k < n; k += lanes) {
        // The partners: x y z h (their lines were just read by the filter), then vx vy vz m rho c
        // s6 s7 (one cache line each).
        V ox, oy, oz, oh, o[8];
        gather_position(p.positions, inside + k, ox, oy, oz, oh);
        gather(p.records, inside + k, o);
        if (k + lanes < n)  // the next partners' records, while this batch computes
            for (int l = 0; l < lanes; ++l)
                __builtin_prefetch(p.records + inside[k + lanes + static_cast<std::size_t>(l)]);
        const V dx = x - ox, dy = y - oy, dz = z - oz;
        const V r2 = dx * dx + dy * dy + dz * dz;
        // pair_terms: grad_i W_ij = F x_ij (kernel.hpp).
        const V hij = half * (h + oh), r = vsqrt(r2), hij2 = hij * hij;
        // The five divisions of the pair: 1 / h_ij, h_ij / r = h_ij r / r^2 (the outer shell only:
        // where r <= h_ij the factor is h_ij^2, so that every factor is positive, coincident
        // particles included; and r^2 rather than r, so that the division need not wait for the
        // square root), the viscosity's phi and 1 / rho_ij, and momentum.hpp's 1 / (rho_i rho_j) under
        // FORM 1 (FORM 0 passes 1: its 1 / m come precomputed in s7).
        const V visc_den = r2 + splat(0.01) * hij2;
        const Reciprocals inv =
            reciprocals(hij, select((M)(r2 > hij2), r2, hij2), visc_den, rho + o[4], Renormalise ? rho * o[4] : one);
        const V inv_h = inv.a, q = r * inv_h;
        const V inv_h2 = inv_h * inv_h;
        const V scale = norm * (Dimension == 2 ? inv_h2 * inv_h2 : inv_h2 * inv_h2 * inv_h);
        const V inner = scale * (splat(-3.0) + splat(2.25) * q);
        const V outer = -scale * splat(0.75) * (splat(2.0) - q) * (splat(2.0) - q) * (hij * r * inv.b);
        // Outside the support (the filter's margin): no term at all (g = 0 makes every share 0).
        const V f = select((M)(r2 < splat(4.0) * hij2), select((M)(q <= one), inner, outer), zero);
        V gx = f * dx, gy = f * dy, gz = f * dz;
        if constexpr (Renormalise) {  // the mean of the two corrections (renormalisation.hpp)
            double mean[6][lanes];    // built in memory: lane stores into vectors trip GCC 12's -Wmaybe-uninitialized
            for (int e = 0; e < 6; ++e)
                for (int l = 0; l < lanes; ++l) mean[e][l] = 0.5 * (ci[e] + p.correction[6 * inside[k + l] + e]);
            V b[6];
            for (int e = 0; e < 6; ++e) __builtin_memcpy(&b[e], mean[e], sizeof(V));
            const V tx = b[0] * gx + b[3] * gy + b[4] * gz, ty = b[3] * gx + b[1] * gy + b[5] * gz;
            gz = b[4] * gx + b[5] * gy + b[2] * gz, gx = tx, gy = ty;
        }
        const V dvx = vx - o[0], dvy = vy - o[1], dvz = vz - o[2];
        const V v_dot_g = dvx * gx + dvy * gy + dvz * gz;
        const V v_dot_x = dvx * dx + dvy * dy + dvz * dz;
        // viscosity.hpp: Pi_ij, 0 where the pair separates.
        const V phi = hij * v_dot_x * inv.c;
        const V pi_all = (-q2 * (half * (c + o[5])) * phi + q1 * phi * phi) * (splat(2.0) * inv.d);
        const V pi = select((M)(v_dot_x < zero), pi_all, zero);
        // momentum.hpp's A_ij.
        const V a = (Renormalise ? (s6 * rho + o[6] * o[4]) * inv.e : (s6 + o[6]) * s7 * o[7]) + pi;
        // add_to, lanes past the row's end masked.
        const M valid = (M)(lane_index < splat(static_cast<double>(n - k)));
        own.ax += select(valid, o[3] * a * gx, zero);
        own.ay += select(valid, o[3] * a * gy, zero);
        own.az += select(valid, o[3] * a * gz, zero);
        // continuity.hpp and energy.hpp: V_j v_ij . g_ij and V_j p_i / rho_i (FORM 1), v_ij . g_ij and
        // p_i V_i^2 / m_i (FORM 0).
        // FORM 0: a partner that does not interact (1 / m = 0) adds no pdV term (its m = 0 drops the rest).
        if constexpr (Renormalise) {
            own.drho += select(valid, o[7] * v_dot_g, zero);
            own.de += select(valid, (o[7] * s6 + half * o[3] * pi) * v_dot_g, zero);
        } else {
            const M present = valid & (M)(o[7] > zero);
            own.drho += select(present, v_dot_g, zero);
            own.de += select(valid, (select(present, own_work, zero) + half * o[3] * pi) * v_dot_g, zero);
        }
        if (k < forward) {  // add_reverse: g_ji = -g_ij, v_ji . g_ji = v_ij . g_ij
            const V share[5] = {m * a * gx, m * a * gy, m * a * gz, Renormalise ? s7 * v_dot_g : v_dot_g,
                                ((Renormalise ? s7 * o[6] : o[6] * o[7]) + half * m * pi) * v_dot_g};
            add_shares(p.received, inside + k, forward - k < lanes ? forward - k : std::size_t{lanes}, share);
        }
    }
}

template <int Dimension, bool Renormalise>
void rows(const PairRows& p, std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
        if (!p.interacting[i]) continue;
        OwnSums own;
        row<Dimension, Renormalise>(p, i, own);
        p.ax[i] = p.body[0] - lane_sum(own.ax), p.ay[i] = p.body[1] - lane_sum(own.ay);
        p.az[i] = p.body[2] - lane_sum(own.az);
        p.drho[i] = lane_sum(own.drho), p.de[i] = lane_sum(own.de);
    }
}

void rows_for_deck(const PairRows& p, std::size_t first, std::size_t last) {
    if (p.dimension == 2)
        p.renormalise ? rows<2, true>(p, first, last) : rows<2, false>(p, first, last);
    else
        p.renormalise ? rows<3, true>(p, first, last) : rows<3, false>(p, first, last);
}

}  // namespace
}  // namespace sphdeck::refsolver
