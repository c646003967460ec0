#include "refsolver/rates.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <omp.h>

#include "refsolver/continuity.hpp"
#include "refsolver/energy.hpp"
#include "refsolver/momentum.hpp"
#include "refsolver/pair_rows.hpp"
#include "refsolver/stress.hpp"
#include "refsolver/tensor3.hpp"

namespace sphdeck::refsolver {

namespace {

using Correction = std::array<double, 6>;

// The geometry of one pair (i, j), seen from i (g = g_ij), the momentum factor A_ij (momentum.hpp,
// symmetric: both particles' sums use it) and Pi_ij for the viscous heating (energy.hpp).
struct PairTerms {
    double gx, gy, gz, v_dot_g, a, pi;  // a: momentum.hpp's A_ij (= A_ji)
};

// One pair within the support (r2 < 4 h_ij^2). One square root and two divisions for the kernel
// (1 / h_ij and the outer-shell 1 / r) and one for the momentum factor; p / rho comes precomputed per
// particle.
template <int Dimension, bool Renormalise>
[[gnu::always_inline]] inline PairTerms pair_terms(const PackedParticle& a, const PackedParticle& b,
                                                   const Correction& ba, const Correction& bb, double dx, double dy,
                                                   double dz, double r2, double norm,
                                                   const MonaghanViscosity& viscosity) {
    // grad_i W_ij = F x_ij (kernel.hpp), F = C_d / h^(d+2) theta'(q) / q.
    const double hij = 0.5 * (a.h + b.h);
    const double inv_h = 1.0 / hij, r = std::sqrt(r2), q = r * inv_h;
    const double inv_h2 = inv_h * inv_h;
    const double scale = norm * (Dimension == 2 ? inv_h2 * inv_h2 : inv_h2 * inv_h2 * inv_h);
    const double inner = scale * (-3.0 + 2.25 * q), outer = -scale * 0.75 * (2 - q) * (2 - q) * (hij / r);
    const double f = q <= 1 ? inner : outer;
    double gx = f * dx, gy = f * dy, gz = f * dz;
    if constexpr (Renormalise) {  // the mean of the two corrections (renormalisation.hpp)
        const double xx = 0.5 * (ba[0] + bb[0]), yy = 0.5 * (ba[1] + bb[1]), zz = 0.5 * (ba[2] + bb[2]);
        const double xy = 0.5 * (ba[3] + bb[3]), xz = 0.5 * (ba[4] + bb[4]), yz = 0.5 * (ba[5] + bb[5]);
        const double tx = xx * gx + xy * gy + xz * gz, ty = xy * gx + yy * gy + yz * gz;
        gz = xz * gx + yz * gy + zz * gz, gx = tx, gy = ty;
    }
    const double dvx = a.vx - b.vx, dvy = a.vy - b.vy, dvz = a.vz - b.vz;
    const double v_dot_g = dvx * gx + dvy * gy + dvz * gz;
    const double v_dot_x = dvx * dx + dvy * dy + dvz * dz;
    const double pi_ij = viscosity.pi(v_dot_x, r2, hij, 0.5 * (a.c + b.c), 0.5 * (a.rho + b.rho), 0.5 * (a.f + b.f));
    return {gx, gy, gz, v_dot_g, momentum_factor<Renormalise>(a.s6, a.s7, a.rho, b.s6, b.s7, b.rho, pi_ij), pi_ij};
}

// Sums of one particle: ax ay az drho de.
using RateSums = std::array<double, 5>;

// Adds j's share of pair (i, j) to i's sums: m_j A_ij g_ij and the continuity and energy terms
// (FORM 1: the volume-weighted forms, FORM 0 the number-density forms, continuity.hpp).
template <bool Renormalise>
inline void add_to(RateSums& sums, const PairTerms& t, const PackedParticle& i, const PackedParticle& j) {
    sums[0] -= j.m * t.a * t.gx, sums[1] -= j.m * t.a * t.gy, sums[2] -= j.m * t.a * t.gz;
    sums[3] += continuity_term<Renormalise>(j.s7, t.v_dot_g);
    sums[4] += energy_term<Renormalise>(i.s6, i.s7, j.s7, j.m, t.pi, t.v_dot_g);
}

// Adds i's share of pair (i, j) to j's sums: g_ji = -g_ij and v_ji . g_ji = v_ij . g_ij.
template <bool Renormalise>
inline void add_reverse(RateSums& sums, const PairTerms& t, const PackedParticle& i, const PackedParticle& j) {
    sums[0] += i.m * t.a * t.gx, sums[1] += i.m * t.a * t.gy, sums[2] += i.m * t.a * t.gz;
    sums[3] += continuity_term<Renormalise>(i.s7, t.v_dot_g);
    sums[4] += energy_term<Renormalise>(j.s6, j.s7, i.s7, i.m, t.pi, t.v_dot_g);
}

// The stress terms of pair (i, j) of a deck with *MAT_ELASTIC parts (stress.hpp; sph-algorithms.md
// §5 FORM 0 with sigma = -p I + S, the -p I part being momentum.hpp's): with
// D = S_i / rho_i^2 + S_j / rho_j^2 (symmetric in i and j), i receives m_j D g_ij in its
// acceleration and -1/2 m_j v_ij . D g_ij in its energy (energy.hpp's form: the pair terms of
// kinetic plus internal energy cancel), j receives -m_i D g_ij and -1/2 m_i v_ij . D g_ij. Both
// add v_ij (x) g_ij and x_ij (x) g_ij to their P and Q, weighted by the other's volume.
struct StressTerms {
    Eigen::Vector3d dg;  // D g_ij
    double v_dot_dg;
    std::array<double, 18> outer;  // v_ij (x) g_ij, then x_ij (x) g_ij, row-major
};
using GradientSums = std::array<double, 18>;  // P, then Q (stress.hpp)

[[gnu::always_inline]] inline StressTerms stress_terms(const SymmetricTensor& si, const SymmetricTensor& sj,
                                                       const PackedParticle& a, const PackedParticle& b,
                                                       const PairTerms& t, double dx, double dy, double dz) {
    const Eigen::Vector3d g(t.gx, t.gy, t.gz), v(a.vx - b.vx, a.vy - b.vy, a.vz - b.vz), x(dx, dy, dz);
    StressTerms st;
    st.dg.noalias() = (symmetric_matrix(si) + symmetric_matrix(sj)) * g;
    st.v_dot_dg = v.dot(st.dg);
    Eigen::Map<RowMajorMatrix3d>(st.outer.data()).noalias() = v * g.transpose();
    Eigen::Map<RowMajorMatrix3d>(st.outer.data() + 9).noalias() = x * g.transpose();
    return st;
}

// `sign` +1 for i (m, volume: j's), -1 for j (i's).
inline void add_stress(RateSums& sums, GradientSums& gradient, const StressTerms& st, double m, double volume,
                       double sign) {
    sums[0] += sign * m * st.dg[0], sums[1] += sign * m * st.dg[1], sums[2] += sign * m * st.dg[2];
    sums[4] -= 0.5 * m * st.v_dot_dg;
    for (int k = 0; k < 18; ++k) gradient[k] += volume * st.outer[k];
}

// The neighbours of `me` in list[first, last) that lie within the support, into `inside`.
// Branch-free: the Verlet lists hold about a third more than the support, and a branch on
// in/out would be mispredicted often.
[[gnu::always_inline]] inline std::size_t within_support(const PackedParticle& me, const PackedParticle* nb,
                                                         const std::uint32_t* list, std::uint32_t first,
                                                         std::uint32_t last, std::vector<std::uint32_t>& inside) {
    if (inside.size() < last - first) inside.resize(2 * (last - first));
    std::size_t n = 0;
    for (std::uint32_t k = first; k < last; ++k) {
        const std::uint32_t j = list[k];
        const PackedParticle& o = nb[j];
        const double dx = me.x - o.x, dy = me.y - o.y, dz = me.z - o.z, hij = 0.5 * (me.h + o.h);
        inside[n] = j;
        n += static_cast<std::size_t>(!(dx * dx + dy * dy + dz * dz >= 4 * hij * hij));
    }
    return n;
}

// The SIMD rows' view of the pair loop's input and output (pair_rows.hpp); the threads set their
// own scratch pointers.
template <int Dimension, bool Renormalise>
PairRows pair_rows_view(Particles& s, const NeighbourList& list, const RateParameters& rp, RateScratch& scratch) {
    PairRows v;  // stride and inside: each thread's own (pair_loop)
    v.records = scratch.records.data(), v.positions = reinterpret_cast<const double*>(scratch.positions.data());
    v.positions_f = reinterpret_cast<const float*>(scratch.positions_f.data()), v.margin = scratch.margin;
    v.interacting = s.interacting.data();
    v.correction = Renormalise ? reinterpret_cast<const double*>(s.correction.data()) : nullptr;
    v.forward_offsets = list.forward_offsets.data(), v.forward = list.forward.data();
    v.ghost_offsets = list.ghost_offsets.data(), v.ghost = list.ghost.data();
    v.norm = CubicSpline{Dimension}.normalisation(), v.q1 = rp.viscosity.q1, v.q2 = rp.viscosity.q2;
    v.body[0] = rp.body[0], v.body[1] = rp.body[1], v.body[2] = rp.body[2];
    v.dimension = Dimension, v.renormalise = Renormalise;
    v.ax = s.ax.data(), v.ay = s.ay.data(), v.az = s.az.data(), v.drho = s.drho.data(), v.de = s.de.data();
    return v;
}

// One block of contiguous real particles per thread, of about equal work: the partners listed
// (forward and ghost: the offsets are their prefix sums) plus a row's own cost. Contiguous in cell
// order, a block's forward partners lie just after it, so each thread writes its received sums
// into a narrow band (RateScratch::reach) instead of across every particle, and the merge reads
// those bands only: with a team of 16 that is the difference between a few and 16 passes over
// the particles' sums.
void split_pair_blocks(const NeighbourList& list, std::size_t real, int team, std::vector<std::size_t>& begin) {
    constexpr std::uint64_t row_cost = 8;  // a row's fixed cost, in listed partners
    const auto work_before = [&](std::size_t i) {
        return std::uint64_t{list.forward_offsets[i]} + list.ghost_offsets[i] + row_cost * i;
    };
    const std::uint64_t total = work_before(real);
    begin.assign(static_cast<std::size_t>(team) + 1, real);
    begin[0] = 0;
    for (int t = 1; t < team; ++t) {
        const std::uint64_t goal = total * static_cast<std::uint64_t>(t) / static_cast<std::uint64_t>(team);
        std::size_t low = begin[static_cast<std::size_t>(t) - 1], high = real;  // first i with work_before(i) >= goal
        while (low < high) {
            const std::size_t middle = low + (high - low) / 2;
            if (work_before(middle) < goal)
                low = middle + 1;
            else
                high = middle;
        }
        begin[static_cast<std::size_t>(t)] = low;
    }
}

template <int Dimension, bool Renormalise, bool Solid>
void pair_loop(Particles& s, const NeighbourList& list, const RateParameters& rp, RateScratch& scratch) {
    const std::size_t real = s.real;
    const int team = rp.threads > 0 ? rp.threads : 1;
    const double norm = CubicSpline{Dimension}.normalisation();
    const MonaghanViscosity viscosity = rp.viscosity;
    const PackedParticle* nb = scratch.packed.data();
    const std::uint8_t* interacting = s.interacting.data();
    const Correction* correction = s.correction.data();
    // Zero once; afterwards the final pass zeroes each entry as it reads it.
    if (scratch.received.size() != real * static_cast<std::size_t>(team))
        scratch.received.assign(real * static_cast<std::size_t>(team), RateSums{0, 0, 0, 0, 0});
    scratch.inside.resize(static_cast<std::size_t>(team));
    const SymmetricTensor* stress = scratch.stress_over_rho2.data();
    if constexpr (Solid) {
        scratch.gradient.resize(real);
        if (scratch.received_gradient.size() != real * static_cast<std::size_t>(team))
            scratch.received_gradient.assign(real * static_cast<std::size_t>(team), GradientSums{});
    }

    // The SIMD rows (pair_rows.hpp) for fluid decks when the CPU runs them; the scalar loop below
    // then has nothing to do.
    const PairRowsPath fast = !Solid && rp.simd && !rp.viscosity_switch ? best_pair_rows(rp.avx512) : PairRowsPath{};
    const PairRows view = fast.run ? pair_rows_view<Dimension, Renormalise>(s, list, rp, scratch) : PairRows{};

    const RateScratch::BlocksKey key{&list, list.builds, static_cast<std::size_t>(team), real, list.pairs()};
    if (!(scratch.blocks_of == key)) {
        split_pair_blocks(list, real, team, scratch.block_begin);
        scratch.reach.assign(static_cast<std::size_t>(team), 0);
        scratch.longest.assign(static_cast<std::size_t>(team), 0);
#pragma omp parallel for schedule(static, 1) num_threads(team)
        for (std::size_t b = 0; b < static_cast<std::size_t>(team); ++b) {
            // The block's longest row (the size of `inside`) and the highest partner it writes to.
            const std::size_t first = scratch.block_begin[b], last = scratch.block_begin[b + 1];
            std::uint32_t longest = 0;
            std::size_t top = first;
            for (std::size_t i = first; i < last; ++i) {
                const std::uint32_t from = list.forward_offsets[i], to = list.forward_offsets[i + 1];
                longest = std::max(longest, to - from + list.ghost_offsets[i + 1] - list.ghost_offsets[i]);
                for (std::uint32_t k = from; k < to; ++k) top = std::max<std::size_t>(top, list.forward[k]);
            }
            scratch.reach[b] = top, scratch.longest[b] = longest;
        }
        scratch.blocks_of = key;
    }
    std::chrono::steady_clock::time_point pairs_done;

#pragma omp parallel num_threads(team)
    {
        // Block b's sums go to received copy b; a thread runs blocks t, t + threads... (one each
        // unless the runtime gave fewer threads than asked).
        const auto t = static_cast<std::size_t>(omp_get_thread_num());
        const auto threads = static_cast<std::size_t>(omp_get_num_threads());
        std::vector<std::uint32_t>& inside = scratch.inside[t];
        for (std::size_t b = t; b < static_cast<std::size_t>(team); b += threads) {
            const std::size_t first = scratch.block_begin[b], last = scratch.block_begin[b + 1];
            RateSums* received = scratch.received.data() + b * real;
            GradientSums* received_gradient = Solid ? scratch.received_gradient.data() + b * real : nullptr;
            if (fast.run) {
                PairRows mine = view;
                mine.stride = scratch.longest[b] + 16;
                if (inside.size() < mine.stride) inside.resize(mine.stride);
                mine.inside = inside.data();
                mine.received = received->data();  // Sums: 5 contiguous doubles per particle
                for (std::size_t from = first; from < last; from += 256)
                    fast.run(mine, from, std::min(last, from + 256));
                continue;
            }
            for (std::size_t i = first; i < last; ++i) {
                if (!interacting[i]) continue;
                const PackedParticle& me = nb[i];
                const Correction& bi = correction[i];
                RateSums own{rp.body[0], rp.body[1], rp.body[2], 0, 0};
                GradientSums own_gradient{};
                const std::size_t pairs = within_support(me, nb, list.forward.data(), list.forward_offsets[i],
                                                         list.forward_offsets[i + 1], inside);
                for (std::size_t k = 0; k < pairs; ++k) {
                    const std::uint32_t j = inside[k];
                    const PackedParticle& o = nb[j];
                    const double dx = me.x - o.x, dy = me.y - o.y, dz = me.z - o.z;
                    const PairTerms terms =
                        pair_terms<Dimension, Renormalise>(me, o, bi, correction[j], dx, dy, dz,
                                                           dx * dx + dy * dy + dz * dz, norm, viscosity);
                    add_to<Renormalise>(own, terms, me, o);
                    add_reverse<Renormalise>(received[j], terms, me, o);
                    if constexpr (Solid) {
                        const StressTerms st = stress_terms(stress[i], stress[j], me, o, terms, dx, dy, dz);
                        add_stress(own, own_gradient, st, o.m, o.volume, 1.0);
                        add_stress(received[j], received_gradient[j], st, me.m, me.volume, -1.0);
                    }
                }
                // Ghosts act on real particles only: one-sided.
                const std::size_t images =
                    within_support(me, nb, list.ghost.data(), list.ghost_offsets[i], list.ghost_offsets[i + 1], inside);
                for (std::size_t k = 0; k < images; ++k) {
                    const std::uint32_t j = inside[k];
                    const PackedParticle& o = nb[j];
                    const double dx = me.x - o.x, dy = me.y - o.y, dz = me.z - o.z;
                    const PairTerms terms =
                        pair_terms<Dimension, Renormalise>(me, o, bi, correction[j], dx, dy, dz,
                                                           dx * dx + dy * dy + dz * dz, norm, viscosity);
                    add_to<Renormalise>(own, terms, me, o);
                    if constexpr (Solid)
                        add_stress(own, own_gradient, stress_terms(stress[i], stress[j], me, o, terms, dx, dy, dz), o.m,
                                   o.volume, 1.0);
                }
                s.ax[i] = own[0], s.ay[i] = own[1], s.az[i] = own[2], s.drho[i] = own[3], s.de[i] = own[4];
                if constexpr (Solid) scratch.gradient[i] = own_gradient;
            }
        }
#pragma omp barrier  // every pair is done: add what each particle received, in thread order
#pragma omp master
        pairs_done = std::chrono::steady_clock::now();
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < real; ++i) {
            for (int u = 0; u < team; ++u) {
                const auto w = static_cast<std::size_t>(u);  // entries outside a block's band stay zero
                if (i < scratch.block_begin[w] || i > scratch.reach[w]) continue;
                RateSums& r = scratch.received[w * real + i];
                s.ax[i] += r[0], s.ay[i] += r[1], s.az[i] += r[2], s.drho[i] += r[3], s.de[i] += r[4];
                r = RateSums{0, 0, 0, 0, 0};
            }
            if constexpr (Solid) {
                GradientSums& sum = scratch.gradient[i];
                if (!interacting[i]) sum = GradientSums{};
                for (int u = 0; u < team; ++u) {
                    const auto w = static_cast<std::size_t>(u);
                    if (i < scratch.block_begin[w] || i > scratch.reach[w]) continue;
                    GradientSums& r = scratch.received_gradient[w * real + i];
                    for (int k = 0; k < 18; ++k) sum[k] += r[k];
                    r = GradientSums{};
                }
                const double shear = interacting[i] ? rp.shear[s.part[i]] : 0.0;
                if (shear > 0) {
                    Tensor P, Q;
                    std::copy(sum.begin(), sum.begin() + 9, P.begin()),
                        std::copy(sum.begin() + 9, sum.end(), Q.begin());
                    s.dstress[i] = jaumann_stress_rate(velocity_gradient(P, Q, Dimension), s.stress[i], shear);
                } else {
                    s.dstress[i] = SymmetricTensor{};
                }
            }
            if (!interacting[i]) {
                s.ax[i] = rp.body[0], s.ay[i] = rp.body[1], s.az[i] = Dimension == 2 ? 0.0 : rp.body[2];
                s.drho[i] = 0, s.de[i] = 0, s.dh[i] = 0;
                continue;
            }
            if (Dimension == 2) s.az[i] = 0.0;
            s.drho[i] *= continuity_factor<Renormalise>(s.rho[i], s.m[i], s.omega[i]);  // continuity.hpp
            s.dh[i] = smoothing_length_rate(rp.h_rule, Dimension, s.h[i], s.rho[i], s.drho[i]);
        }
    }
    scratch.merge_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - pairs_done).count();
}

void evaluate_rates(Particles& s, const NeighbourList& list, const RateParameters& parameters, RateScratch& scratch) {
    // Pack what neighbours are read for, ghosts included; the formulation's two values (continuity.hpp)
    // and V = m / rho once per particle.
    // The SIMD loop reads the same values from two arrays (rates.hpp), the scalar loop from one.
    const std::size_t n = s.total();
    const bool simd =
        parameters.simd && !parameters.solid && !parameters.viscosity_switch && best_pair_rows(parameters.avx512).run;
    const double* switches = parameters.viscosity_switch ? parameters.viscosity_switch->data() : nullptr;
    if (simd)
        scratch.positions.resize(n), scratch.positions_f.resize(n), scratch.records.resize(n);
    else
        scratch.packed.resize(n);
    PackedParticle* packed = scratch.packed.data();
    std::array<double, 4>* positions = scratch.positions.data();
    std::array<float, 4>* positions_f = scratch.positions_f.data();
    PairRecord* records = scratch.records.data();
    double largest = 0;  // the largest coordinate magnitude: the single-precision filter's rounding scales with it
#pragma omp parallel for schedule(static) reduction(max : largest) num_threads(parameters.threads)
    for (std::size_t i = 0; i < n; ++i) {
        const double m = s.interacting[i] ? s.m[i] : 0.0, volume = m / s.rho[i];
        const FormValues f = form_values(parameters.renormalise, s.p[i], s.rho[i], m, s.m[i], s.omega[i]);
        if (simd) {
            positions[i] = {s.x[i], s.y[i], s.z[i], s.h[i]};
            positions_f[i] = {static_cast<float>(s.x[i]), static_cast<float>(s.y[i]), static_cast<float>(s.z[i]),
                              static_cast<float>(s.h[i])};
            largest = std::max({largest, std::abs(s.x[i]), std::abs(s.y[i]), std::abs(s.z[i])});
            records[i] = {s.vx[i], s.vy[i], s.vz[i], m, s.rho[i], s.c[i], f.s6, f.s7};
        } else {
            const double sw = !switches ? 1.0 : switches[i < s.real ? i : s.ghost_source[i - s.real]];
            packed[i] = {s.x[i], s.y[i],   s.z[i], s.vx[i], s.vy[i], s.vz[i], s.h[i],
                         m,      s.rho[i], s.c[i], f.s6,    f.s7,    volume,  sw};
        }
    }
    // Rounding a coordinate to float moves it by at most 2^-24 of `largest`; a separation in single
    // precision is then within about 4 such steps (and 2^-22 of itself) of the exact one. The margin
    // doubles that (pair_rows_kernel.hpp adds a relative slack too).
    scratch.margin = static_cast<float>(std::ldexp(largest, -20));
    const bool two = parameters.kernel.dimension == 2;
    if (parameters.solid) {  // *MAT_ELASTIC parts: S / rho^2 too, and the loops with the stress terms
        scratch.stress_over_rho2.resize(n);
        SymmetricTensor* sr2 = scratch.stress_over_rho2.data();
#pragma omp parallel for schedule(static) num_threads(parameters.threads)
        for (std::size_t i = 0; i < n; ++i) {
            const double inv = 1.0 / (s.rho[i] * s.rho[i]);
            for (int k = 0; k < 6; ++k) sr2[i][k] = s.stress[i][k] * inv;
        }
        if (parameters.renormalise)
            two ? pair_loop<2, true, true>(s, list, parameters, scratch)
                : pair_loop<3, true, true>(s, list, parameters, scratch);
        else
            two ? pair_loop<2, false, true>(s, list, parameters, scratch)
                : pair_loop<3, false, true>(s, list, parameters, scratch);
        return;
    }
    if (parameters.renormalise)
        two ? pair_loop<2, true, false>(s, list, parameters, scratch)
            : pair_loop<3, true, false>(s, list, parameters, scratch);
    else
        two ? pair_loop<2, false, false>(s, list, parameters, scratch)
            : pair_loop<3, false, false>(s, list, parameters, scratch);
}

}  // namespace

void compute_rates(Particles& s, const NeighbourList& list, const RateParameters& parameters, RateScratch& scratch) {
    const auto start = std::chrono::steady_clock::now();
    evaluate_rates(s, list, parameters, scratch);
    scratch.rates_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sphdeck::refsolver
