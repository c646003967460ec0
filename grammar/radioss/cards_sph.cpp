// SPH cards of the starter and the engine (radioss-format.md §5.2-§5.7).
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

void add_sph_keywords(std::vector<KeywordSpec>& out) {
    out.push_back({.name = "/SPHCEL",
                   .title = false,
                   .summary = "SPH particles of a part: node, Type (1 mass, 2 volume), MASS",
                   .formats = {{0, {repeated({I("node_ID"), I("Type"), R("MASS")})}}}});
    out.push_back({.name = "/SPHGLO",
                   .title = false,
                   .summary = "global SPH parameters: neighbour search margin and counts",
                   .formats = {{2017, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh"), I("Nneigh"), I("Isol2sph")})}},
                               {120, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh"), I("Nneigh")})}},
                               {0, {once({R("Alpha_sort"), I("Maxsph"), I("Lneigh")})}}}});
    out.push_back({.name = "/SPHBCS",
                   .summary = "SPH symmetry plane: /SPHBCS/SLIDE|TIED/id, normal axis of a frame",
                   .formats = {{0, {once({T("Dir"), I("frame_ID"), I("grnod_ID"), S(), I("Ilev")})}}}});
    // CFG radioss140/LOADS/sph_inout.cfg: `%10d%10d%10d%20lg`, then cards per Itype (not checked).
    out.push_back({.name = "/SPH/INOUT",
                   .summary = "SPH inlet, outlet or non-reflecting frontier",
                   .formats = {{0, {once({I("Itype"), I("part_ID"), I("surf_ID"), R("Dist")}), opaque()}}}});
    out.push_back({.name = "/SPH/RESERVE",
                   .title = false,
                   .summary = "reserve particles of a part (for inlets)",
                   .formats = {{0, {once({I("Np")})}}}});
    out.push_back({.name = "/SPH", .decoded = false, .summary = "SPH option", .formats = {{0, {opaque()}}}});
    out.push_back({.name = "/INISPHCEL", .decoded = false, .summary = "initial particle states",
                   .formats = {{0, {opaque()}}}});

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
