// *PART and *HOURGLASS (lsdyna-sph-cards.md §5, §13).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

KeywordSchema part() {
    return {
        .name = "*PART",
        .cards =
            {
                {
                    .name = "Heading",
                    .fields = {{.name = "HEADING", .column = 1, .width = 70, .type = A, .doc = "part title"}},
                    .doc = "part title (A70)",
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "PID", .column = 1, .width = 10, .type = IA, .required = true, .doc = "part id"},
                            {.name = "SECID",
                             .column = 11,
                             .width = 10,
                             .type = IA,
                             .required = true,
                             .doc = "section id (*SECTION_SPH for particles)"},
                            {.name = "MID",
                             .column = 21,
                             .width = 10,
                             .type = IA,
                             .required = true,
                             .doc = "material id"},
                            {.name = "EOSID",
                             .column = 31,
                             .width = 10,
                             .type = IA,
                             .default_value = 0,
                             .doc = "equation-of-state id; 0 = none"},
                            {.name = "HGID",
                             .column = 41,
                             .width = 10,
                             .type = IA,
                             .default_value = 0,
                             .doc = "*HOURGLASS id; 0 = defaults (per-part Q1/Q2 for SPH)"},
                            {.name = "GRAV",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "gravity-initialisation flag"},
                            {.name = "ADPOPT", .column = 61, .width = 10, .type = I, .doc = "adaptivity option"},
                            {.name = "TMID",
                             .column = 71,
                             .width = 10,
                             .type = IA,
                             .default_value = 0,
                             .doc = "thermal material id"},
                        },
                },
            },
        .doc = "parts: per part a heading line and a card of section, material, EOS and hourglass ids",
        // Heading + data card per part, repeated until the next keyword (pydyna TableCardGroup).
        .repeat_group = 2,
    };
}

KeywordSchema hourglass() {
    return {
        .name = "*HOURGLASS",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "HGID",
                     .column = 1,
                     .width = 10,
                     .type = IA,
                     .default_value = 0,
                     .doc = "hourglass id, referenced by *PART HGID"},
                    {.name = "IHQ",
                     .column = 11,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .min = 0,
                     .max = 10,
                     .doc = "hourglass control type"},
                    {.name = "QM",
                     .column = 21,
                     .width = 10,
                     .type = F,
                     .default_value = 0.1,
                     .doc = "hourglass coefficient"},
                    {.name = "IBQ", .column = 31, .width = 10, .type = I, .doc = "unused"},
                    {.name = "Q1",
                     .column = 41,
                     .width = 10,
                     .type = F,
                     .default_value = 1.5,
                     .doc = "quadratic bulk viscosity for the part"},
                    {.name = "Q2",
                     .column = 51,
                     .width = 10,
                     .type = F,
                     .default_value = 0.06,
                     .doc = "linear bulk viscosity for the part"},
                    {.name = "QB",
                     .column = 61,
                     .width = 10,
                     .type = F,
                     .default_value = 0.1,
                     .doc = "hourglass coefficient for shell bending (VDC: viscous damping)",
                     .aliases = {"VDC"}},
                    {.name = "QW",
                     .column = 71,
                     .width = 10,
                     .type = F,
                     .default_value = 0.1,
                     .doc = "hourglass coefficient for shell warping"},
                },
            // Several hourglass sets may follow in one block.
            .repeat = CardRepeat::Repeated,
        }},
        .doc = "hourglass and per-part bulk-viscosity settings",
        .options = {title_option()},
    };
}

}  // namespace

std::vector<KeywordSchema> part_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(part());
    k.push_back(hourglass());
    return k;
}

}  // namespace sphdeck::keywords::tables
