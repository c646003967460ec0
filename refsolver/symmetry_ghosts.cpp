#include "refsolver/symmetry_ghosts.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <bit>

#include "refsolver/tensor3.hpp"

namespace sphdeck::refsolver {

namespace {

Eigen::Vector3d unit_normal(const SymmetryPlane& q) { return {q.normal[0], q.normal[1], q.normal[2]}; }

// p - 2 dd n, dd = p . n - offset the signed distance.
void mirror_point(const SymmetryPlane& q, double& x, double& y, double& z) {
    const Eigen::Vector3d n = unit_normal(q);
    Eigen::Vector3d p(x, y, z);
    p -= 2 * (p.dot(n) - q.offset) * n;
    x = p[0], y = p[1], z = p[2];
}

// v - 2 (v . n) n.
void mirror_vector(const SymmetryPlane& q, double& x, double& y, double& z) {
    const Eigen::Vector3d n = unit_normal(q);
    Eigen::Vector3d v(x, y, z);
    v -= 2 * v.dot(n) * n;
    x = v[0], y = v[1], z = v[2];
}

// R B R with R = I - 2 n n^T (a reflection: symmetric), B symmetric stored as xx yy zz xy xz yz.
[[gnu::always_inline]] inline std::array<double, 6> mirror_tensor(const SymmetryPlane& q,
                                                                  const std::array<double, 6>& b) {
    const Eigen::Vector3d n = unit_normal(q);
    const Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity() - (2 * n) * n.transpose();
    const Eigen::Matrix3d rb = reflection * symmetric_matrix(b);
    return symmetric_entries(rb * reflection);
}

}  // namespace

void build_ghosts(Particles& s, const std::vector<SymmetryPlane>& planes, double radius, int threads,
                  unsigned max_planes_per_image) {
    s.ghost_source.clear(), s.ghost_planes.clear();
    const std::size_t count = std::min<std::size_t>(planes.size(), 8);
    for (std::size_t i = 0; i < s.real; ++i) {
        if (!s.active[i]) continue;
        unsigned near = 0;
        for (std::size_t k = 0; k < count; ++k) {
            const SymmetryPlane& q = planes[k];
            const double dd = s.x[i] * q.normal[0] + s.y[i] * q.normal[1] + s.z[i] * q.normal[2] - q.offset;
            if (dd <= radius) near |= 1u << k;
        }
        // Every non-empty subset of the near planes, up to max_planes_per_image planes per image.
        for (unsigned subset = near; subset; subset = (subset - 1) & near) {
            if (static_cast<unsigned>(std::popcount(subset)) > max_planes_per_image) continue;
            s.ghost_source.push_back(static_cast<std::uint32_t>(i));
            s.ghost_planes.push_back(static_cast<std::uint8_t>(subset));
        }
    }
    s.resize_pair_arrays();
    update_ghosts(s, planes, threads);
}

void update_ghosts(Particles& s, const std::vector<SymmetryPlane>& planes, int threads) {
    const std::size_t n = s.ghosts();
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : 1)
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t g = s.real + k, i = s.ghost_source[k];
        double x = s.x[i], y = s.y[i], z = s.z[i], vx = s.vx[i], vy = s.vy[i], vz = s.vz[i];
        std::array<double, 6> b = s.correction[i];
        for (std::size_t q = 0; q < planes.size() && q < 8; ++q) {
            if (!(s.ghost_planes[k] >> q & 1u)) continue;
            mirror_point(planes[q], x, y, z);
            if (planes[q].tied)
                vx = -vx, vy = -vy, vz = -vz;
            else
                mirror_vector(planes[q], vx, vy, vz);
            if (b[3] != 0 || b[4] != 0 || b[5] != 0 || b[0] != b[1] || b[1] != b[2]) b = mirror_tensor(planes[q], b);
        }
        s.x[g] = x, s.y[g] = y, s.z[g] = z, s.vx[g] = vx, s.vy[g] = vy, s.vz[g] = vz;
        s.rho[g] = s.rho[i], s.p[g] = s.p[i], s.c[g] = s.c[i], s.h[g] = s.h[i], s.m[g] = s.m[i];
        s.interacting[g] = s.interacting[i];
        s.correction[g] = b;
        if (s.solid) {  // deviatoric stress R S R: Slide flips the n-t shear stresses (§8.6)
            SymmetricTensor st = s.stress[i];
            for (std::size_t q = 0; q < planes.size() && q < 8; ++q)
                if (s.ghost_planes[k] >> q & 1u) st = mirror_tensor(planes[q], st);
            s.stress[g] = st;
        }
    }
}

std::size_t reflect_crossed(Particles& s, const std::vector<SymmetryPlane>& planes, int threads) {
    std::size_t put_back = 0;
    const std::size_t n = s.real;
    // Particle by particle, the planes in order (what happens to a particle depends on its own
    // state only): one pass over the particles rather than one per plane.
#pragma omp parallel for schedule(static) reduction(+ : put_back) num_threads(threads > 0 ? threads : 1)
    for (std::size_t i = 0; i < n; ++i) {
        for (const SymmetryPlane& q : planes) {
            const double dd = s.x[i] * q.normal[0] + s.y[i] * q.normal[1] + s.z[i] * q.normal[2] - q.offset;
            if (!(dd < 0)) continue;
            mirror_point(q, s.x[i], s.y[i], s.z[i]);
            const double vn = s.vx[i] * q.normal[0] + s.vy[i] * q.normal[1] + s.vz[i] * q.normal[2];
            if (vn < 0) mirror_vector(q, s.vx[i], s.vy[i], s.vz[i]);
            const double vhn = s.vx_half[i] * q.normal[0] + s.vy_half[i] * q.normal[1] + s.vz_half[i] * q.normal[2];
            if (vhn < 0) mirror_vector(q, s.vx_half[i], s.vy_half[i], s.vz_half[i]);
            ++put_back;
        }
    }
    return put_back;
}

}  // namespace sphdeck::refsolver
