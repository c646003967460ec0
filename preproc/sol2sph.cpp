// generate_sol2sph: SOL2SPH particle layouts of bricks and tetras (sph-algorithms.md §9.1, §9.2;
// OpenRadioss starter/source/elements/sph/soltosph.F).
#include "preproc/sol2sph.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "model/id_index.hpp"

namespace sphdeck::preproc {
namespace {

using Vec = Eigen::Vector3d;

// Parent-cube corners of the 8-node brick in /BRICK order: 1-4 the face zeta = -1, counter-
// clockwise seen from the face zeta = +1, 5-8 above them.
constexpr int corner_sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

Vec brick_point(const std::array<Vec, 8>& p, double r, double s, double t) {
    Vec x = Vec::Zero();
    for (int k = 0; k < 8; ++k) {
        const double n = (1 + corner_sign[k][0] * r) * (1 + corner_sign[k][1] * s) * (1 + corner_sign[k][2] * t) / 8;
        x += n * p[k];
    }
    return x;
}

// det of the Jacobian dx/d(r, s, t) of the trilinear map: sum over the corners of x_k (x) dN_k/d(r, s, t).
double brick_jacobian(const std::array<Vec, 8>& p, double r, double s, double t) {
    Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 8; ++k) {
        const double a = corner_sign[k][0], b = corner_sign[k][1], c = corner_sign[k][2];
        const Vec d(a * (1 + b * s) * (1 + c * t) / 8, b * (1 + a * r) * (1 + c * t) / 8,
                    c * (1 + a * r) * (1 + b * s) / 8);
        j.noalias() += p[k] * d.transpose();
    }
    return j.determinant();
}

// The integral of det J over the box [r0, r1] x [s0, s1] x [t0, t1] of the parent cube: 2x2x2 Gauss
// points, exact since det J of a trilinear map has degree <= 2 in each variable.
double brick_volume(const std::array<Vec, 8>& p, double r0, double r1, double s0, double s1, double t0, double t1) {
    const double g = 1 / std::sqrt(3.0);
    double v = 0;
    for (double a : {-g, g})
        for (double b : {-g, g})
            for (double c : {-g, g})
                v += brick_jacobian(p, 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * a, 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * b,
                                    0.5 * (t0 + t1) + 0.5 * (t1 - t0) * c);
    return v * (r1 - r0) * (s1 - s0) * (t1 - t0) / 8;
}

// The signed volume: a triple product of the edges from corner 0.
double tetra_volume(const std::array<Vec, 4>& p) {
    const Vec a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
    return a.dot(b.cross(c)) / 6;
}

struct PartSetup {
    const model::RadiossSolidProperty* property = nullptr;
    Sol2sphPart summary;
    std::vector<double> pitches;
};

class Generator {
public:
    explicit Generator(const model::Model& m) : m_(m), f_(*m.radioss), nodes_(m.nodes.id) {}

    Sol2sph run() {
        std::vector<PartSetup> parts = setup_parts();
        for (PartSetup& part : parts) {
            if (part.summary.ndir >= 1 && part.summary.ndir <= 9) {
                elements(part, f_.bricks, true);
                elements(part, f_.tetra4, false);
            }
            std::size_t unsupported = 0;
            for (const model::RadiossSolids* other : {&f_.tetra10, &f_.penta6}) {
                std::size_t n = 0;
                for (std::size_t e = 0; e < other->size(); ++e) n += other->part[e] == part.summary.solid_part;
                if (n == 0) continue;
                part.summary.skipped += n;
                unsupported += n;
                part.summary.notes.push_back(
                    fmt::format("{} {} element(s) get no particles: SOL2SPH covers 8-node "
                                "bricks and 4-node tetras only",
                                n, other == &f_.tetra10 ? "/TETRA10" : "/PENTA6"));
            }
            explain_no_particles(part.summary, unsupported);
            std::vector<double>& v = part.pitches;
            if (!v.empty()) {
                std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
                part.summary.pitch = v[v.size() / 2];
            }
            out_.parts.push_back(std::move(part.summary));
        }
        return std::move(out_);
    }

private:
    // The starter silently creates nothing for such a part; the user asked for particles.
    static void explain_no_particles(Sol2sphPart& s, std::size_t unsupported) {
        if (s.ndir < 1 || s.ndir > 9 || s.particles > 0) return;  // a bad Ndir has its own note (RAD011)
        if (s.skipped == 0)
            s.no_particles = "no particles are generated: the part has no elements";
        else if (unsupported == s.skipped)
            s.no_particles = fmt::format(
                "no particles are generated: its {} element(s) are all of kinds SOL2SPH does "
                "not convert (it takes 8-node bricks and 4-node tetras)",
                unsupported);
        else
            s.no_particles = "no particles are generated: every element of the part was rejected";
    }

    std::vector<PartSetup> setup_parts() {
        std::vector<PartSetup> parts;
        for (const model::Part& part : m_.parts) {
            const model::RadiossSolidProperty* prop = nullptr;
            for (const auto& p : f_.solid_properties)
                if (std::to_string(p.id) == part.section.value && p.sol2sph()) prop = &p;
            if (!prop) continue;
            PartSetup s;
            s.property = prop;
            Sol2sphPart& sum = s.summary;
            sum.solid_part = std::stoll(part.id);
            sum.span = part.span;
            sum.property = prop->id;
            sum.ndir = static_cast<int>(std::clamp<long long>(prop->ndir.value, -1, 1000));
            sum.sph_part = prop->sph_part.value;
            sum.solid_density = density_of(part);
            if (sum.ndir < 1 || sum.ndir > 9)
                sum.notes.push_back(fmt::format("Ndir {} is outside 1-9: no particles generated", prop->ndir.value));
            const model::Part* sph = m_.part(std::to_string(sum.sph_part));
            if (!sph) {
                sum.sph_density = sum.solid_density;
                sum.notes.push_back(
                    fmt::format("SPH part {} is not defined: the solid's density is used", sum.sph_part));
            } else {
                sum.sph_density = density_of(*sph);
                for (const auto& p : f_.sph_properties)
                    if (std::to_string(p.id) == sph->section.value) sum.sph_h = p.h.value, sum.sph_h_1d = p.h_1d.value;
            }
            if (sum.sph_density != sum.solid_density)
                sum.notes.push_back(
                    fmt::format("the SPH part's density {:.6g} differs from the solid's {:.6g}: the "
                                "particles do not carry the element mass",
                                sum.sph_density, sum.solid_density));
            parts.push_back(std::move(s));
        }
        return parts;
    }

    double density_of(const model::Part& part) const {
        const model::Material* mat = m_.material(part.material.value);
        return mat ? mat->density.value : 0.0;
    }

    void issue(PartSetup& part, const model::RadiossSolids& solids, std::size_t e, std::string message) {
        ++part.summary.skipped;
        out_.issues.push_back({solids.id[e], solids.line[e], std::move(message)});
    }

    void elements(PartSetup& part, const model::RadiossSolids& solids, bool brick_list) {
        const int per = solids.nodes_per_element;
        const char* kind = brick_list ? "/BRICK" : "/TETRA4";
        for (std::size_t e = 0; e < solids.size(); ++e) {
            if (solids.part[e] != part.summary.solid_part) continue;
            std::vector<Vec> at;
            std::vector<long long> distinct;
            bool missing = false;
            for (int k = 0; k < per; ++k) {
                const long long id = solids.nodes[e * per + k];
                const auto index = id > 0 ? nodes_.find(id) : std::nullopt;
                if (!index) {
                    issue(part, solids, e,
                          id > 0 ? fmt::format("{} {}: node {} is not defined", kind, solids.id[e], id)
                                 : fmt::format("{} {}: node {} of {} is missing", kind, solids.id[e], k + 1, per));
                    missing = true;
                    break;
                }
                at.emplace_back(m_.nodes.x[*index], m_.nodes.y[*index], m_.nodes.z[*index]);
                if (std::find(distinct.begin(), distinct.end(), id) == distinct.end()) distinct.push_back(id);
            }
            if (missing) continue;
            if (distinct.size() < 4) {
                issue(part, solids, e,
                      fmt::format("{} {} has {} distinct nodes: no volume", kind, solids.id[e], distinct.size()));
            } else if (distinct.size() == 4) {
                std::array<Vec, 4> corners;
                std::size_t c = 0;
                std::vector<long long> seen;
                for (int k = 0; k < per; ++k) {
                    const long long id = solids.nodes[e * per + k];
                    if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
                    seen.push_back(id);
                    corners[c++] = at[k];
                }
                tetra(part, solids, e, corners, kind);
            } else {
                std::array<Vec, 8> corners;
                std::copy_n(at.begin(), 8, corners.begin());
                brick(part, solids, e, corners);
            }
        }
    }

    void add_particle(const PartSetup& part, long long element, const Vec& x, double volume, double starter_volume) {
        Sol2sphParticles& p = out_.particles;
        p.x.push_back(x[0]), p.y.push_back(x[1]), p.z.push_back(x[2]);
        p.volume.push_back(volume);
        p.mass.push_back(part.summary.sph_density * volume);
        p.mass_starter.push_back(part.summary.sph_density * starter_volume);
        p.element.push_back(element);
        p.solid_part.push_back(part.summary.solid_part);
        p.sph_part.push_back(part.summary.sph_part);
    }

    void count_element(PartSetup& part, double volume, std::size_t count, double particle_mass, double starter_mass) {
        Sol2sphPart& s = part.summary;
        s.element_mass += s.solid_density * volume;
        s.particle_mass += particle_mass;
        s.starter_mass += starter_mass;
        s.particles += count;
        part.pitches.push_back(std::cbrt(volume / static_cast<double>(count)));
    }

    // A tetra: every particle gets V / count (soltosph.F, SOLTOSPHV4); the node order does not
    // matter since the layout is symmetric in the four corners (the starter reorders a negative one).
    void tetra(PartSetup& part, const model::RadiossSolids& solids, std::size_t e, const std::array<Vec, 4>& p,
               const char* kind) {
        const double volume = std::abs(tetra_volume(p));
        if (!(volume > 0)) {
            issue(part, solids, e, fmt::format("{} {}: its four corners are coplanar (volume 0)", kind, solids.id[e]));
            return;
        }
        const auto layout = sol2sph_tetra_barycentrics(part.summary.ndir);
        const double share = volume / static_cast<double>(layout.size());
        double mass = 0;
        for (const auto& l : layout) {
            Vec x = Vec::Zero();
            for (int a = 0; a < 4; ++a) x += l[a] * p[a];
            add_particle(part, solids.id[e], x, share, share);
            mass += out_.particles.mass.back();
        }
        ++part.summary.tetras;
        count_element(part, volume, layout.size(), mass, mass);
    }

    // A brick: Ndir^3 sub-cell centres mapped through the shape functions (soltosph.F, SOLTOSPHX8).
    void brick(PartSetup& part, const model::RadiossSolids& solids, std::size_t e, const std::array<Vec, 8>& p) {
        const int n = part.summary.ndir;
        const double volume = brick_volume(p, -1, 1, -1, 1, -1, 1);
        const auto centre = sol2sph_brick_abscissae(n);
        const double half = 1.0 / n, weight = 8.0 / (n * n * n);
        struct Sub {
            Vec x;
            double volume, starter;
        };
        std::vector<Sub> subs;
        for (double r : centre)
            for (double s : centre)
                for (double t : centre) {
                    const double starter = weight * brick_jacobian(p, r, s, t);
                    const double exact = brick_volume(p, r - half, r + half, s - half, s + half, t - half, t + half);
                    if (!(starter > 0) || !(exact > 0)) {
                        issue(part, solids, e,
                              fmt::format("/BRICK {}: a sub-cell has a non-positive volume ({:.4g}; the starter stops "
                                          "with error 1038): distorted, or nodes numbered the other way round",
                                          solids.id[e], std::min(starter, exact)));
                        return;
                    }
                    subs.push_back({brick_point(p, r, s, t), exact, starter});
                }
        double mass = 0, starter_mass = 0;
        for (const Sub& sub : subs) {
            add_particle(part, solids.id[e], sub.x, sub.volume, sub.starter);
            mass += out_.particles.mass.back();
            starter_mass += out_.particles.mass_starter.back();
        }
        ++part.summary.bricks;
        count_element(part, volume, subs.size(), mass, starter_mass);
    }

    const model::Model& m_;
    const model::RadiossFacts& f_;
    model::IdIndex nodes_;
    Sol2sph out_;
};

double relative(double value, double reference) {
    return reference != 0 ? (value - reference) / reference : (value == 0 ? 0.0 : 1.0);
}

}  // namespace

std::size_t sol2sph_brick_count(int ndir) { return ndir > 0 ? static_cast<std::size_t>(ndir) * ndir * ndir : 0; }

std::size_t sol2sph_tetra_count(int ndir) {
    return ndir > 0 ? static_cast<std::size_t>(ndir) * (ndir + 1) * (ndir + 2) / 6 : 0;
}

std::vector<double> sol2sph_brick_abscissae(int ndir) {
    std::vector<double> out;
    for (int k = 1; k <= ndir; ++k) out.push_back(static_cast<double>(2 * k - 1) / ndir - 1.0);
    return out;
}

// All k_a >= 1 with k_1 + k_2 + k_3 + k_4 = N + 3, lambda_a = (2 k_a - 1) / (2 (N + 1)) (§9.2; the
// loops of SOLTOSPHX4: IR, IS, IT and the fourth coordinate 1 - the others).
std::vector<std::array<double, 4>> sol2sph_tetra_barycentrics(int ndir) {
    std::vector<std::array<double, 4>> out;
    const double scale = 2.0 * (ndir + 1);
    for (int a = 1; a <= ndir; ++a)
        for (int b = 1; b <= ndir + 1 - a; ++b)
            for (int c = 1; c <= ndir + 2 - a - b; ++c) {
                const int d = ndir + 3 - a - b - c;
                out.push_back({(2 * a - 1) / scale, (2 * b - 1) / scale, (2 * c - 1) / scale, (2 * d - 1) / scale});
            }
    return out;
}

double Sol2sphPart::relative_difference() const { return relative(particle_mass, element_mass); }
double Sol2sphPart::starter_relative_difference() const { return relative(starter_mass, element_mass); }

Sol2sph generate_sol2sph(const model::Model& model) {
    if (!model.radioss) return {};
    return Generator(model).run();
}

}  // namespace sphdeck::preproc
