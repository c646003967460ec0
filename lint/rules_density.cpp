// SPH119: a material density the solver rejects. LS-DYNA: RO <= 0 (or blank) of a material that
// an SPH, solid or shell part uses, since their mass and time step come from it. OpenRadioss: RHO_I <= 0 of any /MAT
// whose law the starter checks (hm_read_mat.F90, message 683), used or not.
#include <fmt/format.h>

#include <set>
#include <string_view>
#include <vector>

#include "lint/rules.hpp"
#include "lint/rules_control_sph.hpp"

namespace sphdeck::lint {
namespace {

bool density_starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

std::string density_written(const model::Material& m, std::string_view name) {
    if (!m.density.explicit_value) return fmt::format("{} blank (read as 0)", name);
    return fmt::format("{} {:g}", name, m.density.value);
}

// The elements whose mass and time step come from RO (element mass RO times volume, sound speed from
// the stiffness over RO): solids, the 2D solids of *SECTION_SHELL (ELFORM 12 plane stress, 13 plane
// strain, 14 and 15 axisymmetric), shells, thick shells. Empty for the others: beams (discrete beams
// and spot welds may take their mass from elsewhere), springs, seatbelts.
std::string_view element_kind(const model::Section& section) {
    if (density_starts_with(section.keyword, "*SECTION_SOLID")) return "solid";
    if (density_starts_with(section.keyword, "*SECTION_SHELL"))
        return section.shell_form >= 12 && section.shell_form <= 15 ? "solid" : "shell";
    if (density_starts_with(section.keyword, "*SECTION_TSHELL")) return "thick shell";
    return {};
}

bool rigid(const model::Material& m) { return m.keyword == "*MAT_RIGID" || m.keyword == "*MAT_020"; }

void check_lsdyna_densities(RuleContext& c) {
    const model::Model& m = c.model;
    std::set<const model::Part*> sph;
    for (const model::Part* p : control_sph::sph_parts(c)) sph.insert(p);
    std::set<const model::Material*> reported;
    for (const model::Part& part : m.parts) {
        const model::Section* section = c.definitions().section_of(part);
        const std::string_view kind = sph.count(&part) ? "SPH" : section ? element_kind(*section) : "";
        if (kind.empty()) continue;
        const model::Material* mat = c.definitions().material_of(part);
        if (!mat || !mat->has_density || mat->density.value > 0 || reported.count(mat)) continue;
        if (rigid(*mat) && part.inertia) continue;  // *PART_INERTIA gives the mass itself
        reported.insert(mat);
        auto& d = c.report("SPH119", mat->density.span,
                           fmt::format("{} of {} {} used by {} part {}: its {} have no mass; expected a density > 0",
                                       density_written(*mat, "RO"), mat->keyword, mat->id, kind, part.id,
                                       kind == "SPH" ? "particles" : "elements"));
        d.notes.push_back({part.material.span, fmt::format("part {} uses material {} here", part.id, mat->id)});
    }
}

void check_radioss_densities(RuleContext& c) {
    for (const model::Material& mat : c.model.materials) {
        if (!mat.has_density || mat.density.value > 0) continue;
        c.report("SPH119", mat.density.span,
                 fmt::format("{} of {} material {}: the starter stops (error 683, DENSITY); expected a density > 0",
                             density_written(mat, "RHO_I"), mat.keyword, mat.id));
    }
}

}  // namespace

void check_densities(RuleContext& c) {
    if (c.model.radioss)
        check_radioss_densities(c);
    else
        check_lsdyna_densities(c);
}

}  // namespace sphdeck::lint
