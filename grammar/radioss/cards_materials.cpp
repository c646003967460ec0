// Materials: /MAT/<law>/mat_ID. sphdeck reads what the density, the mass and the sound speed
// need, each card where the starter's CFG files put it (hm_cfg_files/config/CFG/radiossNNNN/MAT/):
// the density card of every law, E and nu of LAW23, C0-C3 of the older LAW3 and LAW6 forms, every card
// of LAW2 (Johnson-Cook, the QA decks' most common law, whose CFG cards the generator cannot follow).
// Any other law is read by its generated cards (grammar/radioss/generated/) where the CFG lays it out;
// the rest of a law no table lays out is kept as text, not checked.
#include "grammar/radioss/cards_build.hpp"

namespace sphdeck::grammar::radioss::detail {

using namespace build;

namespace {

// A line sphdeck keeps without reading its fields.
CardSpec skipped_line() { return once({L("")}); }

// E and nu, then the law's own fields (Iflag, Eps_p_max...), kept as text and not checked.
CardSpec young_poisson() { return once({R("E"), R("nu"), L("")}); }

// Card 1 of nearly every law: `%20lg%20lg` RHO_I RHO_0 (`%16lg` in V4), e.g. elast_1.cfg.
CardSpec density() { return once({R("RHO_I"), R("RHO_0")}); }

KeywordSpec law(std::string_view name, std::vector<std::string_view> aliases, std::string_view summary,
                std::vector<FormatSpec> formats) {
    return {.name = name,
            .aliases = std::move(aliases),
            .family = "/MAT",
            .summary = summary,
            .formats = std::move(formats)};
}

}  // namespace

void add_material_keywords(std::vector<KeywordSpec>& out) {
    // Any other law: the density card, then text; a law the CFG files lay out is checked by its
    // generated cards instead (/MAT/VOID: RHO, E, Nu in 20-column cells, matl_void0.cfg).
    out.push_back({.name = "/MAT",
                   .summary = "material: law and density (the law's other cards are not checked)",
                   .fallback = true,
                   .formats = {{0, {density(), opaque()}}}});

    // LAW23 (matl23_plas_dama.cfg): E and nu, then text. The other elastic-plastic laws (LAW1, 4, 21, 22, 24,
    // 27, 32, 36, 44, 49, PLAS_ZERIL) are read whole by their generated cards (the generic /MAT above gives way
    // to them, the model reads MAT_RHO, MAT_E and MAT_NU); /MAT/PLAS_DAM, a name no CFG file gives, keeps this
    // table with LAW23.
    const FormatSpec elastic{0, {density(), young_poisson(), opaque()}};
    out.push_back(law("/MAT/LAW23", {"/MAT/PLAS_DAM"}, "elastic-plastic material: density, E, nu", {elastic}));

    // LAW2, Johnson-Cook (matl2_plas_johns.cfg, FORMAT radioss51 to radioss2025): after E and nu, the yield
    // card (a, b, n, or from format 140 SIG_Y, UTS, EUTS when Iflag is 1), the strain-rate card (Chard from
    // format 100) and the thermal card (T_max from 2025). V4 decks (16-column cells): E and nu, then text.
    const CardCondition by_uts = +[](const EarlierValues& e) { return e("Iflag") == 1; };
    const CardCondition by_abn = +[](const EarlierValues& e) { return e("Iflag") != 1; };
    const auto johnson_cook = [&](CardSpec elastic_card, bool iflag, bool chard, bool tmax) {
        std::vector<CardSpec> cards = {density(), std::move(elastic_card)};
        const CardSpec abn = once({R("a"), R("b"), R("n"), R("EPS_p_max"), R("SIG_max0")});
        if (iflag) {
            cards.push_back(
                when(once({R("SIG_Y"), R("UTS"), R("EUTS"), R("EPS_p_max"), R("SIG_max0")}), by_uts, "Iflag 1"));
            cards.push_back(when(abn, by_abn, "Iflag not 1"));
        } else {
            cards.push_back(abn);
        }
        cards.push_back(chard ? once({R("c"), R("EPS_DOT_0"), I("ICC"), I("Fsmooth"), R("F_cut"), R("Chard")})
                              : once({R("c"), R("EPS_DOT_0"), I("ICC"), I("Fsmooth"), R("F_cut")}));
        cards.push_back(tmax ? once({R("m"), R("T_melt"), R("rhoC_p"), R("T_r"), R("T_max")})
                             : once({R("m"), R("T_melt"), R("rhoC_p"), R("T_r")}));
        return cards;
    };
    out.push_back(law("/MAT/LAW2", {"/MAT/LAW02", "/MAT/PLAS_JOHNS"}, "Johnson-Cook elastic-plastic material",
                      {{2025, johnson_cook(once({R("E"), R("nu"), I("Iflag"), I("VP"), R("Pmin")}), true, true, true)},
                       {2023, johnson_cook(once({R("E"), R("nu"), I("Iflag"), I("VP")}), true, true, false)},
                       {140, johnson_cook(once({R("E"), R("nu"), I("Iflag")}), true, true, false)},
                       {100, johnson_cook(once({R("E"), R("nu")}), false, true, false)},
                       {51, johnson_cook(once({R("E"), R("nu")}), false, false, false)},
                       {0, {density(), young_poisson(), opaque()}}}));

    // LAW3 (matl3_hydpla.cfg): E nu, the yield card, then C0-C3 up to format 2017; from 2018 the
    // fourth card is Pmin and the coefficients moved to /EOS.
    out.push_back(
        law("/MAT/LAW3", {"/MAT/LAW03", "/MAT/HYDPLA"}, "hydrodynamic elastic-plastic material",
            {{2018, {density(), young_poisson(), opaque()}},
             {0, {density(), young_poisson(), skipped_line(), once({R("C0"), R("C1"), R("C2"), R("C3")}), opaque()}}}));
    // LAW6 (mat_law6.cfg): the viscosity card, then C0-C3 up to format 2017 (2018: /EOS).
    out.push_back(law("/MAT/LAW6", {"/MAT/LAW06", "/MAT/HYD_VISC", "/MAT/HYDRO", "/MAT/K-EPS"},
                      "hydrodynamic viscous fluid",
                      {{2018, {density(), opaque()}},
                       {0, {density(), skipped_line(), once({R("C0"), R("C1"), R("C2"), R("C3")}), opaque()}}}));

    // Laws whose first card is no density, each read by its own first card (a scan of the first
    // CARD after the title in every MAT/*.cfg of hm_cfg_files/config/CFG, latest format of each):
    // /MAT/GAS/<MASS|MOLE|PREDEF>/id (mat_gas.cfg: a gas name or a molar mass), LAW51
    // (mat_law51.cfg: Iflag and material ids from format 120), LAW151 (mat_law151.cfg: material ids
    // and volume fractions), LAW20 (matl20_bimat.cfg: the two material ids), LAW37
    // (matl37_biphas.cfg: Psh, then the liquid's and the gas's cards) and PLAS_PREDEF
    // (mat_plas_predef.cfg: `%20s` the name of a predefined material, STEEL, HSS, UHSS, AA5182,
    // AA6082-T6, PA6GF30 or PPT40, whose density and moduli the reader assigns).
    out.push_back(law("/MAT/GAS", {}, "gas of a monitored volume (not checked)", {{0, {opaque()}}}));
    out.push_back(law("/MAT/LAW51", {"/MAT/MULTIMAT"}, "multi-material ALE law (not checked)", {{0, {opaque()}}}));
    out.push_back(law("/MAT/LAW151", {"/MAT/MULTIFLUID"}, "multi-fluid law (not checked)", {{0, {opaque()}}}));
    out.push_back(
        law("/MAT/LAW20", {"/MAT/BIMAT"}, "bi-material law of two material ids (not checked)", {{0, {opaque()}}}));
    out.push_back(law("/MAT/LAW37", {"/MAT/BIPHAS"}, "liquid-gas law: Psh, then the phases' cards (not checked)",
                      {{0, {once({R("Psh")}), opaque()}}}));
    out.push_back(law("/MAT/PLAS_PREDEF", {}, "predefined elastic-plastic material named by its first card",
                      {{0, {once({T20("Material_Name")}), opaque()}}}));
}

}  // namespace sphdeck::grammar::radioss::detail
