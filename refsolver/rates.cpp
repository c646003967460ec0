#include "refsolver/rates.hpp"

#include <cmath>
#include <vector>

#include "refsolver/continuity.hpp"
#include "refsolver/energy.hpp"
#include "refsolver/momentum.hpp"

namespace sphdeck::refsolver {

namespace {

// What the pair loop reads of a neighbour, packed together: one or two cache lines per neighbour
// instead of one per array. Non-interacting particles get m = 0 and contribute nothing.
struct Neighbour {
    double x, y, z, vx, vy, vz, h, m, rho, c, p_over_rho2, pad;
};

// The pair loop, specialised on the dimension (the kernel's powers of h) and on FORM 1. Per pair:
// one square root and two divisions (1 / h_ij and the outer-shell 1 / r); p_j / rho_j^2 is
// computed once per particle.
template <int Dimension, bool Renormalise>
void gather(Particles& s, const NeighbourList& list, const RateParameters& rp, const std::vector<Neighbour>& packed) {
    const std::size_t real = s.real;
    const double norm = CubicSpline{Dimension}.normalisation();
    const MonaghanViscosity viscosity = rp.viscosity;
    const double* h = s.h.data();
    const double* rho = s.rho.data();
    const Neighbour* nb = packed.data();
    const std::uint8_t* interacting = s.interacting.data();
    const std::array<double, 6>* correction = s.correction.data();
    const std::uint32_t* offsets = list.offsets.data();
    const std::uint32_t* neighbours = list.neighbours.data();

#pragma omp parallel for schedule(dynamic, 256) num_threads(rp.threads)
    for (std::size_t i = 0; i < real; ++i) {
        double ax = rp.body[0], ay = rp.body[1], az = rp.body[2], drho = 0, de = 0;
        if (interacting[i]) {
            const Neighbour& me = nb[i];
            const double xi = me.x, yi = me.y, zi = me.z, vxi = me.vx, vyi = me.vy, vzi = me.vz;
            const double rhoi = me.rho, ci = me.c, hi = me.h, pressure_i = me.p_over_rho2;
            const std::array<double, 6> bi = correction[i];
            for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k) {
                const std::uint32_t j = neighbours[k];
                const Neighbour& o = nb[j];
                const double dx = xi - o.x, dy = yi - o.y, dz = zi - o.z;
                const double r2 = dx * dx + dy * dy + dz * dz, hij = 0.5 * (hi + o.h);
                if (r2 >= 4 * hij * hij) continue;
                // grad_i W_ij = F x_ij (kernel.hpp), F = C_d / h^(d+2) theta'(q) / q.
                const double inv_h = 1.0 / hij, r = std::sqrt(r2), q = r * inv_h;
                const double inv_h2 = inv_h * inv_h;
                const double scale = norm * (Dimension == 2 ? inv_h2 * inv_h2 : inv_h2 * inv_h2 * inv_h);
                const double f = q <= 1 ? scale * (-3.0 + 2.25 * q) : -scale * 0.75 * (2 - q) * (2 - q) * (hij / r);
                double gx = f * dx, gy = f * dy, gz = f * dz;
                if constexpr (Renormalise) {
                    const std::array<double, 6>& bj = correction[j];
                    const double xx = 0.5 * (bi[0] + bj[0]), yy = 0.5 * (bi[1] + bj[1]), zz = 0.5 * (bi[2] + bj[2]);
                    const double xy = 0.5 * (bi[3] + bj[3]), xz = 0.5 * (bi[4] + bj[4]), yz = 0.5 * (bi[5] + bj[5]);
                    const double tx = xx * gx + xy * gy + xz * gz, ty = xy * gx + yy * gy + yz * gz;
                    gz = xz * gx + yz * gy + zz * gz, gx = tx, gy = ty;
                }
                const double dvx = vxi - o.vx, dvy = vyi - o.vy, dvz = vzi - o.vz;
                const double v_dot_g = dvx * gx + dvy * gy + dvz * gz;
                const double v_dot_x = dvx * dx + dvy * dy + dvz * dz;
                const double pi_ij =
                    v_dot_x < 0 ? viscosity.pi(v_dot_x, r2, hij, 0.5 * (ci + o.c), 0.5 * (rhoi + o.rho)) : 0.0;
                const double a_ij = momentum_factor(pressure_i, o.p_over_rho2, pi_ij);
                const double mj = o.m;
                drho += continuity_term(mj / o.rho, v_dot_g);
                ax -= mj * a_ij * gx, ay -= mj * a_ij * gy, az -= mj * a_ij * gz;
                de += energy_term(mj, a_ij, v_dot_g);
            }
        }
        s.ax[i] = ax, s.ay[i] = ay, s.az[i] = Dimension == 2 ? 0.0 : az;
        drho *= rho[i];  // continuity.hpp: rho_i sum_j V_j v_ij . g_ij
        s.drho[i] = drho, s.de[i] = de;
        s.dh[i] = interacting[i] ? smoothing_length_rate(rp.h_rule, Dimension, h[i], rho[i], drho) : 0.0;
    }
}

}  // namespace

void compute_rates(Particles& s, const NeighbourList& list, const RateParameters& parameters) {
    // Pack what neighbours are read for, ghosts included; p / rho^2 once per particle (momentum.hpp).
    const std::size_t n = s.total();
    std::vector<Neighbour> packed(n);
#pragma omp parallel for schedule(static) num_threads(parameters.threads)
    for (std::size_t i = 0; i < n; ++i)
        packed[i] = {s.x[i], s.y[i], s.z[i], s.vx[i], s.vy[i], s.vz[i], s.h[i], s.interacting[i] ? s.m[i] : 0.0,
                     s.rho[i], s.c[i], s.p[i] / (s.rho[i] * s.rho[i]), 0.0};
    const bool two = parameters.kernel.dimension == 2;
    if (parameters.renormalise) two ? gather<2, true>(s, list, parameters, packed) : gather<3, true>(s, list, parameters, packed);
    else two ? gather<2, false>(s, list, parameters, packed) : gather<3, false>(s, list, parameters, packed);
}

}  // namespace sphdeck::refsolver
