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

// /PROP/TYPE14 (SOLID), CFG radioss2025/PROP/prop_p14_solid.cfg. Isolid in cell 1 and Iframe in
// cell 8 from format 51; the third card changes (dt_min alone, with Istrain and Imod, or the five
// deletion limits from 2023); the SOL2SPH card (Ndir, sphpartID) is the fourth from format 140.
KeywordSpec prop_solid() {
    const auto card1_2022 = once({I("Isolid"), I("Ismstr"), I("Iale"), I("Icpre"), I("Itetra10"), I("Inpts"),
                                  I("Itetra4"), I("Iframe"), R("Dn")});
    const auto card1_2019 = once(
        {I("Isolid"), I("Ismstr"), S(), I("Icpre"), I("Itetra10"), I("Inpts"), I("Itetra4"), I("Iframe"), R("Dn")});
    const auto card1_100 =
        once({I("Isolid"), I("Ismstr"), S(), I("Icpre"), S(), I("Inpts"), I("Itetra4"), I("Iframe"), R("Dn")});
    const auto card1_51 = once({I("Isolid"), I("Ismstr"), S(), I("Icpre"), S(), I("Inpts"), S(), I("Iframe"), R("Dn")});
    const auto card2 = once({R("qa"), R("qb"), R("h"), R("Lambda"), R("Mu")});
    const auto card2_short = once({R("qa"), R("qb"), R("h")});
    const auto card3_2023 = once({R("deltaT_min"), R("vdef_min"), R("vdef_max"), R("ASP_max"), R("COL_min")});
    const auto card3_120 = once({R("deltaT_min"), I("Istrain"), I("Imod")});
    const auto sol2sph = once({I("Ndir"), I("sphpartID")});
    return {.name = "/PROP/TYPE14",
            .aliases = {"/PROP/SOLID"},
            .summary = "solid property; Ndir and sphpartID turn its elements into SPH particles (SOL2SPH)",
            .formats = {{2025, {card1_2022, card2, card3_2023, once({I("Ndir"), I("sphpartID"), I("Icontrol")})}},
                        {2023, {card1_2022, card2, card3_2023, sol2sph}},
                        {2022, {card1_2022, card2, card3_120, sol2sph}},
                        {2019, {card1_2019, card2, card3_120, sol2sph}},
                        {140, {card1_100, card2, card3_120, sol2sph}},
                        {120, {card1_100, card2, card3_120}},
                        {100, {card1_100, card2_short, once({R("deltaT_min"), I("Istrain")})}},
                        {51, {card1_51, card2_short, once({R("deltaT_min")})}},
                        {44,
                         {once({I("Isolid"), I("Ismstr"), I("Iplas"), I("Icpre"), I("Icstr"), R("Dn")}), card2_short}},
                        {0, {once({I("Isolid"), I("Ismstr")}), card2_short}}}};
}

// /PROP/TYPE6 (SOL_ORTH), CFG radioss2025/PROP/prop_p6_sol_orth.cfg: as TYPE14 with the
// orthotropy cards; the SOL2SPH card is the sixth from format 2017.
KeywordSpec prop_sol_orth() {
    const auto card1_2020 = once(
        {I("Isolid"), I("Ismstr"), S(), I("Icpre"), I("Itetra10"), I("Inpts"), I("Itetra4"), I("Iframe"), R("Dn")});
    const auto card1_51 = once({I("Isolid"), I("Ismstr"), S(), I("Icpre"), S(), I("Inpts"), S(), I("Iframe"), R("Dn")});
    const auto card2 = once({R("qa"), R("qb"), R("h")});
    const auto card3 = once({R("Vx"), R("Vy"), R("Vz"), I("skew_ID"), I("Ip"), I("Iorth")});
    const auto card4 = once({R("Phi"), R("Px"), R("Py"), R("Pz")});
    const auto card4_phi = once({R("Phi")});
    const auto card5_2023 = once({R("deltaT_min"), R("vdef_min"), R("vdef_max"), R("ASP_max"), R("COL_min")});
    const auto card5_140 = once({R("deltaT_min"), I("Istrain"), I("IHKT")});
    const auto sol2sph = once({I("Ndir"), I("sphpartID")});
    const auto v4_card3 = once({I("Ip"), I("skew_ID"), R("Phi")});
    return {.name = "/PROP/TYPE6",
            .aliases = {"/PROP/SOL_ORTH"},
            .summary = "orthotropic solid property; Ndir and sphpartID give SOL2SPH particles",
            .formats = {
                {2025, {card1_2020, card2, card3, card4, card5_2023, once({I("Ndir"), I("sphpartID"), I("Icontrol")})}},
                {2023, {card1_2020, card2, card3, card4, card5_2023, sol2sph}},
                {2021, {card1_2020, card2, card3, card4, card5_140, sol2sph}},
                {2020, {card1_2020, card2, card3, card4_phi, card5_140, sol2sph}},
                {2017, {card1_51, card2, card3, card4_phi, card5_140, sol2sph}},
                {140, {card1_51, card2, card3, card4_phi, card5_140}},
                {120, {card1_51, card2, card3, card4_phi, once({R("deltaT_min"), I("Istrain")})}},
                {51, {card1_51, card2, card3, card4_phi, once({R("deltaT_min")})}},
                {44, {once({I("Isolid"), I("Ismstr"), I("Iplas"), I("Dn")}), card2, v4_card3}},
                {0, {once({I("Isolid"), I("Ismstr")}), card2, v4_card3}}}};
}

}  // namespace

void add_property_keywords(std::vector<KeywordSpec>& out) {
    out.push_back(prop_sph());
    out.push_back(prop_solid());
    out.push_back(prop_sol_orth());
    out.push_back({.name = "/PROP", .summary = "other property", .formats = {{0, {opaque()}}}});

    add_material_keywords(out);
    // /EOS/POLYNOMIAL/mat_ID, CFG radioss2026/MAT/mat_EOS.cfg: RHO_0 ends the second card up to
    // format 2022 (starter hm_read_eos_polynomial.F reads it as Refer_Rho when present), C6 from 2026.
    const auto c0_c3 = once({R("C0"), R("C1"), R("C2"), R("C3")});
    out.push_back({.name = "/EOS/POLYNOMIAL",
                   .summary = "polynomial equation of state of a material",
                   .formats = {{2026, {c0_c3, once({R("C4"), R("C5"), R("E0"), R("Psh"), R("C6")})}},
                               {2023, {c0_c3, once({R("C4"), R("C5"), R("E0"), R("Psh")})}},
                               {0, {c0_c3, once({R("C4"), R("C5"), R("E0"), R("Psh"), R("RHO_0")})}}}});
    out.push_back({.name = "/EOS", .decoded = false, .summary = "equation of state", .formats = {{0, {opaque()}}}});
    out.push_back({.name = "/FAIL", .decoded = false, .summary = "failure model", .formats = {{0, {opaque()}}}});
}

}  // namespace sphdeck::grammar::radioss::detail
