// The body of the SIMD pair loop (pair_rows.hpp), included by each per-ISA unit after it has
// defined, in an unnamed namespace of sphdeck::refsolver: `lanes`, the vector types V (double) and
// M (64-bit integer) of that many lanes, vsqrt(V), gather(nb, indices, V field[12]) (the 12
// PackedParticle fields of `lanes` particles) and gather_position(positions, indices, x, y, z, h). Everything here has internal linkage, so nothing
// compiled with that unit's instruction set can stand in for another unit's code.
// The arithmetic of a pair is rates.cpp's pair_terms, add_to and add_reverse, term for term.
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

// One row of particle i: its partners list[first, last) within the support (rates.cpp's
// within_support), `lanes` at a time; with `Reverse` (real partners) the shares they receive too.
template <int Dimension, bool Renormalise, bool Reverse>
void row(const PairRows& p, std::size_t i, const std::uint32_t* list, std::uint32_t first, std::uint32_t last,
         OwnSums& own) {
    const PackedParticle* nb = p.nb;
    const PackedParticle& me = nb[i];
    // Within the support: rates.cpp's within_support test, `lanes` candidates at a time from the
    // compact positions (x y z h), so the filter reads 32 bytes per candidate instead of a packed
    // particle's 96; branch-free (the lists hold about three times the pairs within the support).
    std::uint32_t* inside = p.inside;
    std::size_t n = 0;
    {
        const V x = splat(me.x), y = splat(me.y), z = splat(me.z), h = splat(me.h), half = splat(0.5), four = splat(4.0);
        std::uint32_t k = first;
        for (; k + lanes <= last; k += lanes) {
            V ox, oy, oz, oh;
            gather_position(p.positions, list + k, ox, oy, oz, oh);
            const V dx = x - ox, dy = y - oy, dz = z - oz, hij = half * (h + oh);
            const M in = (M)(dx * dx + dy * dy + dz * dz < four * hij * hij);
            for (int l = 0; l < lanes; ++l) inside[n] = list[k + l], n += static_cast<std::size_t>(in[l] & 1);
        }
        for (; k < last; ++k) {
            const std::uint32_t j = list[k];
            const double* o = p.positions + 4 * static_cast<std::size_t>(j);
            const double dx = me.x - o[0], dy = me.y - o[1], dz = me.z - o[2], hij = 0.5 * (me.h + o[3]);
            inside[n] = j;
            n += static_cast<std::size_t>(!(dx * dx + dy * dy + dz * dz >= 4 * hij * hij));
        }
    }
    if (n == 0) return;
    for (std::size_t k = n; k < n + lanes; ++k) inside[k] = inside[n - 1];  // padding lanes, masked below

    const V x = splat(me.x), y = splat(me.y), z = splat(me.z), vx = splat(me.vx), vy = splat(me.vy), vz = splat(me.vz);
    const V h = splat(me.h), m = splat(me.m), rho = splat(me.rho), c = splat(me.c), por = splat(me.p_over_rho);
    const V volume = splat(me.volume), norm = splat(p.norm), q1 = splat(p.q1), q2 = splat(p.q2);
    const V half = splat(0.5), one = splat(1.0), zero = {};
    V lane_index = {};
    for (int l = 0; l < lanes; ++l) lane_index[l] = l;
    [[maybe_unused]] const double* ci = Renormalise ? p.correction + 6 * i : nullptr;

    for (std::size_t k = 0; k < n; k += lanes) {
        V o[12];  // x y z vx vy vz h m rho c p_over_rho volume of the partners
        gather(nb, inside + k, o);
        const V dx = x - o[0], dy = y - o[1], dz = z - o[2];
        const V r2 = dx * dx + dy * dy + dz * dz;
        // pair_terms: grad_i W_ij = F x_ij (kernel.hpp).
        const V hij = half * (h + o[6]);
        const V inv_h = one / hij, r = vsqrt(r2), q = r * inv_h;
        const V inv_h2 = inv_h * inv_h;
        const V scale = norm * (Dimension == 2 ? inv_h2 * inv_h2 : inv_h2 * inv_h2 * inv_h);
        const V inner = scale * (splat(-3.0) + splat(2.25) * q);
        const V outer = -scale * splat(0.75) * (splat(2.0) - q) * (splat(2.0) - q) * (hij / r);
        const V f = select((M)(q <= one), inner, outer);
        V gx = f * dx, gy = f * dy, gz = f * dz;
        if constexpr (Renormalise) {  // the mean of the two corrections (renormalisation.hpp)
            double mean[6][lanes];  // built in memory: lane stores into vectors trip GCC 12's -Wmaybe-uninitialized
            for (int e = 0; e < 6; ++e)
                for (int l = 0; l < lanes; ++l) mean[e][l] = 0.5 * (ci[e] + p.correction[6 * inside[k + l] + e]);
            V b[6];
            for (int e = 0; e < 6; ++e) __builtin_memcpy(&b[e], mean[e], sizeof(V));
            const V tx = b[0] * gx + b[3] * gy + b[4] * gz, ty = b[3] * gx + b[1] * gy + b[5] * gz;
            gz = b[4] * gx + b[5] * gy + b[2] * gz, gx = tx, gy = ty;
        }
        const V dvx = vx - o[3], dvy = vy - o[4], dvz = vz - o[5];
        const V v_dot_g = dvx * gx + dvy * gy + dvz * gz;
        const V v_dot_x = dvx * dx + dvy * dy + dvz * dz;
        // viscosity.hpp: Pi_ij, 0 where the pair separates.
        const V phi = hij * v_dot_x / (r2 + splat(0.01) * hij * hij);
        const V pi_all = (-q2 * (half * (c + o[9])) * phi + q1 * phi * phi) / (half * (rho + o[8]));
        const V pi = select((M)(v_dot_x < zero), pi_all, zero);
        // momentum.hpp's A_ij.
        const V a = (por * rho + o[10] * o[8]) / (rho * o[8]) + pi;
        // add_to, lanes past the row's end masked.
        const M valid = (M)(lane_index < splat(static_cast<double>(n - k)));
        own.ax += select(valid, o[7] * a * gx, zero);
        own.ay += select(valid, o[7] * a * gy, zero);
        own.az += select(valid, o[7] * a * gz, zero);
        own.drho += select(valid, o[11] * v_dot_g, zero);
        own.de += select(valid, (o[11] * por + half * o[7] * pi) * v_dot_g, zero);
        if constexpr (Reverse) {  // add_reverse: g_ji = -g_ij, v_ji . g_ji = v_ij . g_ij
            const V share[5] = {m * a * gx, m * a * gy, m * a * gz, volume * v_dot_g,
                                (volume * o[10] + half * m * pi) * v_dot_g};
            for (int s = 0; s < 5; ++s) __builtin_memcpy(p.reverse + s * p.stride + k, &share[s], sizeof(V));
        }
    }
    if constexpr (Reverse)
        for (std::size_t k = 0; k < n; ++k) {
            double* r = p.received + 5 * static_cast<std::size_t>(inside[k]);
            for (int s = 0; s < 5; ++s) r[s] += p.reverse[s * p.stride + k];
        }
}

template <int Dimension, bool Renormalise>
void rows(const PairRows& p, std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
        if (!p.interacting[i]) continue;
        OwnSums own;
        row<Dimension, Renormalise, true>(p, i, p.forward, p.forward_offsets[i], p.forward_offsets[i + 1], own);
        // Ghosts act on real particles only: one-sided.
        row<Dimension, Renormalise, false>(p, i, p.ghost, p.ghost_offsets[i], p.ghost_offsets[i + 1], own);
        p.ax[i] = p.body[0] - lane_sum(own.ax), p.ay[i] = p.body[1] - lane_sum(own.ay);
        p.az[i] = p.body[2] - lane_sum(own.az);
        p.drho[i] = lane_sum(own.drho), p.de[i] = lane_sum(own.de);
    }
}

void rows_for_deck(const PairRows& p, std::size_t first, std::size_t last) {
    if (p.dimension == 2) p.renormalise ? rows<2, true>(p, first, last) : rows<2, false>(p, first, last);
    else p.renormalise ? rows<3, true>(p, first, last) : rows<3, false>(p, first, last);
}

}  // namespace
}  // namespace sphdeck::refsolver
