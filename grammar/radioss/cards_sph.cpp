// SPH cards of the starter and the engine (radioss-format.md §5.2-§5.7).
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

void add_sph_keywords(std::vector<KeywordSpec>& out) {
    out.push_back({.name = "/SPHCEL",
                   .title = false,
                   .summary = "SPH particles of a part: node, Type (1 mass, 2 volume), MASS",
                   .formats = {{0, {repeated({I("node_ID"), I("Type"), R("MASS")})}}}});
    // CFG radioss2017/CARDS/sphglo.cfg: `%20lg%10d%10d%10d%10d` (2017, Isol2sph added),
    // `%20lg%10d%10d%10d` (120, Nneigh added), `%20lg%10d%10d` (51; no V4 format, so V4 decks
    // read the 51 cells at their own widths).
    out.push_back({.name = "/SPHGLO",
                   .title = false,
                   .summary = "global SPH parameters: neighbour search margin and counts",
                   .formats = {{2017, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh"), I("Nneigh"), I("Isol2sph")})}},
                               {120, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh"), I("Nneigh")})}},
                               {0, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh")})}}}});
    out.push_back({.name = "/SPHBCS",
                   .summary = "SPH symmetry plane: /SPHBCS/SLIDE|TIED/id, normal axis of a frame",
                   .formats = {{0, {once({T("Dir"), I("frame_ID"), I("grnod_ID"), S(), I("Ilev")})}}}});
    // CFG radioss140/LOADS/sph_inout.cfg: card 1 is `%10d%10d%10d%20lg` in FORMAT(radioss51/90/110);
    // FORMAT(radioss140) adds node_ID1-3 and Fcut on it (outlets given by three nodes, a Butterworth
    // cut-off). The cards that follow depend on Itype (functions and scales, or the three points
    // XM..ZM2 when neither surface nor nodes are given): kept as text.
    out.push_back({.name = "/SPH/INOUT",
                   .summary = "SPH inlet, outlet or non-reflecting frontier",
                   .formats = {{140,
                                {once({I("Itype"), I("part_ID"), I("surf_ID"), R("Dist"), I("node_ID1"),
                                       I("node_ID2"), I("node_ID3"), R("Fcut")}),
                                 opaque()}},
                               {0, {once({I("Itype"), I("part_ID"), I("surf_ID"), R("Dist")}), opaque()}}}});
    out.push_back({.name = "/SPH/RESERVE",
                   .title = false,
                   .summary = "reserve particles of a part (for inlets)",
                   .formats = {{0, {once({I("Np")})}}}});
    out.push_back({.name = "/SPH", .decoded = false, .summary = "SPH option", .formats = {{0, {opaque()}}}});
    // /INISPHCEL/FULL: CFG radioss2025/TABLE/inisphcel_full.cfg (FORMAT(radioss2024): the header,
    // no title) and inisphcel_full_sub.cfg (FORMAT(radioss2025)), per particle `%10d%10d`
    // sphcel_ID nvarsph, `%20lg%20lg%20lg` Eint Rho h, Sigma1-3, `%20lg` Epsp, then
    // LIST("%20lg", V, nvarsph): nvarsph values five a line.
    out.push_back({.name = "/INISPHCEL",
                   .title = false,
                   .summary = "initial particle states: /INISPHCEL/FULL, per particle Eint, Rho, h, stresses, Epsp",
                   .formats = {{2024,
                                {repeated({I("sphcel_ID"), I("nvarsph")}), repeated({R("Eint"), R("Rho"), R("h")}),
                                 repeated({R("Sigma1"), R("Sigma2"), R("Sigma3")}), repeated({R("Epsp")}),
                                 list("V", 5, "nvarsph")}}}});

    // Engine keywords (§5.7): list-directed data, so only the field order matters.
    const FormatSpec dt{0, {once({R("DTsca"), R("DTmin"), R("percent_addmass")})}};
    out.push_back({.name = "/DT/SPHCEL",
                   .aliases = {"/DT/SPCEL"},
                   .title = false,
                   .engine = true,
                   .summary = "particle time step: /DT/SPHCEL/STOP|DEL|KILL, scale and minimum",
                   .formats = {dt}});
    out.push_back({.name = "/DT/NODA",
                   .title = false,
                   .engine = true,
                   .summary = "nodal time step: /DT/NODA/<Keyword3>[/1], scale and minimum",
                   .formats = {{0, {once({R("DTsca"), R("DTmin"), R("percent_addmass")}), once({I("grpart_ID")})}}}});
    out.push_back({.name = "/DT/BRICK",
                   .title = false,
                   .engine = true,
                   .summary = "brick time step: /DT/BRICK/DEL deletes bricks (releases SOL2SPH particles)",
                   .formats = {{0,
                                {once({R("DTsca"), R("DTmin")}),
                                 once({R("COL_min"), R("Vdef_min"), R("ASP_max"), R("Vdef_max")})}}}});
    out.push_back({.name = "/DT",
                   .title = false,
                   .engine = true,
                   .summary = "global time step scale and minimum",
                   .formats = {{0, {once({R("DTsca"), R("DTmin")})}}}});
    for (std::string_view name : {"/RUN", "/VERS", "/TFILE", "/ANIM", "/H3D", "/PRINT", "/STOP", "/MON", "/RFILE",
                                  "/OUTP", "/PARITH", "/STATE", "/KILL", "/ADYREL", "/DTIX", "/MADYMO", "/CHKPT"})
        out.push_back({.name = name, .title = false, .engine = true, .decoded = false, .summary = "engine option",
                       .formats = {{0, {opaque()}}}});
}

}  // namespace sphdeck::grammar::radioss::detail
