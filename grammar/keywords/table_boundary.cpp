// SPH boundary keywords (lsdyna-sph-cards.md §6-§8).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

// A plane given by the tail and head of its normal (symmetry and non-reflecting planes).
std::vector<FieldSpec> plane_fields(std::optional<double> def) {
    return {
        {.name = "VTX", .column = 1, .width = 10, .type = F, .default_value = def, .doc = "x of the normal's tail"},
        {.name = "VTY", .column = 11, .width = 10, .type = F, .default_value = def, .doc = "y of the normal's tail"},
        {.name = "VTZ", .column = 21, .width = 10, .type = F, .default_value = def, .doc = "z of the normal's tail"},
        {.name = "VHX", .column = 31, .width = 10, .type = F, .default_value = def, .doc = "x of the normal's head"},
        {.name = "VHY", .column = 41, .width = 10, .type = F, .default_value = def, .doc = "y of the normal's head"},
        {.name = "VHZ", .column = 51, .width = 10, .type = F, .default_value = def, .doc = "z of the normal's head"},
    };
}

KeywordSchema symmetry_plane() {
    return {
        .name = "*BOUNDARY_SPH_SYMMETRY_PLANE",
        .cards = {{
            .name = "Plane",
            .fields = plane_fields(0.0),  // pydyna defaults
            .repeat = CardRepeat::Repeated,
            .doc = "one plane per line; the normal (tail to head) points into the body",
        }},
        .doc = "symmetry planes for SPH (ghost particles; memory set by ISYMP of *CONTROL_SPH)",
    };
}

KeywordSchema flow() {
    return {
        .name = "*BOUNDARY_SPH_FLOW",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "ID",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .doc = "set or part id, kind given by STYP"},
                            {.name = "STYP",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 1,
                             .choices = {{1, "part set"}, {2, "part"}, {3, "node set"}},
                             .doc = "kind of ID"},
                            // "0 is not valid": no default, so blank or 0 is an error.
                            {.name = "DOF",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .choices = {{1, "x"}, {2, "y"}, {3, "z"}, {4, "along vector VID"}},
                             .doc = "direction of the prescribed motion"},
                            {.name = "VAD",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "velocity"}, {1, "acceleration"}, {2, "displacement"}},
                             .doc = "kind of prescribed motion"},
                            {.name = "LCID",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .doc = "load curve of the prescribed motion"},
                            {.name = "SF",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "load-curve scale factor"},
                            {.name = "DEATH",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e20,
                             .zero_is_default = true,  // "EQ.0.0: default set to 10^20"
                             .doc = "time the condition ends"},
                            {.name = "BIRTH",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "time the condition starts"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "NID",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .doc = "fixed node marking where particles are activated"},
                            {.name = "VID",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .doc = "*DEFINE_VECTOR id, used when DOF = 4"},
                        },
                },
            },
        .doc = "inflow of SPH particles with a prescribed motion",
    };
}

KeywordSchema non_reflecting() {
    return {
        .name = "*BOUNDARY_SPH_NON_REFLECTING",
        .cards = {{
            .name = "Plane",
            .fields = plane_fields(std::nullopt),  // no defaults in pydyna
            .doc = "a plane given by the tail and head of its normal",
        }},
        .doc = "non-reflecting plane for SPH",
    };
}

}  // namespace

std::vector<KeywordSchema> boundary_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(symmetry_plane());
    k.push_back(flow());
    k.push_back(non_reflecting());
    return k;
}

}  // namespace sphdeck::keywords::tables
