// Properties, materials and equations of state (radioss-format.md §5.1, §5.8; OpenRadioss CFG
// files prop_p34_sph.cfg, prop_p14_solid.cfg, prop_p6_sol_orth.cfg, the /MAT laws, /EOS).
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

namespace {

// /PROP/SPH (TYPE34), §5.1: five formats; V4 (44) is the 51 layout in 16/8-character cells.
KeywordSpec prop_sph() {
    const auto card1_2019 = once({R("mp"), R("qa"), R("qb"), R("alpha_cs"), I("skew_ID"), I("h_1D")});
    return {.name = "/PROP/SPH",
            .aliases = {"/PROP/TYPE34"},
            .summary = "SPH particle property: mass, viscosity, smoothing length",
            .formats = {{2026,
                         {card1_2019, once({I("Order"), R("h"), R("Xi_Stab"), S(), R("hmin"), R("hmax")}),
                          once({R("hcst")})}},
                        {2019, {card1_2019, once({I("Order"), R("h"), R("Xi_Stab")})}},
                        {130,
                         {once({R("mp"), R("qa"), R("qb"), R("alpha_cs"), I("skew_ID")}),
                          once({I("Order"), R("h"), R("Xi_Stab")})}},
                        {0, {once({R("mp"), R("qa"), R("qb"), R("alpha_cs")}), once({I("Order"), R("h")})}}}};
}

// /PROP/TYPE14 (SOLID), §5.8: Isolid in cells 1, Iframe in cell 8 in every format from 51; the
// SOL2SPH card (Ndir, sphpartID) is the fourth card from format 140 (optional before 2025).
KeywordSpec prop_solid() {
    const auto card1 = once({I("Isolid"), I("Ismstr"), I("Iale"), I("Icpre"), I("Itetra10"), I("Inpts"),
                             I("Itetra4"), I("Iframe"), R("Dn")});
    const auto card2 = once({R("qa"), R("qb"), R("h"), R("Lambda"), R("Mu")});
    const auto card3 = once({R("deltaT_min"), R("vdef_min"), R("vdef_max"), R("ASP_max"), R("COL_min")});
    return {.name = "/PROP/TYPE14",
            .aliases = {"/PROP/SOLID"},
            .summary = "solid property; Ndir and sphpartID turn its elements into SPH particles (SOL2SPH)",
            .formats = {{2025, {card1, card2, card3, once({I("Ndir"), I("sphpartID"), I("Icontrol")})}},
                        {140, {card1, card2, card3, once({I("Ndir"), I("sphpartID")})}},
                        {0, {card1, card2, card3}}}};
}

// /PROP/TYPE6 (SOL_ORTH), §5.8: as TYPE14 with orthotropy cards; the SOL2SPH card is the sixth.
KeywordSpec prop_sol_orth() {
    const auto card1 = once({I("Isolid"), I("Ismstr"), S(), I("Icpre"), I("Itetra10"), I("Inpts"), I("Itetra4"),
                             I("Iframe"), R("Dn")});
    const auto card2 = once({R("qa"), R("qb"), R("h")});
    const auto card3 = once({R("Vx"), R("Vy"), R("Vz"), I("skew_ID"), I("Ip"), I("Iorth")});
    const auto card4 = once({R("Phi"), R("Px"), R("Py"), R("Pz")});
    const auto card5 = once({R("deltaT_min"), R("vdef_min"), R("vdef_max"), R("ASP_max"), R("COL_min")});
    return {.name = "/PROP/TYPE6",
            .aliases = {"/PROP/SOL_ORTH"},
            .summary = "orthotropic solid property; Ndir and sphpartID give SOL2SPH particles",
            .formats = {{2025, {card1, card2, card3, card4, card5, once({I("Ndir"), I("sphpartID"), I("Icontrol")})}},
                        {140, {card1, card2, card3, card4, card5, once({I("Ndir"), I("sphpartID")})}},
                        {0, {card1, card2, card3, card4, card5}}}};
}

}  // namespace

void add_property_keywords(std::vector<KeywordSpec>& out) {
    out.push_back(prop_sph());
    out.push_back(prop_solid());
    out.push_back(prop_sol_orth());
    out.push_back({.name = "/PROP", .summary = "other property", .formats = {{0, {opaque()}}}});

    // /MAT/<law or name>/mat_ID: the density is the first field of every law; the laws' other
    // cards are read as rows of reals and picked per law by the decoder (E and nu, or C0-C5).
    out.push_back({.name = "/MAT",
                   .summary = "material: law, density and the moduli the sound speed needs",
                   .formats = {{0, {once({R("RHO_I"), R("RHO_0")}),
                                    repeated({R("v1"), R("v2"), R("v3"), R("v4"), R("v5")})}}}});
    // /EOS/POLYNOMIAL/mat_ID (starter hm_read_eos_polynomial.F).
    out.push_back({.name = "/EOS/POLYNOMIAL",
                   .summary = "polynomial equation of state of a material",
                   .formats = {{0,
                                {once({R("C0"), R("C1"), R("C2"), R("C3")}), once({R("C4"), R("C5"), R("E0"), R("Psh")}),
                                 once({R("RHO_0")})}}}});
    out.push_back({.name = "/EOS", .decoded = false, .summary = "equation of state", .formats = {{0, {opaque()}}}});
    out.push_back({.name = "/FAIL", .decoded = false, .summary = "failure model", .formats = {{0, {opaque()}}}});
}

}  // namespace sphdeck::grammar::radioss::detail
