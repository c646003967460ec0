// *SECTION_SPH and its options (lsdyna-sph-cards.md §2).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

// Card 1 is the same for all variants (pydyna). "inferred" zero_is_default: Ansys Workbench
// (2025 R2) writes CSLH = HMIN = HMAX = DEATH = 0 and those decks run.
CardSpec section_sph_card1() {
    return {
        .name = "Card 1",
        .fields =
            {
                {.name = "SECID",
                 .column = 1,
                 .width = 10,
                 .type = IA,
                 .required = true,
                 .doc = "section id, referenced by *PART"},
                {.name = "CSLH",
                 .column = 11,
                 .width = 10,
                 .type = F,
                 .default_value = 1.2,
                 .zero_is_default = true,  // inferred
                 .doc = "smoothing-length constant (1.05-1.3; not used when SPHINI is given)"},
                {.name = "HMIN",
                 .column = 21,
                 .width = 10,
                 .type = F,
                 .default_value = 0.2,
                 .zero_is_default = true,  // inferred
                 .doc = "scale factor of the minimum smoothing length (h >= HMIN h0)"},
                {.name = "HMAX",
                 .column = 31,
                 .width = 10,
                 .type = F,
                 .default_value = 2.0,
                 .zero_is_default = true,  // inferred
                 .doc = "scale factor of the maximum smoothing length (h <= HMAX h0)"},
                {.name = "SPHINI",
                 .column = 41,
                 .width = 10,
                 .type = F,
                 .default_value = 0.0,
                 .zero_is_default = true,  // documented: 0 = computed by LS-DYNA
                 .doc = "initial smoothing length; 0 = computed"},
                {.name = "DEATH",
                 .column = 51,
                 .width = 10,
                 .type = F,
                 .default_value = 1.0e20,
                 .zero_is_default = true,  // inferred
                 .doc = "time at which the SPH approximation stops for this section"},
                {.name = "START",
                 .column = 61,
                 .width = 10,
                 .type = F,
                 .default_value = 0.0,
                 .doc = "time at which the SPH approximation starts"},
                {.name = "SPHKERN",
                 .column = 71,
                 .width = 10,
                 .type = I,
                 .default_value = 0,
                 .choices =
                     {
                         {0, "cubic spline"},
                         {1, "quintic spline (HMAX >= 3 recommended; FORM 0, 1, 9, 10 only)"},
                         // 2 and 3 come from newer editions (secondary source; pydyna's enum).
                         {2, "quadratic (3D)"},
                         {3, "quartic B-spline (3D)"},
                     },
                 .doc = "smoothing kernel",
                 .since = "R11.1"},
            },
    };
}

CardSpec ellipse_card() {
    return {
        .name = "Card 2",
        .fields =
            {
                {.name = "HXCSLH", .column = 1, .width = 10, .type = F, .doc = "CSLH for the x direction"},
                {.name = "HYCSLH", .column = 11, .width = 10, .type = F, .doc = "CSLH for the y direction"},
                {.name = "HZCSLH", .column = 21, .width = 10, .type = F, .doc = "CSLH for the z direction"},
                {.name = "HXINI", .column = 31, .width = 10, .type = F, .doc = "initial smoothing length in x"},
                {.name = "HYINI", .column = 41, .width = 10, .type = F, .doc = "initial smoothing length in y"},
                {.name = "HZINI", .column = 51, .width = 10, .type = F, .doc = "initial smoothing length in z"},
            },
        .doc = "anisotropic smoothing (ASPH, FORM 9/10)",
    };
}

}  // namespace

std::vector<KeywordSchema> section_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back({
        .name = "*SECTION_SPH",
        .cards = {section_sph_card1()},
        .doc = "SPH section: smoothing-length controls and kernel",
        .options =
            {
                title_option(),
                {
                    .suffix = "ELLIPSE",
                    // LS-DYNA 971 spelled the option _TENSOR (same extra card); renamed in R8.0.
                    .aliases = {"TENSOR"},
                    .cards_after = {ellipse_card()},
                    .doc = "adds card 2 with per-direction smoothing lengths (ASPH, FORM 9/10)",
                },
                {
                    .suffix = "INTERACTION",
                    .doc = "section takes part in the inter-part approximation when CONT = 1 "
                           "(cards beyond card 1 UNVERIFIED)",
                },
                {
                    .suffix = "USER",
                    .doc = "user-defined SPH section (cards beyond card 1 UNVERIFIED)",
                },
            },
    });
    return k;
}

}  // namespace sphdeck::keywords::tables
