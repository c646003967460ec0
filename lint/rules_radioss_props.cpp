// RAD020, RAD022-RAD024, RAD026-RAD029: /PROP/SPH values, /SPHCEL masses, /SPHGLO, the engine's
// time-step scales and the analysis dimension (radioss-format.md §5.1-§5.4, §5.7, §8).
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

#include "lint/rules_radioss.hpp"

namespace sphdeck::lint::radioss {
namespace {

using model::RadiossSphProperty;

// RAD023: mp <= 0 on a property some particle takes its mass from (Type-0 cells without MASS,
// reserve particles of inlets); the starter warns (138) and uses 1.0.
void check_mass(RuleContext& c, const RadiossSphProperty& p) {
    if (p.mp.written > 0) return;
    const model::Particles& particles = c.model.particles;
    const model::RadiossFacts& f = *c.model.radioss;
    std::size_t users = 0;
    std::set<long long> parts;
    for (const model::Part* part : parts_using(c.model, p.id)) parts.insert(std::stoll(part->id));
    for (std::size_t i = 0; i < particles.size(); ++i)
        users += f.cells.from_property[i] && parts.count(particles.part[i]);
    std::size_t reserves = 0;
    for (const auto& r : f.reserves) reserves += parts.count(r.part);
    if (!users && !reserves) return;
    std::string who = users == 1 ? std::string("1 particle takes its mass from it")
                      : users    ? fmt::format("{} particles take their mass from it", users)
                                 : "the reserve particles of its inlet take their mass from it";
    c.report("RAD023", p.mp.span,
             fmt::format("mp {:g} on /PROP/SPH {}: {}; the starter replaces it by 1.0 (warning 138)", p.mp.written,
                         p.id, who));
}

// RAD024: qa or qb written as 0 are silently the defaults 2 and 1.
void check_viscosity(RuleContext& c, const RadiossSphProperty& p) {
    if (p.qa.explicit_value && p.qa.written == 0)
        c.report("RAD024", p.qa.span,
                 "qa 0 is read as the default 2.0, not as no quadratic viscosity; write a tiny value (1E-30) to "
                 "switch it off");
    if (p.qb.explicit_value && p.qb.written == 0)
        c.report("RAD024", p.qb.span,
                 "qb 0 is read as the default 1.0, not as no linear viscosity; write a tiny value (1E-30) to switch "
                 "it off");
}

// RAD027, RAD028: values the engine does not know, without a message.
void check_modes(RuleContext& c, const RadiossSphProperty& p) {
    const long long h1d = p.h_1d.value, order = p.order.value;
    if (h1d < 0 || h1d > 3)
        c.report("RAD027", p.h_1d.span,
                 fmt::format("h_1D {} is not 0, 1, 2 or 3: the engine silently treats it as 0 (3D dilatation)", h1d));
    if (order < -1 || order > 1)
        c.report("RAD028", p.order.span,
                 fmt::format("Order {} is not -1, 0 or 1: the engine puts these particles in no correction list",
                             order));
}

// RAD026: /SPHCEL Type 1 (mass) or 2 (volume) with MASS <= 0, one finding per part and type.
void check_cells(RuleContext& c) {
    const model::Particles& p = c.model.particles;
    const model::RadiossCells& cells = c.model.radioss->cells;
    std::map<std::pair<long long, int>, Group> bad;
    for (std::size_t i = 0; i < p.size(); ++i)
        if ((cells.type[i] == 1 || cells.type[i] == 2) && cells.mass[i] <= 0) bad[{p.part[i], cells.type[i]}].add(i);
    for (const auto& [key, g] : bad) {
        const std::size_t i = g.first.front();
        const char* what = key.second == 1 ? "mass" : "volume";
        std::string who = g.count == 1 ? fmt::format("particle {} of part {}", p.node[i], key.first)
                                       : fmt::format("{} particles of part {} ({})", g.count, key.first, g.ids(p));
        c.report("RAD026", cell_field_span(c, i, "MASS"),
                 fmt::format("MASS {:g} with Type {} ({}) on {}: the particle gets no {} and a zero smoothing length "
                             "(engine error 174); expected MASS > 0",
                             cells.mass[i], key.second, what, who, what));
    }
}

// RAD022 and the duplicate /SPHGLO (DK018).
void check_global(RuleContext& c) {
    const model::RadiossSphGlobal& g = c.model.radioss->sph_global;
    for (const grammar::Span& again : g.ignored)
        c.report("DK018", again, "/SPHGLO appears more than once; the starter uses the first one only")
            .notes.push_back({g.span, "first defined here"});
    if (!g.present || !g.alpha_sort.explicit_value) return;
    const double a = g.alpha_sort.written;
    if (a == 0)
        c.report("RAD022", g.alpha_sort.span, "Alpha_sort written as 0 silently means the default 0.25");
    else if (a < 0 || a > 0.5)
        c.report("RAD022", g.alpha_sort.span,
                 fmt::format("Alpha_sort {:g} is outside (0, 0.5]: the documented maximum is 0.5, default 0.25", a));
}

// RAD020: the documentation's time-step scales for SPH, 0.3 (particle) and 0.67 (nodal).
void check_scales(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    bool sph = c.model.particles.size() > 0;
    for (const auto& p : f.solid_properties) sph |= p.sol2sph();
    if (!sph) return;
    const model::RadiossDt* global = f.time_step(model::DtKind::Global);
    const double global_scale = global && global->dtsca.value > 0 ? global->dtsca.value : 0.9;
    for (const auto& d : f.time_steps) {
        if (d.in_starter || (d.kind != model::DtKind::SphCell && d.kind != model::DtKind::Nodal)) continue;
        const bool particle = d.kind == model::DtKind::SphCell;
        const double advised = particle ? 0.3 : 0.67;
        const double scale = d.dtsca.value > 0 ? d.dtsca.value : global_scale;
        if (std::abs(scale - advised) < 1e-9) continue;
        const std::string value = d.dtsca.value > 0 ? fmt::format("DTsca {:g}", scale)
                                                    : fmt::format("DTsca 0 (the global factor {:g})", scale);
        c.report("RAD020", d.dtsca.explicit_value ? d.dtsca.span : d.span,
                 fmt::format("{} on {}: the documentation recommends {:g} for the {} time step", value,
                             particle ? "/DT/SPHCEL" : "/DT/NODA", advised, particle ? "particle" : "nodal"));
    }
}

// RAD029: a 2D analysis (/ANALY N2D3D 1 or 2) with SPH particles.
void check_dimension(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    bool sph = c.model.particles.size() > 0;
    for (const auto& p : f.solid_properties) sph |= p.sol2sph();
    if (f.analysis == 0 || !sph) return;
    c.report("RAD029", f.analysis_span,
             fmt::format("/ANALY N2D3D {} ({}) with SPH particles: Radioss SPH is 3D only", f.analysis,
                         f.analysis == 1   ? "axisymmetric"
                         : f.analysis == 2 ? "plane strain"
                                           : "not 3D"));
}

}  // namespace

void check_properties(RuleContext& c) {
    for (const RadiossSphProperty& p : c.model.radioss->sph_properties) {
        check_mass(c, p);
        check_viscosity(c, p);
        check_modes(c, p);
    }
    check_cells(c);
    check_global(c);
    check_scales(c);
    check_dimension(c);
}

}  // namespace sphdeck::lint::radioss
