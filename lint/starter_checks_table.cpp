// The starter's value checks, law by law (lint/starter_checks.hpp says where they come from).
// Paths are under starter/source/materials/mat/ of OpenRadioss (AGPL-3.0) at commit
// bd4557ba7503a277d3be5b50e1c64e8a12e0c53f; message texts from starter_message_description.txt.
#include <algorithm>
#include <limits>

#include "grammar/radioss/cards_build.hpp"
#include "lint/starter_checks.hpp"

namespace sphdeck::lint::radioss {

namespace rad = grammar::radioss;
using namespace rad::build;
using rad::CardSpec;
using rad::FieldSpec;

bool allowed(Allowed a, double v) {
    switch (a) {
        case Allowed::Positive: return v > 0;
        case Allowed::AboveMinusOne: return v > -1;
        case Allowed::NotZero: return v != 0;
        case Allowed::ZeroToOne: return v >= 0 && v <= 1;
        case Allowed::AtMostOne: return v <= 1;
        case Allowed::ZeroToHalf: return v >= 0 && v < 0.5;
        case Allowed::AtMostHundred: return v <= 100;
    }
    return true;
}

std::string_view expected(Allowed a) {
    switch (a) {
        case Allowed::Positive: return "> 0";
        case Allowed::AboveMinusOne: return "> -1";
        case Allowed::NotZero: return "not 0";
        case Allowed::ZeroToOne: return "between 0 and 1";
        case Allowed::AtMostOne: return "<= 1";
        case Allowed::ZeroToHalf: return ">= 0 and < 0.5";
        case Allowed::AtMostHundred: return "<= 100";
    }
    return "";
}

namespace {

// hm_read_mat.F90:1595, after every law's reader: RHO_I <= 0 stops every law but 0, 20, 51, 151, 108.
// SPH119 reports it for every /MAT (lint/rules_density.cpp); the row keeps the table whole.
StarterCheck density() {
    return {"MAT_RHO", "RHO_I", Allowed::Positive, 0.0, {}, 683, "DENSITY IS LESS THAN OR EQUAL TO ZERO",
            "hm_read_mat.F90:1595", "SPH119"};
}

// /MAT/LAW2 (matl2_plas_johns.cfg, formats 2025, 2023, 140, 100, 51, 42, 41): the generated layout
// stops at its CARD_PREREAD; these are its cards. Card 3 is SIG_Y UTS EUTS with Iflag 1, a b n else.
std::vector<rad::FormatSpec> law2_layout() {
    const CardSpec rho = once({R("MAT_RHO"), R("Refer_Rho")});
    const auto hardening = [](std::string_view when, std::initializer_list<FieldSpec> fields) {
        CardSpec c = once(fields);
        c.when = c.condition = when;
        return c;
    };
    const CardSpec von_mises_iflag1 = hardening("MAT_Iflag=1", {R("MAT_SIG2_yc"), R("MAT_UTS"), R("MAT_EUTS"),
                                                                R("MAT_EPS"), R("MAT_SIG")});
    const CardSpec johnson_cook = hardening("MAT_Iflag!1", {R("MAT_SIGY"), R("MAT_BETA"), R("MAT_HARD"),
                                                            R("MAT_EPS"), R("MAT_SIG")});
    const CardSpec abn = once({R("MAT_SIGY"), R("MAT_BETA"), R("MAT_HARD"), R("MAT_EPS"), R("MAT_SIG")});
    const CardSpec rate = once({R("MAT_SRC"), R("MAT_SRP"), I("STRFLAG"), I("Fsmooth"), R("Fcut"), R("MAT_CHARD")});
    const CardSpec thermal = once({R("MAT_M"), R("MAT_TMELT"), R("MAT_SPHEAT"), R("MAT_TREF")});
    return {
        {2025,
         {rho, once({R("MAT_E"), R("MAT_NU"), I("MAT_Iflag"), I("MAT_VP"), R("MAT_PMIN")}), von_mises_iflag1,
          johnson_cook, rate, once({R("MAT_M"), R("MAT_TMELT"), R("MAT_SPHEAT"), R("MAT_TREF"), R("MAT_TMAX")}),
          opaque()}},
        {2023,
         {rho, once({R("MAT_E"), R("MAT_NU"), I("MAT_Iflag"), I("MAT_VP")}), von_mises_iflag1, johnson_cook, rate,
          thermal, opaque()}},
        {140, {rho, once({R("MAT_E"), R("MAT_NU"), I("MAT_Iflag")}), von_mises_iflag1, johnson_cook, rate, thermal,
               opaque()}},
        {100, {rho, once({R("MAT_E"), R("MAT_NU")}), abn, rate, thermal, opaque()}},
        {51, {rho, once({R("MAT_E"), R("MAT_NU")}), abn,
              once({R("MAT_SRC"), R("MAT_SRP"), I("STRFLAG"), I("Fsmooth"), R("Fcut")}), thermal, opaque()}},
        {42, {once({R("MAT_RHO")}), once({R("MAT_E"), R("MAT_NU")}), abn,
              once({R("MAT_SRC"), R("MAT_SRP"), I("STRFLAG"), I("Fsmooth"), R("Fcut")}), thermal, opaque()}},
        {0, {once({R("MAT_RHO")}), once({R("MAT_E"), R("MAT_NU")}), abn,
             once({R("MAT_SRC"), R("MAT_SRP"), I("STRFLAG")}), thermal, opaque()}},
    };
}

std::vector<StarterLaw> build() {
    std::vector<StarterLaw> laws;
    // LAW1 (hm_read_mat01.F)
    laws.push_back({{"/MAT/LAW1", "/MAT/LAW01", "/MAT/ELAST"},
                    "mat001/hm_read_mat01.F",
                    {density(),
                     {"MAT_E", "E", Allowed::Positive, 0.0, {}, 683, "YOUNG'S MODULUS IS LESS THAN OR EQUAL TO ZERO",
                      "mat001/hm_read_mat01.F:107"}}});
    // LAW2, Johnson-Cook (hm_read_mat02_jc.F90); the Zerilli and predefined forms have their own readers.
    laws.push_back(
        {{"/MAT/LAW2", "/MAT/LAW02", "/MAT/PLAS_JOHNS", "/MAT/JOHNS"},
         "mat002/hm_read_mat02_jc.F90",
         {density(),
          {"MAT_NU", "Nu", Allowed::AboveMinusOne, 0.0, {}, 300, "POISSON'S RATIO SHOULD BE .GT. -1.",
           "mat002/hm_read_mat02_jc.F90:211"},
          {"MAT_E", "E", Allowed::Positive, 0.0, {}, 276, "YOUNG MODULUS SHOULD BE GREATER THAN 0.",
           "mat002/hm_read_mat02_jc.F90:214"},
          {"MAT_CHARD", "Chard", Allowed::ZeroToOne, 0.0, {}, 912,
           "CARD (MIXED HARDENING FACTOR) MUST BE BETWEEN 0. AND 1.", "mat002/hm_read_mat02_jc.F90:217"},
          {"MAT_SIGY", "a", Allowed::Positive, 0.0, {}, 301, "A SHOULD BE GREATER THAN 0.",
           "mat002/hm_read_mat02_jc.F90:222"},
          {"MAT_SIG2_yc", "SIG_Y", Allowed::Positive, 0.0, {}, 301, "A SHOULD BE GREATER THAN 0.",
           "mat002/hm_read_mat02_jc.F90:222"},
          // n 0 is 1 (line 148); with Iflag 1 n is computed from UTS and EUTS, not read.
          {"MAT_HARD", "n", Allowed::AtMostOne, 1.0, "MAT_Iflag!1", 213, "N SHOULD BE LESS THAN 1.",
           "mat002/hm_read_mat02_jc.F90:226"},
          // EPS_DOT_0 becomes 1 when c is 0 (line 184): only a rate-dependent law needs it.
          {"MAT_SRP", "EPS_DOT_0", Allowed::NotZero, 0.0, "MAT_SRC!0", 298,
           "EPS0 SHOULD BE GREATER THAN 0. IF CC IS NOT EQUAL TO 0.", "mat002/hm_read_mat02_jc.F90:230"}},
         law2_layout()});
    // LAW3 (hm_read_mat03.F): no value check of its own.
    laws.push_back({{"/MAT/LAW3", "/MAT/LAW03", "/MAT/HYDPLA"}, "mat003/hm_read_mat03.F", {density()}});
    // LAW4 (hm_read_mat04.F)
    laws.push_back({{"/MAT/LAW4", "/MAT/LAW04", "/MAT/HYD_JCOOK"},
                    "mat004/hm_read_mat04.F",
                    {density(),
                     // rhoC_p 0 with T_melt 0 is a warning (593) and no thermal softening.
                     {"MAT_SPHEAT", "rhoC_p", Allowed::NotZero, 0.0, "MAT_TMELT!0", 594,
                      "Rho0Cp is zero in the material input ; Rho0Cp must be given in case of temperature dependency.",
                      "mat004/hm_read_mat04.F:210"},
                     {"MAT_SRP", "EPS_DOT_0", Allowed::NotZero, 0.0, "MAT_SRC!0", 298,
                      "EPS0 SHOULD BE GREATER THAN 0. IF CC IS NOT EQUAL TO 0.", "mat004/hm_read_mat04.F:304"}}});
    // LAW6 (hm_read_mat06.F): no value check of its own.
    laws.push_back({{"/MAT/LAW6", "/MAT/LAW06", "/MAT/HYD_VISC", "/MAT/HYDRO"}, "mat006/hm_read_mat06.F", {density()}});
    // LAW36 (hm_read_mat36.F)
    laws.push_back(
        {{"/MAT/LAW36", "/MAT/PLAS_TAB"},
         "mat036/hm_read_mat36.F",
         {density(),
          // tested before 0.5 becomes 0.499 (line 220): 0.5 stops.
          {"MAT_NU", "Nu", Allowed::ZeroToHalf, 0.0, {}, 49,
           "WRONG NU VALUE: NU MUST BE GREATER THAN 0 AND LESS THAN 0.5", "mat036/hm_read_mat36.F:144"},
          {"NFUNC", "N_funct", Allowed::AtMostHundred, 0.0, {}, 3127, "NRATE MUST BE LESS OR EQUAL THAN 100",
           "mat036/hm_read_mat36.F:148"},
          {"NFUNC", "N_funct", Allowed::Positive, 0.0, {}, 740, "NFUNCT MUST BE GREATER THAN 0",
           "mat036/hm_read_mat36.F:150"},
          {"MAT_HARD", "C_hard", Allowed::ZeroToOne, 0.0, {}, 912,
           "CARD (MIXED HARDENING FACTOR) MUST BE BETWEEN 0. AND 1.", "mat036/hm_read_mat36.F:224"},
          {"MAT_E", "E", Allowed::Positive, 0.0, {}, 276, "YOUNG MODULUS SHOULD BE GREATER THAN 0.",
           "mat036/hm_read_mat36.F:261"}}});
    // LAW42 (hm_read_mat42.F): its check (828) is on a modulus computed from the mu_i.
    laws.push_back({{"/MAT/LAW42", "/MAT/OGDEN"}, "mat042/hm_read_mat42.F", {density()}});
    // LAW70 (hm_read_mat70.F)
    laws.push_back({{"/MAT/LAW70", "/MAT/FOAM_TAB"},
                    "mat070/hm_read_mat70.F",
                    {density(),
                     {"NRATEP", "N_load", Allowed::NotZero, 0.0, {}, 866, "LOADING STRESS/STRAIN CURVE IS MANDATORY",
                      "mat070/hm_read_mat70.F:152"}}});
    // LAW80 (hm_read_mat80.F): the density only here.
    laws.push_back({{"/MAT/LAW80"}, "mat080/hm_read_mat80.F", {density()}});
    return laws;
}

}  // namespace

std::span<const StarterLaw> starter_laws() {
    static const std::vector<StarterLaw> laws = build();
    return laws;
}

const StarterLaw* starter_law_of(std::string_view header) {
    // "/MAT/LAW2/7" → "/MAT/LAW2": the family and the law, the segments a row names.
    const std::size_t second = header.find('/', 1);
    if (second == std::string_view::npos) return nullptr;
    const std::size_t third = header.find('/', second + 1);
    std::string_view name = header.substr(0, third);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    for (const StarterLaw& law : starter_laws())
        if (std::find(law.names.begin(), law.names.end(), name) != law.names.end()) return &law;
    return nullptr;
}

}  // namespace sphdeck::lint::radioss
