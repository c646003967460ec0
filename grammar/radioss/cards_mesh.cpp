// Deck structure, nodes, parts, solid elements, node groups, skews and frames.
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

void add_mesh_keywords(std::vector<KeywordSpec>& out) {
    // /BEGIN (radioss-format.md §3; CFG radioss2021/CARDS/begin.cfg, radioss100/CARDS/begin.cfg):
    // the two unit lines (input and work units) are read from format 100 on; Irun until 2021.
    // Its own version is read from card 2 before decoding. The starter reads text after Irun
    // silently (SUBMODEL/update_v_100 FAIL deck: "100 0 ... 1", no reader warning in its listing).
    const CardSpec units_input = once({T20("Input_mass"), T20("Input_length"), T20("Input_time")});
    const CardSpec units_work = once({T20("Work_mass"), T20("Work_length"), T20("Work_time")});
    out.push_back({.name = "/BEGIN",
                   .title = false,
                   .trailing_checked = false,
                   .summary = "run name, input version Invers and unit systems",
                   .formats = {{2021, {once({L("Runname")}), once({I("Invers")}), units_input, units_work}},
                               {100, {once({L("Runname")}), once({I("Invers"), I("Irun")}), units_input, units_work}},
                               {0, {once({L("Runname")}), once({I("Invers"), I("Irun")})}}}});
    out.push_back(
        {.name = "/END", .title = false, .decoded = false, .summary = "end of the deck", .formats = {{0, {}}}});
    out.push_back({.name = "/NODE",
                   .title = false,
                   .summary = "nodes: id and coordinates",
                   .formats = {{0, {repeated({I("node_ID"), R("X"), R("Y"), R("Z")})}}}});
    // CFG radioss2612/PART/part.cfg (formats 51 and 41).
    out.push_back({.name = "/PART",
                   .summary = "part: property, material and subset",
                   .formats = {{0, {once({I("prop_ID"), I("mat_ID"), I("subset_ID"), R("Thick")})}}}});
    // CFG radioss2026/CARDS/analy.cfg: `%10d          %10d%10d` (51-2022), `%8d          %8d%8d` (41).
    out.push_back({.name = "/ANALY",
                   .title = false,
                   .summary = "analysis type: N2D3D 0 = 3D, 1 = axisymmetric, 2 = plane strain",
                   .formats = {{2026, {once({I("N2D3D"), I("Itemp"), I("Iparith")})}},
                               {2023, {once({I("N2D3D"), gap(10), I("Iparith")})}},
                               {51, {once({I("N2D3D"), gap(10), I("Iparith"), I("Isubcyc")})}},
                               {0, {once({I("N2D3D"), gap(10), I("Iparith"), I("Isubcyc")})}}}});
    // CFG radioss2025/CARDS/def_solid.cfg: Iframe in cell 8 from format 51; V4 has none.
    out.push_back(
        {.name = "/DEF_SOLID",
         .title = false,
         .summary = "default solid formulation (Isolid, Iframe)",
         .formats = {{2025,
                      {once({I("Isolid"), I("Ismstr"), I("Icpre"), S(), I("Itetra4"), I("Itetra10"), I("Imas"),
                             I("Iframe"), I("Icontrol")})}},
                     {2021,
                      {once({I("Isolid"), I("Ismstr"), I("Icpre"), S(), I("Itetra4"), I("Itetra10"), I("Imas"),
                             I("Iframe")})}},
                     {2019,
                      {once({I("Isolid"), I("Ismstr"), S(), I("Istrain"), I("Itetra4"), I("Itetra10"), I("Imas"),
                             I("Iframe")})}},
                     {120, {once({I("Isolid"), I("Ismstr"), S(), I("Istrain"), S(), S(), I("Imas"), I("Iframe")})}},
                     {100, {once({I("Isolid"), I("Ismstr"), S(), I("Istrain"), S(), S(), S(), I("Iframe")})}},
                     {51, {once({I("Isolid"), I("Ismstr"), S(), S(), S(), S(), S(), I("Iframe")})}},
                     {44, {once({I("Isolid"), I("Ismstr"), I("Iplas")})}},
                     {0, {once({I("Isolid"), I("Ismstr")})}}}});

    // Solid elements: /BRICK/part_ID etc., one element per line (/TETRA10: two lines).
    out.push_back({.name = "/BRICK",
                   .title = false,
                   .summary = "8-node bricks of a part",
                   .formats = {{0,
                                {repeated({I("brick_ID"), I("node_ID1"), I("node_ID2"), I("node_ID3"), I("node_ID4"),
                                           I("node_ID5"), I("node_ID6"), I("node_ID7"), I("node_ID8")})}}}});
    out.push_back(
        {.name = "/TETRA4",
         .title = false,
         .summary = "4-node tetras of a part",
         .formats = {{0, {repeated({I("tetra_ID"), I("node_ID1"), I("node_ID2"), I("node_ID3"), I("node_ID4")})}}}});
    out.push_back(
        {.name = "/TETRA10",
         .title = false,
         .summary = "10-node tetras of a part (id line, then the ten nodes)",
         .formats = {{0,
                      {repeated({I("tetra_ID")}),
                       repeated({I("node_ID1"), I("node_ID2"), I("node_ID3"), I("node_ID4"), I("node_ID5"),
                                 I("node_ID6"), I("node_ID7"), I("node_ID8"), I("node_ID9"), I("node_ID10")})}}}});
    out.push_back({.name = "/PENTA6",
                   .title = false,
                   .summary = "6-node pentas of a part",
                   .formats = {{0,
                                {repeated({I("penta_ID"), I("node_ID1"), I("node_ID2"), I("node_ID3"), I("node_ID4"),
                                           I("node_ID5"), I("node_ID6")})}}}});

    // Node groups: members of /GRNOD/NODE and /GRNOD/PART are read; other kinds keep their id.
    out.push_back({.name = "/GRNOD/NODE",
                   .summary = "node group given by node ids",
                   .formats = {{0, {repeated_ints("node_ID", 10)}}}});
    out.push_back({.name = "/GRNOD/PART",
                   .summary = "node group: the nodes of parts",
                   .formats = {{0, {repeated_ints("part_ID", 10)}}}});
    out.push_back({.name = "/GRNOD", .summary = "node group", .formats = {{0, {opaque()}}}});

    // Skews and frames. Fixed ones: origin, then the local Y' and Z' axes (CFG
    // radioss110/SYSTEM/frame_fix.cfg and radioss120/SYSTEM/skew_fix.cfg read globalyaxis* and
    // globalzaxis*; starter hm_read_frm.F / hm_read_skw.F build X' = Y' x Z'). A /SKEW/FIX has
    // no origin line before format 120. Moving ones: three nodes and the direction of N1N2.
    const CardSpec origin = once({R("Ox"), R("Oy"), R("Oz")});
    const CardSpec y_axis = once({R("Yx"), R("Yy"), R("Yz")});
    const CardSpec z_axis = once({R("Zx"), R("Zy"), R("Zz")});
    const FormatSpec moving{0, {once({I("node_ID1"), I("node_ID2"), I("node_ID3"), T("Dir")})}};
    out.push_back({.name = "/FRAME/FIX",
                   .summary = "fixed frame: origin, Y' and Z' axes (X' = Y' x Z')",
                   .formats = {{0, {origin, y_axis, z_axis}}}});
    out.push_back({.name = "/SKEW/FIX",
                   .summary = "fixed skew: origin (from format 120), Y' and Z' axes (X' = Y' x Z')",
                   .formats = {{120, {origin, y_axis, z_axis}}, {0, {y_axis, z_axis}}}});
    out.push_back({.name = "/FRAME/MOV", .summary = "moving frame given by three nodes", .formats = {moving}});
    out.push_back({.name = "/SKEW/MOV", .summary = "moving skew given by three nodes", .formats = {moving}});
    out.push_back({.name = "/FRAME", .summary = "frame (moving)", .formats = {{0, {opaque()}}}});
    out.push_back({.name = "/SKEW", .summary = "skew (moving)", .formats = {{0, {opaque()}}}});

    // /PARAMETER/<scope>/INTEGER|REAL/id: a title line, then `%-10s%10d` or `%-10s%20lg`, name and
    // value (OpenRadioss CFG radioss2017/PARAMETER/parameter_int.cfg, parameter_float.cfg).
    // model/radioss_parameters.cpp reads them before the other blocks, so the walker skips them;
    // other kinds (REAL_EXPR, INT_EXPR, TEXT) stay opaque under /PARAMETER below.
    for (std::string_view scope : {"GLOBAL", "LOCAL"}) {
        const bool global = scope == "GLOBAL";
        out.push_back({.name = global ? "/PARAMETER/GLOBAL/INTEGER" : "/PARAMETER/LOCAL/INTEGER",
                       .decoded = false,
                       .summary = "integer parameter: name, value",
                       .formats = {{2017, {once({T("name"), I("value")})}}}});
        out.push_back({.name = global ? "/PARAMETER/GLOBAL/REAL" : "/PARAMETER/LOCAL/REAL",
                       .decoded = false,
                       .summary = "real parameter: name, value",
                       .formats = {{2017, {once({T("name"), R("value")})}}}});
    }

    // Structural or global keywords kept as they are.
    for (std::string_view name :
         {"/TITLE", "/UNIT",  "/IOFLAG", "/SPMD",   "/RANDOM", "/DEF_SHELL", "/PARAMETER", "/SUBSET",
          "/SURF",  "/LINE",  "/GRSHEL", "/GRBRIC", "/GRPART", "/BCS",       "/IMPVEL",    "/INIVEL",
          "/GRAV",  "/FUNCT", "/INTER",  "/RWALL",  "/TH",     "/SENSOR",    "/KEY"})
        out.push_back(
            {.name = name, .title = false, .decoded = false, .summary = "kept as is", .formats = {{0, {opaque()}}}});
}

}  // namespace sphdeck::grammar::radioss::detail
