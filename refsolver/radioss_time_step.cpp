#include "refsolver/radioss_time_step.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "refsolver/kernel.hpp"

namespace sphdeck::refsolver {

namespace {

// -d_ij v_ij.x_ij / (r^2 + 0.01 d_ij^2) of one pair within the support, else 0.
double approach(const Particles& s, std::size_t i, std::size_t j) {
    const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
    const double r2 = dx * dx + dy * dy + dz * dz, d = 0.5 * (s.h[i] + s.h[j]);
    if (r2 >= 4 * d * d) return 0;
    const double vr = (s.vx[i] - s.vx[j]) * dx + (s.vy[i] - s.vy[j]) * dy + (s.vz[i] - s.vz[j]) * dz;
    return -d * vr / (r2 + 0.01 * d * d);
}

// One pair (i, j) within the support: g = grad_i W_ij at d_ij (kernel.hpp, the engine's weight.F),
// v_ij, x_ij. `inside` false beyond the support.
struct Pair {
    bool inside = false;
    double r = 0, d = 0;
    Eigen::Vector3d g = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::Zero();
};

Pair stiffness_pair(const Particles& s, std::size_t i, std::size_t j) {
    Pair p;
    p.x = Eigen::Vector3d(s.x[i], s.y[i], s.z[i]) - Eigen::Vector3d(s.x[j], s.y[j], s.z[j]);
    const double r2 = p.x.squaredNorm();
    p.d = 0.5 * (s.h[i] + s.h[j]);
    if (!(r2 < 4 * p.d * p.d)) return p;
    p.inside = true;
    p.r = std::sqrt(r2);
    const double f = CubicSpline{3}.gradient_factor(p.r, p.d);
    p.g = f * p.x;
    p.v = Eigen::Vector3d(s.vx[i], s.vy[i], s.vz[i]) - Eigen::Vector3d(s.vx[j], s.vy[j], s.vz[j]);
    return p;
}

// The stiffness the pair (i, j) adds to particle i (spforcp.F "nodal stability"; header).
double pair_stiffness(const Particles& s, std::size_t i, std::size_t j, const Pair& p, double fi, double fj, double qa,
                      double qb) {
    const double vi = s.m[i] / s.rho[i], vj = s.m[j] / s.rho[j];
    const double g2 = p.g.squaredNorm();
    double k = 2 * (s.m[i] * s.c[i] * s.c[i] * vj * vj * g2 + s.m[j] * s.c[j] * s.c[j] * vi * vi * g2);
    const double v_dot_x = p.v.dot(p.x);
    double mu = std::min(0.0, p.d * v_dot_x / (p.r * p.r + 0.01 * p.d * p.d));
    mu *= 0.5 * (fi + fj);
    const double c = 0.5 * (s.c[i] + s.c[j]);
    const double pi = (qa * mu * mu - qb * c * mu) * 2 / std::max(1e-20, s.rho[i] + s.rho[j]);
    const double rate = std::max(1e-20, std::abs(v_dot_x) / std::max(1e-20, p.r));  // dl/dt
    const double damping = s.m[i] * s.m[j] * std::abs(pi) * std::sqrt(g2) / rate;
    const double z = damping / std::max(1e-20, std::sqrt(2 * k * s.m[i]));
    const double shrink = std::sqrt(1 + z * z) - z;
    return k / std::max(1e-20, shrink * shrink);
}

// Calls real(i, j, pair) once for each pair of interacting real particles within reach (the half list
// names each once) and ghost(i, j, pair) for each interacting ghost within reach of a real particle i, in
// the list's order: the velocity gradient and the nodal stiffness walk the pairs alike.
template <typename RealPair, typename GhostPair>
void for_each_interacting_pair(const Particles& s, const NeighbourList& list, RealPair&& real, GhostPair&& ghost) {
    for (std::size_t i = 0; i < s.real; ++i) {
        if (!s.interacting[i]) continue;
        for (std::uint32_t k = list.forward_offsets[i]; k < list.forward_offsets[i + 1]; ++k) {
            const std::uint32_t j = list.forward[k];
            if (!s.interacting[j]) continue;
            const Pair p = stiffness_pair(s, i, j);
            if (p.inside) real(i, std::size_t(j), p);
        }
        for (std::uint32_t k = list.ghost_offsets[i]; k < list.ghost_offsets[i + 1]; ++k) {
            const std::uint32_t j = list.ghost[k];
            if (!s.interacting[j]) continue;
            const Pair p = stiffness_pair(s, i, j);
            if (p.inside) ghost(i, std::size_t(j), p);
        }
    }
}

}  // namespace

double radioss_particle_time_step(const Particles& s, const NeighbourList& list, double qa, double qb, int threads) {
    const std::size_t n = s.real;
    std::vector<double> mu(n, 0.0);
    // The half list names each real pair once: both particles take its approach (serial: two writes per pair).
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        for (std::uint32_t k = list.forward_offsets[i]; k < list.forward_offsets[i + 1]; ++k) {
            const std::uint32_t j = list.forward[k];
            const double a = approach(s, i, j);
            mu[i] = std::max(mu[i], a), mu[j] = std::max(mu[j], a);
        }
        for (std::uint32_t k = list.ghost_offsets[i]; k < list.ghost_offsets[i + 1]; ++k)
            mu[i] = std::max(mu[i], approach(s, i, list.ghost[k]));
    }
    double smallest = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : smallest) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (!s.active[i]) continue;
        const double q = qb * s.c[i] + qa * mu[i];
        const double speed = q + std::sqrt(q * q + s.c[i] * s.c[i]);
        if (speed > 0) smallest = std::min(smallest, s.h[i] / speed);
    }
    return smallest;
}

RadiossGradient radioss_velocity_gradient(const Particles& s, const NeighbourList& list, double dt1) {
    const std::size_t n = s.real;
    // Per real particle, from grad v_i = -sum_j V_j v_ij (x) g_ij: its trace div v, its antisymmetric
    // part rot v = sum_j V_j v_ij x g_ij, and sum_j V_j^2 |v_ij|^2 |g_ij|^2.
    struct Sums {
        double div = 0;
        Eigen::Vector3d rot = Eigen::Vector3d::Zero();
        double second = 0;
    };
    std::vector<Sums> sums(n);
    // j's share of i's sums, V_j the volume; seen from j, v and g both change sign, so the same
    // products with V_i.
    auto add = [&](std::size_t i, double volume, const Pair& p) {
        sums[i].div -= volume * p.v.dot(p.g);
        sums[i].rot += volume * p.v.cross(p.g);
        sums[i].second += volume * volume * p.v.squaredNorm() * p.g.squaredNorm();
    };
    for_each_interacting_pair(
        s, list,
        [&](std::size_t i, std::size_t j, const Pair& p) {
            add(i, s.m[j] / s.rho[j], p), add(j, s.m[i] / s.rho[i], p);
        },
        [&](std::size_t i, std::size_t j, const Pair& p) { add(i, s.m[j] / s.rho[j], p); });
    RadiossGradient out{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    for (std::size_t i = 0; i < n; ++i) {
        out.second_order[i] = -0.5 * dt1 * sums[i].second;
        const double div = std::abs(sums[i].div + out.second_order[i]);
        const double rot = sums[i].rot.norm();
        out.f[i] = div / std::max(1e-20, div + rot);
    }
    return out;
}

double radioss_nodal_time_step(const Particles& s, const NeighbourList& list, const std::vector<double>& f, double qa,
                               double qb, int threads) {
    const std::size_t n = s.real;
    std::vector<double> stiffness(n, 0.0);
    for_each_interacting_pair(
        s, list,
        [&](std::size_t i, std::size_t j, const Pair& p) {
            stiffness[i] += pair_stiffness(s, i, j, p, f[i], f[j], qa, qb);
            Pair q = p;  // the same pair seen from j: x and v reversed, g reversed (|g| alike)
            q.x = -p.x, q.v = -p.v, q.g = -p.g;
            stiffness[j] += pair_stiffness(s, j, i, q, f[j], f[i], qa, qb);
        },
        [&](std::size_t i, std::size_t j, const Pair& p) {
            stiffness[i] += pair_stiffness(s, i, j, p, f[i], f[s.ghost_source[j - n]], qa, qb);
        });
    double smallest = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : smallest) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i)
        if (s.interacting[i] && stiffness[i] > 0) smallest = std::min(smallest, std::sqrt(2 * s.m[i] / stiffness[i]));
    return smallest;
}

}  // namespace sphdeck::refsolver
