// Equations of state used with SPH (lsdyna-sph-cards.md §18).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

FieldSpec eos_id() {
    return {.name = "EOSID", .column = 1, .width = 10, .type = IA, .required = true, .doc = "equation-of-state id"};
}

KeywordSchema eos_gruneisen() {
    return {
        .name = "*EOS_GRUNEISEN",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            eos_id(),
                            {.name = "C",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "intercept of the us-up line (bulk sound speed)"},
                            {.name = "S1", .column = 21, .width = 10, .type = F, .doc = "first slope coefficient"},
                            {.name = "S2", .column = 31, .width = 10, .type = F, .doc = "second slope coefficient"},
                            {.name = "S3", .column = 41, .width = 10, .type = F, .doc = "third slope coefficient"},
                            {.name = "GAMMA0", .column = 51, .width = 10, .type = F, .doc = "Gruneisen gamma"},
                            {.name = "A",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .doc = "first-order volume correction to GAMMA0"},
                            {.name = "E0", .column = 71, .width = 10, .type = F, .doc = "initial internal energy"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "V0", .column = 1, .width = 10, .type = F, .doc = "initial relative volume"},
                            unused(11),
                            {.name = "LCID", .column = 21, .width = 10, .type = I, .doc = "energy-deposition curve"},
                        },
                },
            },
        .doc = "Mie-Gruneisen shock EOS (form 4)",
        .options = {title_option()},
    };
}

KeywordSchema eos_linear_polynomial() {
    return {
        .name = "*EOS_LINEAR_POLYNOMIAL",
        .cards =
            {
                {
                    .name = "Card 1",
                    // Defaults 0.0 each (pydyna).
                    .fields =
                        {
                            eos_id(),
                            {.name = "C0",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C1",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C2",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C3",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C4",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C5",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                            {.name = "C6",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "polynomial coefficient"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "E0", .column = 1, .width = 10, .type = F, .doc = "initial internal energy"},
                            {.name = "V0", .column = 11, .width = 10, .type = F, .doc = "initial relative volume"},
                        },
                },
            },
        .doc = "linear polynomial EOS (form 1)",
        .options = {title_option()},
    };
}

KeywordSchema eos_murnaghan() {
    return {
        .name = "*EOS_MURNAGHAN",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    eos_id(),
                    {.name = "GAMMA",
                     .column = 11,
                     .width = 10,
                     .type = F,
                     .required = true,
                     .doc = "exponent (often 7 for water)"},
                    {.name = "K0",
                     .column = 21,
                     .width = 10,
                     .type = F,
                     .required = true,
                     .doc = "reference stiffness; choose c0 = sqrt(GAMMA K0 / rho0) >= 10 v_max"},
                    {.name = "V0", .column = 31, .width = 10, .type = F, .doc = "initial relative volume"},
                },
        }},
        .doc = "Murnaghan EOS for weakly compressible fluids with SPH or ALE (form 19)",
        .options = {title_option()},
    };
}

}  // namespace

std::vector<KeywordSchema> eos_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(eos_gruneisen());
    k.push_back(eos_linear_polynomial());
    k.push_back(eos_murnaghan());
    return k;
}

}  // namespace sphdeck::keywords::tables
