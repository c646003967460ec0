// SPH090, SPH113-SPH115, SPH118: rules on the preview's geometry (spacing, h0, neighbour counts).
// The preview is computed once per check, here; rules never measure geometry themselves.
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <memory>

#include "lint/rules.hpp"
#include "preproc/preview.hpp"
#include "preproc/smoothing_length.hpp"

namespace sphdeck::lint {
namespace {

using preproc::PartPreview;
using preproc::Preview;

constexpr std::size_t preview_max_listed = 20;  // findings per rule and part: the rest are the same mistake

// The first particle of part q (model order), or the size when none.
std::size_t first_particle(const Preview& p, std::size_t q) {
    for (std::size_t i = 0; i < p.particles.part.size(); ++i)
        if (p.particles.part[i] == q && p.particles.located[i]) return i;
    return p.particles.part.size();
}

// The mass particle i carries: the preview's, or computed as the preview does when it kept no
// per-particle arrays.
double particle_mass(const RuleContext& c, const Preview& p, std::size_t i) {
    if (!p.particles.mass.empty()) return p.particles.mass[i];
    return preproc::particle_mass(c.model.particles.mass[i], c.model.particles.volume[i] != 0,
                                  p.parts[p.particles.part[i]].density);
}

// Particle i's position (it is located): the preview's, or its node's in the model.
std::array<double, 3> particle_position(const RuleContext& c, const Preview& p, std::size_t i) {
    if (!p.particles.x.empty()) return {p.particles.x[i], p.particles.y[i], p.particles.z[i]};
    const auto at = c.node_index().find(c.model.particles.node[i]);
    if (!at) return {0.0, 0.0, 0.0};
    return {c.model.nodes.x[*at], c.model.nodes.y[*at], c.model.nodes.z[*at]};
}

// SPH090: MEMORY against the largest estimated neighbour count.
void check_memory(RuleContext& c, const Preview& p) {
    const auto& memory = c.model.controls.sph.memory;
    const PartPreview* worst = nullptr;
    for (const PartPreview& part : p.parts)
        if (!worst || part.neighbours.max > worst->neighbours.max) worst = &part;
    if (!worst || memory.value == 0) return;
    const auto largest = static_cast<long long>(worst->neighbours.max);
    const long long cap = std::llabs(memory.value);
    if (largest <= cap) return;
    if (memory.value < 0)
        c.report("SPH090", memory.span,
                 fmt::format("MEMORY {} fixes the neighbour arrays at {} per particle, but particles of part {} have "
                             "up to {} neighbours within the kernel support {:.4g}",
                             memory.value, cap, worst->part, largest, worst->support));
    else
        c.report(
            "SPH090", diag::Severity::Info, memory.span,
            fmt::format(
                "MEMORY {} is below the {} neighbours estimated for part {} (within the kernel support {:.4g}); the "
                "arrays will grow during the run",
                memory.value, largest, worst->part, worst->support));
}

// SPH113: particle mass against rho * spacing^d, reported at the part's first particle whose mass
// is (closest to) the median one.
void check_mass_spacing(RuleContext& c, const Preview& p) {
    if (c.model.controls.sph.idim.value == model::Dimension::Axisymmetric) return;  // mass per radian: not checked
    const std::size_t n = p.particles.part.size();
    std::vector<double> ratio(p.parts.size(), 1.0);
    std::vector<std::size_t> at(p.parts.size(), n);
    bool any = false;
    for (std::size_t q = 0; q < p.parts.size(); ++q) {
        const PartPreview& part = p.parts[q];
        if (part.density <= 0 || part.spacing <= 0 || part.mass_median <= 0) continue;
        ratio[q] = part.mass_median / (part.density * std::pow(part.spacing, p.dimension));
        any = any || ratio[q] > 2.0 || ratio[q] < 0.5;
    }
    if (!any) return;
    // The density field as the deck names it: RO of *MAT_, RHO_I of /MAT.
    const char* density_name = c.model.radioss ? "RHO_I" : "RO";
    std::vector<double> closest(p.parts.size(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t q = p.particles.part[i];
        if (ratio[q] <= 2.0 && ratio[q] >= 0.5) continue;
        const double off = std::abs(particle_mass(c, p, i) - p.parts[q].mass_median);
        if (at[q] == n || off < closest[q]) at[q] = i, closest[q] = off;
    }
    for (std::size_t q = 0; q < p.parts.size(); ++q) {
        if (at[q] == n) continue;
        const PartPreview& part = p.parts[q];
        c.report("SPH113", c.particle_span(at[q]),
                 fmt::format("particle mass {:.4g} is {:.3g} times rho * spacing^{} = {:.4g} (part {}: {} {:.4g}, "
                             "spacing {:.4g}); expected within a factor 2, a unit mistake?",
                             part.mass_median, ratio[q], p.dimension, part.mass_median / ratio[q], part.part,
                             density_name, part.density, part.spacing));
    }
}

// SPH114: particles at the same position.
void check_coincident(RuleContext& c, const Preview& p) {
    const auto& ids = c.model.particles.node;
    for (std::size_t k = 0; k < p.coincident.size() && k < preview_max_listed; ++k) {
        const auto [a, b] = p.coincident[k];
        const auto [x, y, z] = particle_position(c, p, b);
        std::string total =
            k == 0 && p.coincident_pairs > 1 ? fmt::format(" ({} pairs in all)", p.coincident_pairs) : "";
        c.report("SPH114", c.particle_span(b),
                 fmt::format("particle {} is at the same position as particle {} ({:.6g}, {:.6g}, {:.6g}){}", ids[b],
                             ids[a], x, y, z, total))
            .notes.push_back({c.particle_span(a), fmt::format("particle {} is here", ids[a])});
    }
}

// The particles far from the rest of their part, the first few of each part (one pass over the
// particles): a fact of the preview alone, kept under it (lint/bulk_facts.hpp), so the decks of a run
// that share a preview share this pass too.
struct StrayParticles {
    std::vector<std::size_t> particles;
};

StrayParticles stray_particles(const Preview& p) {
    const auto& pp = p.particles;
    StrayParticles out;
    std::vector<std::size_t> listed(p.parts.size(), 0);
    for (std::size_t i = 0; i < pp.part.size(); ++i) {
        const std::uint32_t q = pp.part[i];
        const PartPreview& part = p.parts[q];
        if (part.spacing <= 0 || !pp.located[i] || !(pp.nn_distance[i] > 3.0 * part.spacing) ||
            listed[q] == preview_max_listed)
            continue;
        ++listed[q];
        out.particles.push_back(i);
    }
    return out;
}

// SPH115: a particle far from the rest of its part.
void check_stray(RuleContext& c, const Preview& p) {
    const auto& pp = p.particles;
    const auto stray = c.bulk_facts().get<StrayParticles>([&] { return stray_particles(p); }, c.preview);
    for (const std::size_t i : stray->particles) {
        const PartPreview& part = p.parts[pp.part[i]];
        const bool sets_h0 =
            !part.sphini_given && part.ini != model::IniMode::FromMass && pp.nn_distance[i] == part.nn_distance.max;
        const std::string effect = sets_h0 ? fmt::format("; it sets h0 = {:.4g} for the whole part", part.h0) : "";
        c.report("SPH115", c.particle_span(i),
                 fmt::format("particle {} is {:.4g} from its nearest particle of part {}, {:.3g} times the part's "
                             "median spacing {:.4g}{}",
                             c.model.particles.node[i], pp.nn_distance[i], part.part, pp.nn_distance[i] / part.spacing,
                             part.spacing, effect));
    }
}

// Where a part's smoothing length is set. LS-DYNA: SPHINI when it applies, else CSLH. Radioss has
// no CSLH: the /PROP/SPH h field (the model's section keeps no span when h is 0), or the
// property's header when h is left blank.
grammar::Span smoothing_span(const RuleContext& c, const model::Section& section, bool sphini_given) {
    if (c.model.radioss) {
        for (const model::RadiossSphProperty& p : c.model.radioss->sph_properties)
            if (std::to_string(p.id) == section.id) return p.h.explicit_value ? p.h.span : p.span;
    }
    return sphini_given ? section.sphini.span : section.cslh.span;
}

// SPH118: too few neighbours per particle. Two estimates must agree: the part's median count
// (free-surface corners aside) and the count of an interior particle of a uniform fill at the
// part's spacing, pi r^2 in 2D and 4/3 pi r^3 in 3D with r = support / spacing. The second keeps
// small parts quiet, where every particle is near a surface and sees fewer than an interior one.
void check_few_neighbours(RuleContext& c, const Preview& p) {
    const double needed = p.dimension == 2 ? 8 : 20;
    constexpr double pi = 3.14159265358979323846;
    for (std::size_t q = 0; q < p.parts.size(); ++q) {
        const PartPreview& part = p.parts[q];
        if (part.h0 <= 0 || part.spacing <= 0 || part.particles < 2 || part.neighbours.median >= needed) continue;
        const double r = part.support / part.spacing;
        const double interior = p.dimension == 2 ? pi * r * r : 4.0 / 3.0 * pi * r * r * r;
        if (interior >= needed) continue;
        grammar::Span where;
        const model::Part* def = c.model.part(std::to_string(part.part));
        const model::Section* section = def ? c.definitions().section_of(*def) : nullptr;
        if (section && section->sph)
            where = smoothing_span(c, *section, part.sphini_given);
        else if (def)
            where = def->span;
        else if (std::size_t i = first_particle(p, q); i < p.particles.part.size())
            where = c.particle_span(i);
        c.report("SPH118", where,
                 fmt::format("part {}: about {:.3g} neighbours per particle (median) within the kernel support "
                             "{:.4g} (h0 {:.4g}, spacing {:.4g}); at least {} are needed in {}D",
                             part.part, part.neighbours.median, part.support, part.h0, part.spacing, needed,
                             p.dimension));
    }
}

}  // namespace

// The rules need the per-particle arrays of part, location and nearest distance only; the others
// (positions, masses, h, counts) are made when the preview is kept for `sphdeck smooth`.
std::shared_ptr<const Preview> compute_rules_preview(const model::Model& model, bool particle_arrays,
                                                     bool neighbour_counts) {
    if (model.particles.size() == 0) return nullptr;
    preproc::PreviewOptions options;
    options.particle_arrays = particle_arrays;
    options.neighbour_counts = neighbour_counts;
    return std::make_shared<const Preview>(preproc::compute_preview(model, options));
}

void check_preview(RuleContext& c) {
    if (!c.preview) return;  // no particles
    const Preview& p = *c.preview;
    check_memory(c, p);
    check_mass_spacing(c, p);
    check_coincident(c, p);
    check_stray(c, p);
    check_few_neighbours(c, p);
}

}  // namespace sphdeck::lint
