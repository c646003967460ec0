// Loads and initial conditions of SPH decks: *LOAD_BODY_X/Y/Z, *INITIAL_VELOCITY,
// *INITIAL_VELOCITY_NODE, *INITIAL_VELOCITY_GENERATION (layouts from pydyna load/load_body_x.py,
// boundary/initial_velocity.py, initial_velocity_node.py, initial_velocity_generation.py; see
// /work/shared/reference/lsdyna-keyword-layouts.json).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

KeywordSchema load_body(std::string_view name, std::string_view doc) {
    return {
        .name = name,
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "LCID",
                     .column = 1,
                     .width = 10,
                     .type = I,
                     .required = true,
                     .doc = "curve of the acceleration over time"},
                    {.name = "SF",
                     .column = 11,
                     .width = 10,
                     .type = F,
                     .default_value = 1.0,
                     .doc = "scale factor of LCID and LCIDDR"},
                    {.name = "LCIDDR",
                     .column = 21,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "curve for the dynamic-relaxation phase"},
                    {.name = "XC",
                     .column = 31,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "x of the centre of rotation"},
                    {.name = "YC",
                     .column = 41,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "y of the centre of rotation"},
                    {.name = "ZC",
                     .column = 51,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "z of the centre of rotation"},
                    {.name = "CID",
                     .column = 61,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "coordinate system of the acceleration"},
                },
        }},
        .doc = doc,
    };
}

std::vector<FieldSpec> velocity_fields() {
    return {
        {.name = "VX", .column = 1, .width = 10, .type = F, .default_value = 0.0, .doc = "velocity in x"},
        {.name = "VY", .column = 11, .width = 10, .type = F, .default_value = 0.0, .doc = "velocity in y"},
        {.name = "VZ", .column = 21, .width = 10, .type = F, .default_value = 0.0, .doc = "velocity in z"},
        {.name = "VXR", .column = 31, .width = 10, .type = F, .default_value = 0.0, .doc = "angular velocity about x"},
        {.name = "VYR", .column = 41, .width = 10, .type = F, .default_value = 0.0, .doc = "angular velocity about y"},
        {.name = "VZR", .column = 51, .width = 10, .type = F, .default_value = 0.0, .doc = "angular velocity about z"},
    };
}

std::vector<FieldSpec> exempted_velocity_fields() {
    return {
        {.name = "VXE",
         .column = 1,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "velocity in x of exempted nodes"},
        {.name = "VYE",
         .column = 11,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "velocity in y of exempted nodes"},
        {.name = "VZE",
         .column = 21,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "velocity in z of exempted nodes"},
        {.name = "VXRE",
         .column = 31,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "angular velocity about x, exempted"},
        {.name = "VYRE",
         .column = 41,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "angular velocity about y, exempted"},
        {.name = "VZRE",
         .column = 51,
         .width = 10,
         .type = F,
         .default_value = 0.0,
         .doc = "angular velocity about z, exempted"},
    };
}

KeywordSchema initial_velocity() {
    return {
        .name = "*INITIAL_VELOCITY",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "NSID",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "node set to initialise; 0 = all nodes"},
                            {.name = "NSIDEX",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "node set exempted (velocities of card 3)"},
                            {.name = "BOXID",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "only nodes of NSID inside this box"},
                            {.name = "IRIGID",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "overwrite rigid-body velocities"},
                            {.name = "ICID",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "local coordinate system of the velocities"},
                        },
                },
                {.name = "Card 2", .fields = velocity_fields()},
                {
                    .name = "Card 3",
                    .fields = exempted_velocity_fields(),
                    .present_if = CardCondition{.field = "NSIDEX", .compare = Compare::Greater, .value = 0.0},
                    .doc = "only when NSIDEX > 0",
                },
            },
        .doc = "initial translational and rotational velocity of a node set",
    };
}

// One node per line until the next keyword.
KeywordSchema initial_velocity_node() {
    std::vector<FieldSpec> fields = {
        {.name = "NID", .column = 1, .width = 10, .type = I, .required = true, .doc = "node"}};
    for (FieldSpec f : velocity_fields()) {
        f.column = static_cast<std::uint16_t>(f.column + 10);
        fields.push_back(f);
    }
    fields.push_back({.name = "ICID",
                      .column = 71,
                      .width = 10,
                      .type = I,
                      .default_value = 0,
                      .doc = "local coordinate system of the velocities"});
    return {
        .name = "*INITIAL_VELOCITY_NODE",
        .cards = {{.name = "Card 1", .fields = fields, .repeat = CardRepeat::Repeated, .doc = "one line per node"}},
        .doc = "initial translational and rotational velocity of single nodes",
    };
}

// Translation plus a rigid rotation about an axis, of a part, a part set or a node set: the
// velocity at x is (VX, VY, VZ) + OMEGA n x (x - c). Card pairs repeat until the next keyword.
KeywordSchema initial_velocity_generation() {
    return {
        .name = "*INITIAL_VELOCITY_GENERATION",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "ID", .column = 1, .width = 10, .type = I, .doc = "part, part set or node set"},
                            {.name = "STYP",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 1,
                             .choices = {{1, "part set"}, {2, "part"}, {3, "node set"}},
                             .doc = "what ID is"},
                            {.name = "OMEGA",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "angular velocity about the axis"},
                            {.name = "VX",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "translational velocity in x"},
                            {.name = "VY",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "translational velocity in y"},
                            {.name = "VZ",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "translational velocity in z"},
                            {.name = "IVATN",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "also set the nodes of constrained rigid bodies"},
                            {.name = "ICID",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "local coordinate system of the velocities"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "XC",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "x of a point on the axis"},
                            {.name = "YC",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "y of a point on the axis"},
                            {.name = "ZC",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "z of a point on the axis"},
                            {.name = "NX",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "x direction cosine of the axis; -999: NY and NZ are two nodes on the axis"},
                            {.name = "NY",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "y direction cosine of the axis"},
                            {.name = "NZ",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "z direction cosine of the axis"},
                            {.name = "PHASE",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "at once"}, {1, "after dynamic relaxation"}},
                             .doc = "when the velocities are applied"},
                            {.name = "IRIGID",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "overwrite rigid-body velocities"},
                        },
                },
            },
        .doc = "initial translational and rotational (about an axis) velocity of parts or nodes",
        .repeat_group = 2,
    };
}

}  // namespace

std::vector<KeywordSchema> load_initial_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(load_body("*LOAD_BODY_X", "body force (gravity) in x"));
    k.push_back(load_body("*LOAD_BODY_Y", "body force (gravity) in y"));
    k.push_back(load_body("*LOAD_BODY_Z", "body force (gravity) in z"));
    k.push_back(initial_velocity());
    k.push_back(initial_velocity_node());
    k.push_back(initial_velocity_generation());
    return k;
}

}  // namespace sphdeck::keywords::tables
