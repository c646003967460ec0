// The starter's value checks, law by law (lint/starter_checks.hpp says where they come from).
// Paths are under starter/source/ of OpenRadioss (AGPL-3.0) at commit
// bd4557ba7503a277d3be5b50e1c64e8a12e0c53f (materials/mat/, materials/eos/ or properties/, by the row's
// family: reader_folder); message texts from starter_message_description.txt; the hand-written layouts
// from the CFG files of hm_cfg_files/config/CFG/radiossNNNN/MAT/ (law51_Iflag_10.cfg, mat_EOS.cfg).
#include <algorithm>
#include <limits>

#include "grammar/radioss/cards_build.hpp"
#include "lint/starter_checks.hpp"

// A table laid out by hand, one row per line:
// clang-format off

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
        case Allowed::AboveOne: return v > 1;
        case Allowed::NotNegative: return v >= 0;
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
        case Allowed::AboveOne: return "> 1";
        case Allowed::NotNegative: return ">= 0";
    }
    return "";
}

std::string_view reader_folder(const StarterLaw& law) {
    const std::string_view name = law.names.front();
    if (name.starts_with("/EOS/")) return "materials/eos";
    if (name.starts_with("/PROP/")) return "properties";
    return "materials/mat";
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
    const auto hardening = [](std::string_view when_field, std::initializer_list<FieldSpec> fields) {
        CardSpec c = once(fields);
        c.when = c.condition = when_field;
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

CardSpec when_field(std::string_view condition, std::initializer_list<FieldSpec> fields) {
    CardSpec c = once(fields);
    c.when = c.condition = condition;
    return c;
}

// /MAT/LAW51 with Iform 10 (law51_Iflag_10.cfg of radioss51 to radioss130; Iform 10 stops the starter
// from 2023 on, message 75): the generated layout stops after the Iform card, the rest being a
// sub-object. Three phases of six cards, then the explosive's three; IBFRAC since 130.
std::vector<rad::FormatSpec> law51_layout() {
    constexpr std::string_view iform10 = "MAT_Iflag=10";
    std::vector<CardSpec> cards = {once({R("MAT_RHO"), R("Refer_Rho")}), once({I("MAT_Iflag")}),
                                   when_field(iform10, {R("PEXT"), R("MAT_NU"), R("MAT_Lamda")})};
    for (int phase = 0; phase < 3; ++phase) {
        cards.push_back(when_field(iform10, {R("MAT_ALPHA_Iflg10_phas"), R("MAT_RHO_Iflg10_phas"), R("MAT_E_Iflg10_phas"),
                                       R("MAT_P_Iflg10_phas"), R("MAT_C0_Iflg10_phas")}));
        cards.push_back(when_field(iform10, {R("MAT_C1_Iflg10_phas"), R("MAT_C2_Iflg10_phas"), R("MAT_C3_Iflg10_phas"),
                                       R("MAT_C4_Iflg10_phas"), R("MAT_C5_Iflg10_phas")}));
        cards.push_back(when_field(iform10, {R("MLAW51_G10"), R("Sigma_Y10"), R("BB10"), R("LAW51_N10")}));
        cards.push_back(when_field(iform10, {R("CC10"), R("e010")}));
        cards.push_back(when_field(iform10, {R("CM10"), R("T10_10"), R("T_melt10"), R("T_limit10"), R("Rhocv10")}));
        cards.push_back(when_field(iform10, {R("E_max10"), R("sigma_max10"), R("K_A1"), R("K_B1")}));
    }
    cards.push_back(when_field(iform10, {R("MLAW51_ALPHA"), R("MLAW51_Rho"), R("MLAW51_E0"), R("MLAW51_Pmin"),
                                   R("MLAW51_C0")}));
    cards.push_back(when_field(iform10, {R("MLAW51_B1"), R("MLAW51_B2"), R("MLAW51_R1"), R("MLAW51_R2"), R("MLAW51_W")}));
    cards.push_back(when_field(iform10, {R("MLAW51_D"), R("MLAW51_PCJ"), R("MLAW51_C14"), S(), I("MAT_IBFRAC")}));
    cards.push_back(opaque());  // the other forms' cards
    rad::FormatSpec format;
    format.since = 0;
    format.cards = std::move(cards);
    return {format};
}

// An EOS of one card (mat_EOS.cfg, radioss2018 to radioss2612: the same cells; Refer_Rho, fifth in
// 2018 to 2024, is read but never tested here).
std::vector<rad::FormatSpec> eos_layout(std::initializer_list<FieldSpec> fields) {
    rad::FormatSpec format;
    format.since = 0;
    format.cards = {once(fields), opaque()};
    return {format};
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
    // LAW51 (hm_read_mat51.F), Iform 10: an explosive phase (its density given) needs C14 and D. A line
    // deleted from the block leaves its last card blank: message 99 on the block's last line. The reader
    // returns after the first of the two, so D is tested only when C14 passes.
    constexpr std::string_view explosive = "MAT_Iflag=10&MLAW51_Rho>0";
    laws.push_back({{"/MAT/LAW51", "/MAT/MULTIMAT"},
                    "mat051/hm_read_mat51.F",
                    {{"MLAW51_C14", "C14", Allowed::Positive, 0.0, explosive, 99,
                      "BULK MODULUS C14 MUST BE PROVIDED FOR UNREACTED EXPLOSIVE", "mat051/hm_read_mat51.F:786"},
                     {"MLAW51_D", "D", Allowed::Positive, 0.0, "MAT_Iflag=10&MLAW51_Rho>0&MLAW51_C14>0", 99,
                      "DETONATION VELOCITY MUST BE INPUT FOR EXPLOSIVE SUBMATERIAL", "mat051/hm_read_mat51.F:791"}},
                    law51_layout()});

    // EOS (materials/eos/hm_read_eos_*.F): message 67 "ERROR IN EOS DEFINITION" with its own text.
    laws.push_back({{"/EOS/MURNAGHAN"},
                    "hm_read_eos_murnaghan.F",
                    {{"EOS_K0", "K0", Allowed::Positive, 0.0, {}, 67, "K0 MUST BE POSITIVE",
                      "hm_read_eos_murnaghan.F:102"}},
                    eos_layout({R("EOS_K0"), R("K1"), R("LAW5_P0"), R("LAW5_PSH"), R("Refer_Rho")})});
    laws.push_back({{"/EOS/STIFF-GAS"},
                    "hm_read_eos_stiffened_gas.F",
                    {{"Gamma", "Gamma", Allowed::AboveOne, 0.0, {}, 67, "GAMMA MUST BE GREATER THAN 1.0",
                      "hm_read_eos_stiffened_gas.F:112"}},
                    eos_layout({R("Gamma"), R("LAW5_P0"), R("LAW5_PSH"), R("P_star"), R("Refer_Rho")})});
    laws.push_back({{"/EOS/IDEAL-GAS", "/EOS/IDEAL-GAS-VE"},
                    "hm_read_eos_ideal_gas.F",
                    {{"Gamma", "Gamma", Allowed::AboveOne, 0.0, {}, 67,
                      "SPECIFIC HEAT RATIO (GAMMA) MUST BE GREATER THAN 1.0", "hm_read_eos_ideal_gas.F:135"},
                     {"LAW5_P0", "P0", Allowed::Positive, 0.0, {}, 67, "INITIAL PRESSURE MUST BE POSITIVE",
                      "hm_read_eos_ideal_gas.F:129"}},
                    eos_layout({R("Gamma"), R("LAW5_P0"), R("LAW5_PSH"), R("T_Initial"), R("Refer_Rho")})});
    // NASG: Gamma second on its first card in every format (b, Gamma, P_star, E0 in 2612).
    laws.push_back({{"/EOS/NASG"},
                    "hm_read_eos_nasg.F",
                    {{"Gamma_Constant", "Gamma", Allowed::AboveOne, 0.0, {}, 67, "GAMMA MUST BE GREATER THAN 1.0",
                      "hm_read_eos_nasg.F:117"}},
                    eos_layout({R("b_Covolume"), R("Gamma_Constant")})});

    // /PROP/TYPE6 (properties/solid/hm_read_prop06.F): an orthotropy of REFPLANE 23 or 24 needs a vector V.
    // Its other errors name ids (1037 SPHPART_ID, 137 the skew: the REF rules) or depend on /DEF_SOLID (563).
    // /PROP/TYPE14 (hm_read_prop14.F: 1037, 131, 563) and /PROP/TYPE34 (hm_read_prop34.F: 137; MASS <= 0
    // is warning 138) have no value check of one field; they have no row.
    const auto null_vector = [](std::string_view plane) {
        return StarterCheck{"Vx", "V", Allowed::NotZero, 0.0, plane, 1918,
                            "INVALID ZERO REFERENCE VECTOR WITH IP=23 OR 24", "solid/hm_read_prop06.F:418"};
    };
    laws.push_back({{"/PROP/TYPE6", "/PROP/SOL_ORTH"},
                    "solid/hm_read_prop06.F",
                    {null_vector("REFPLANE=23&Vy=0&Vz=0"), null_vector("REFPLANE=24&Vy=0&Vz=0")}});
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
// clang-format on
