// The smoothing-length preview as JSON (docs/json.md): one writer for `sphdeck smooth --format json` and the
// MCP tool smoothing_preview, so both carry the same fields.
#include "preproc/preview_json.hpp"

namespace sphdeck::preproc {
namespace {

nlohmann::ordered_json stats_json(const Stats& s) { return {{"min", s.min}, {"median", s.median}, {"max", s.max}}; }

// The Radioss additions (docs/json.md, docs/radioss.md): one object per part.
nlohmann::ordered_json radioss_part_json(const RadiossPartPreview& r) {
    return {{"property", r.property},
            {"mp", r.mp},
            {"property_h", r.property_h},
            {"h_1d", r.h_1d},
            {"hcst", r.hcst},
            {"h_rule", r.h_rule},
            {"h_evolution", r.h_evolution},
            {"h", {{"min", r.h_smallest}, {"median", r.h_median}, {"max", r.h_largest}}},
            {"cells",
             {{"from_property", r.cells_from_property},
              {"with_mass", r.cells_with_mass},
              {"with_volume", r.cells_with_volume}}},
            {"mass_before_symmetry", r.mass_before},
            {"mass_after_symmetry", r.mass_after},
            {"on_planes", r.on_planes},
            {"ghosts", r.ghosts},
            {"ghosts_coded", r.ghosts_coded},
            {"qa", r.qa},
            {"qb", r.qb},
            {"dt_particle", r.dt_particle},
            {"dt_nodal", r.dt_nodal}};
}

}  // namespace

std::vector<std::string> split_notes(const std::string& notes) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < notes.size()) {
        std::size_t end = notes.find("; ", start);
        if (end == std::string::npos) end = notes.size();
        out.push_back(notes.substr(start, end - start));
        start = end + 2;
    }
    return out;
}

nlohmann::ordered_json part_preview_json(const PartPreview& pv) {
    nlohmann::ordered_json part = {{"part", pv.part},
                                   {"particles", pv.particles},
                                   {"mass_total", pv.mass_total},
                                   {"mass_median", pv.mass_median},
                                   {"density", pv.density},
                                   {"spacing", pv.spacing},
                                   {"h0", pv.h0},
                                   {"h_min", pv.h_min},
                                   {"h_max", pv.h_max},
                                   {"support", pv.support},
                                   {"nn_distance", stats_json(pv.nn_distance)},
                                   {"neighbours", stats_json(pv.neighbours)},
                                   {"sound_speed", pv.sound_speed},
                                   {"sound_source", pv.sound_source},
                                   {"dt_estimate", pv.dt_estimate},
                                   {"dt_radioss", pv.dt_radioss},
                                   {"ini", static_cast<int>(pv.ini)},
                                   {"sphini_given", pv.sphini_given},
                                   {"notes", split_notes(pv.notes)}};
    if (pv.radioss) part["radioss"] = radioss_part_json(*pv.radioss);
    return part;
}

nlohmann::ordered_json radioss_preview_json(const RadiossPreview& r) {
    nlohmann::ordered_json planes = nlohmann::ordered_json::array();
    for (const RadiossPlanePreview& p : r.planes)
        planes.push_back({{"id", p.id},
                          {"type", p.type},
                          {"origin", p.origin},
                          {"normal", p.normal},
                          {"on_plane", p.on_plane},
                          {"ghosts", p.ghosts},
                          {"ghosts_coded", p.ghosts_coded}});
    return {{"alpha_sort", r.alpha_sort},
            {"h_max", r.h_max},
            {"dt_scale_particle", r.dt_scale_particle},
            {"dt_scale_nodal", r.dt_scale_nodal},
            {"nodal", r.nodal},
            {"engine_deck", r.engine_deck},
            {"planes", std::move(planes)},
            {"unknown_planes", r.unknown_planes}};
}

}  // namespace sphdeck::preproc
