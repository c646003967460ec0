// SPH120-SPH121: what an LS-DYNA SPH deck runs as when it does not say. SPH120: no *CONTROL_SPH,
// so LS-DYNA's defaults apply (3D among them). SPH121: every particle in one plane of a 3D run, the
// shape of a 2D model whose IDIM 2 is missing (*CONTROL_SPH IDIM; lsdyna-sph-cards.md §1).
#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "lint/rules.hpp"

namespace sphdeck::lint {
namespace {

bool dimension_starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// The first keyword that makes a deck an SPH deck: particles, an SPH section, a particle generator.
const grammar::Block* first_sph_keyword(const grammar::RawDeck& deck) {
    for (const grammar::Block& b : deck.blocks)
        if (dimension_starts_with(b.keyword, "*ELEMENT_SPH") || dimension_starts_with(b.keyword, "*SECTION_SPH") ||
            dimension_starts_with(b.keyword, "*DEFINE_SPH_"))
            return &b;
    return nullptr;
}

void check_missing_control_sph(RuleContext& c) {
    if (c.model.controls.sph.present) return;
    const grammar::Block* sph = first_sph_keyword(c.deck);
    if (!sph) return;
    c.report("SPH120", sph->span,
             fmt::format("SPH deck without *CONTROL_SPH: LS-DYNA's defaults apply (3D as IDIM 3, FORM 0, INI 0 "
                         "bucket sort, NCBS 1, MEMORY 150, START 0, MAXV 1e15); expected a *CONTROL_SPH that "
                         "states them"));
}

// The extent of the particles that have a node, their count and the first of them: a fact of the
// particles alone (lint/bulk_facts.hpp).
struct ParticleCloud {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    std::size_t count = 0, first = 0;
};

ParticleCloud particle_cloud(const RuleContext& c) {
    const model::Nodes& n = c.model.nodes;
    const ParticleNodes& node_of = c.particle_nodes();
    ParticleCloud out;
    for (std::size_t i = 0; i < node_of.size(); ++i) {
        const std::uint32_t k = node_of[i];
        if (k == RuleContext::no_node) continue;  // REF001
        if (out.count++ == 0) out.first = i;
        const double x[3] = {n.x[k], n.y[k], n.z[k]};
        for (int a = 0; a < 3; ++a) out.lo[a] = std::min(out.lo[a], x[a]), out.hi[a] = std::max(out.hi[a], x[a]);
    }
    return out;
}

// Every particle within 1e-6 of the cloud's extent of one coordinate value: a plane (or a line).
void check_planar_3d(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    if (sph.present && sph.idim.value != model::Dimension::ThreeD && sph.idim.value != model::Dimension::Unset) return;
    const auto cloud = c.bulk_facts().get<ParticleCloud>([&] { return particle_cloud(c); });
    const double* lo = cloud->lo;
    const double* hi = cloud->hi;
    const std::size_t count = cloud->count, first = cloud->first;
    if (count < 3) return;
    double extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
    if (extent <= 0) return;  // all at one point: SPH115 and the preview speak of that
    int flat = -1;
    for (int a : {2, 1, 0})
        if (flat < 0 && hi[a] - lo[a] <= 1e-6 * extent) flat = a;
    if (flat < 0) return;
    const char axis = static_cast<char>('x' + flat);
    const double at = 0.5 * (lo[flat] + hi[flat]);
    const std::string run = !sph.present              ? "a 3D run (no *CONTROL_SPH)"
                            : sph.idim.explicit_value ? "a 3D run (IDIM 3)"
                                                      : "a 3D run (IDIM blank)";
    const std::string expected = flat == 2 ? "IDIM 2 (plane strain) or -2 (axisymmetric) in *CONTROL_SPH"
                                           : "IDIM 2 with the model in the x-y plane (z = 0)";
    const grammar::Span where = sph.present ? sph.idim.span : c.particle_span(first);
    // IDIM 3 written: the author said 3D, and a sheet one particle thick is a legal 3D model (warning).
    // 3D by default only (no *CONTROL_SPH, IDIM blank): nothing but the default says 3D while the
    // particles say 2D (error).
    const bool said_3d = sph.present && sph.idim.explicit_value && sph.idim.value == model::Dimension::ThreeD;
    auto& d = c.report("SPH121", said_3d ? diag::Severity::Warning : diag::Severity::Error, where,
                       fmt::format("all {} particles lie in the plane {} = {:g} in {}: a 2D model without IDIM 2? "
                                   "expected {}, or particles spread in {}",
                                   count, axis, at, run, expected, axis));
    if (sph.present) d.notes.push_back({c.particle_span(first), fmt::format("first particle, at {} = {:g}", axis, at)});
}

}  // namespace

void check_sph_dimension(RuleContext& c) {
    if (c.model.radioss) return;  // OpenRadioss SPH is 3D only and has no *CONTROL_SPH
    check_missing_control_sph(c);
    check_planar_3d(c);
}

}  // namespace sphdeck::lint
