// SPH cards of the starter and the engine (radioss-format.md §5.2-§5.7).
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

namespace {

// /SPH/INOUT, CFG radioss140/LOADS/sph_inout.cfg. Card 1 is `%10d%10d%10d%20lg` in
// FORMAT(radioss51/90/110); FORMAT(radioss140) adds node_ID1-3 and Fcut (a frontier through three
// nodes, a Butterworth cut-off). Then, by Itype: 1 (inlet) `%10d%20lg%30s%10d%20lg` and `%10d`,
// the density, energy and normal-velocity functions; 2 (outlet) `%30s%10d%20lg` and a blank
// line; 3 (non-reflecting frontier) `%30s%10d%20lg%20lg` and a blank line; 4 (control section)
// nothing. From format 140, an outlet (Itype not 1) without a surface and without all three
// nodes reads the three points M, M1, M2 first, one card each (the CFG's IMPORT branch; the
// starter, hm_read_sphio.F, uses them when the three nodes are 0).
KeywordSpec sph_inout() {
    const CardCondition inlet = +[](const EarlierValues& e) { return e("Itype") == 1; };
    const CardCondition outlet = +[](const EarlierValues& e) { return e("Itype") == 2; };
    const CardCondition frontier = +[](const EarlierValues& e) { return e("Itype") == 3; };
    const CardCondition by_points = +[](const EarlierValues& e) {
        return e("Itype") != 1 && e("surf_ID") == 0 && (e("node_ID1") == 0 || e("node_ID2") == 0 || e("node_ID3") == 0);
    };
    const FieldSpec itype =
        I("Itype", "1 inlet (needs surf_ID), 2 outlet, 3 non-reflecting frontier, 4 control section");
    const FieldSpec dist = R("Dist", "particle control distance from the surface");
    const auto by_itype = [&](std::vector<CardSpec> cards) {
        cards.push_back(when(once({I("fct_IDr"), R("Fscaler", "0 with fct_IDr: 1"), gap(30), I("fct_IDE"),
                                   R("FscaleE", "0 with fct_IDE: 1")}),
                             inlet, "Itype 1"));
        cards.push_back(when(once({I("fct_IDVn")}), inlet, "Itype 1"));
        cards.push_back(when(once({gap(30), I("fct_IDP"), R("FscaleP", "0 with fct_IDP: 1")}), outlet, "Itype 2"));
        cards.push_back(when(once({L("blank")}), outlet, "Itype 2: a blank line"));
        cards.push_back(
            when(once({gap(30), I("fct_IDP"), R("FscaleP", "0 with fct_IDP: 1"), R("Lc")}), frontier, "Itype 3"));
        cards.push_back(when(once({L("blank")}), frontier, "Itype 3: a blank line"));
        cards.push_back(opaque());  // further lines: kept as text
        return cards;
    };
    const char* points = "Itype 2-4 without surf_ID and without all three nodes";
    return {.name = "/SPH/INOUT",
            .summary = "SPH inlet, outlet or non-reflecting frontier",
            .source = "CFG radioss140/LOADS/sph_inout.cfg (formats 140, 110, 90, 51); starter hm_read_sphio.F",
            .formats = {{140,
                         by_itype({once({itype, I("part_ID"), I("surf_ID", "0: the frontier by nodes or points"), dist,
                                         I("node_ID1"), I("node_ID2"), I("node_ID3"), R("Fcut", "0: no filter")}),
                                   when(once({R("XM"), R("YM"), R("ZM")}), by_points, points),
                                   when(once({R("XM1"), R("YM1"), R("ZM1")}), by_points, points),
                                   when(once({R("XM2"), R("YM2"), R("ZM2")}), by_points, points)})},
                        {0, by_itype({once({itype, I("part_ID"), I("surf_ID"), dist})})}}};
}

}  // namespace

void add_sph_keywords(std::vector<KeywordSpec>& out) {
    out.push_back({.name = "/SPHCEL",
                   .title = false,
                   .summary = "SPH particles of a part: node, Type (1 mass, 2 volume), MASS",
                   .formats = {{0, {repeated({I("node_ID"), I("Type"), R("MASS")})}}}});
    // CFG radioss2017/CARDS/sphglo.cfg: `%20lg%10d%10d%10d%10d` (2017, Isol2sph added),
    // `%20lg%10d%10d%10d` (120, Nneigh added), `%20lg%10d%10d` (51; no V4 format, so V4 decks
    // read the 51 cells at their own widths).
    // Notes: hm_read_sphglo.F and radioss-format.md §5.4 (model/radioss_build_sph.cpp end_sphglo).
    const FieldSpec alpha = R("Alpha_sort", "0: 0.25 (search margin, a fraction of h)");
    const FieldSpec maxsph = I("Maxsph", "0: no limit");
    const FieldSpec lneigh = I("Lneigh", "0: Nneigh");
    const FieldSpec nneigh = I("Nneigh", "at least 120 and at least Lneigh");
    out.push_back({.name = "/SPHGLO",
                   .title = false,
                   .summary = "global SPH parameters: neighbour search margin and counts",
                   .source = "CFG radioss2017/CARDS/sphglo.cfg (formats 2017, 120, 51); starter hm_read_sphglo.F",
                   .formats = {{2017, {once({alpha, maxsph, lneigh, nneigh, I("Isol2sph", "0: 1")})}},
                               {120, {once({alpha, maxsph, lneigh, nneigh})}},
                               {0, {once({alpha, maxsph, lneigh})}}}});
    out.push_back({.name = "/SPHBCS",
                   .summary = "SPH symmetry plane: /SPHBCS/SLIDE|TIED/id, normal axis of a frame",
                   .formats = {{0, {once({T("Dir"), I("frame_ID"), I("grnod_ID"), S(), I("Ilev")})}}}});
    out.push_back(sph_inout());
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
                   .source = "CFG radioss2025/TABLE/inisphcel_full.cfg, inisphcel_full_sub.cfg; starter "
                             "hm_read_inistate_d00.F",
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
    out.push_back(
        {.name = "/DT/BRICK",
         .title = false,
         .engine = true,
         .summary = "brick time step: /DT/BRICK/DEL deletes bricks (releases SOL2SPH particles)",
         .formats = {
             {0, {once({R("DTsca"), R("DTmin")}), once({R("COL_min"), R("Vdef_min"), R("ASP_max"), R("Vdef_max")})}}}});
    out.push_back({.name = "/DT",
                   .title = false,
                   .engine = true,
                   .summary = "global time step scale and minimum",
                   .formats = {{0, {once({R("DTsca"), R("DTmin")})}}}});
    for (std::string_view name : {"/RUN", "/VERS", "/TFILE", "/ANIM", "/H3D", "/PRINT", "/STOP", "/MON", "/RFILE",
                                  "/OUTP", "/PARITH", "/STATE", "/KILL", "/ADYREL", "/DTIX", "/MADYMO", "/CHKPT"})
        out.push_back({.name = name,
                       .title = false,
                       .engine = true,
                       .decoded = false,
                       .summary = "engine option",
                       .formats = {{0, {opaque()}}}});
}

}  // namespace sphdeck::grammar::radioss::detail
