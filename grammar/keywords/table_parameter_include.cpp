// *PARAMETER and *INCLUDE families (lsdyna-sph-cards.md §21, §22; lsdyna-format.md §13, §14).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

// Options shared by *PARAMETER and *PARAMETER_EXPRESSION (lsdyna-format.md §14.4).
OptionSpec parameter_local_option() {
    return {
        .suffix = "LOCAL",
        .doc = "parameters visible only in this file and the files it includes (971 R5+)",
    };
}

OptionSpec noecho_option() { return {.suffix = "NOECHO", .doc = "values are not echoed to the output files"}; }

KeywordSchema parameter() {
    return {
        .name = "*PARAMETER",
        .cards = {{
            .name = "Pairs",
            .fields =
                {
                    {.name = "PRMR1", .column = 1, .width = 10, .type = A, .doc = "type letter (R, I, C) and name"},
                    {.name = "VAL1", .column = 11, .width = 10, .type = A, .doc = "value"},
                    {.name = "PRMR2", .column = 21, .width = 10, .type = A, .doc = "type letter (R, I, C) and name"},
                    {.name = "VAL2", .column = 31, .width = 10, .type = A, .doc = "value"},
                    {.name = "PRMR3", .column = 41, .width = 10, .type = A, .doc = "type letter (R, I, C) and name"},
                    {.name = "VAL3", .column = 51, .width = 10, .type = A, .doc = "value"},
                    {.name = "PRMR4", .column = 61, .width = 10, .type = A, .doc = "type letter (R, I, C) and name"},
                    {.name = "VAL4", .column = 71, .width = 10, .type = A, .doc = "value"},
                },
            .repeat = CardRepeat::Repeated,
            .doc = "up to four name/value pairs per line",
        }},
        .doc = "named values referenced as &name in later fields",
        .options =
            {
                parameter_local_option(),
                {.suffix = "MUTABLE", .doc = "parameters that may be redefined"},
                noecho_option(),
                // pydyna: PRMR, VAL, PRTYP per line (PRTYP names an id kind: SSID, PSID, PID...).
                // Layout UNVERIFIED against the manual.
                {
                    .suffix = "TYPE",
                    .cards_after = {{
                        .name = "Typed",
                        .fields =
                            {
                                {.name = "PRMR", .column = 1, .width = 10, .type = A, .doc = "type letter and name"},
                                {.name = "VAL", .column = 11, .width = 10, .type = A, .doc = "value"},
                                {.name = "PRTYP",
                                 .column = 21,
                                 .width = 10,
                                 .type = A,
                                 .doc = "kind of id the value is"},
                            },
                        .repeat = CardRepeat::Repeated,
                    }},
                    .replaces_last = 1,
                    .doc = "one parameter per line with the kind of id it holds (PRTYP)",
                },
            },
    };
}

KeywordSchema parameter_expression() {
    return {
        .name = "*PARAMETER_EXPRESSION",
        .cards = {{
            .name = "Expression",
            .fields =
                {
                    {.name = "PRMR", .column = 1, .width = 10, .type = A, .doc = "type letter (R, I, C) and name"},
                    {.name = "EXPRESSION", .column = 11, .width = 70, .type = A, .doc = "expression"},
                },
            .repeat = CardRepeat::Repeated,
            .doc = "one parameter per line; lines with columns 1-10 blank continue the expression",
        }},
        .doc = "parameters defined by expressions of numbers and other parameters",
        .options = {parameter_local_option(), noecho_option()},
    };
}

KeywordSchema parameter_duplication() {
    return {
        .name = "*PARAMETER_DUPLICATION",
        .cards = {{
            .name = "Card 1",
            .fields = {{
                .name = "DFLAG",
                .column = 1,
                .width = 10,
                .type = I,
                .default_value = 1,
                .choices =
                    {
                        {1, "warning; the new definition is ignored"},
                        {2, "warning; the new definition is accepted"},
                        {3, "error"},
                        {4, "accepted silently"},
                        {5, "ignored silently"},
                    },
                .doc = "what a second definition of a parameter name does",
            }},
        }},
        .doc = "policy for parameters defined twice",
    };
}

CardSpec file_name_card(std::string_view name, std::string_view doc) {
    return {
        .name = "File",
        .fields = {{.name = name, .column = 1, .width = 80, .type = A, .required = true, .doc = doc}},
        .doc = "a line ending in \" +\" continues on the next (236 characters in all)",
    };
}

KeywordSchema include() {
    return {
        .name = "*INCLUDE",
        .cards = {file_name_card("FILENAME", "file to read here")},
        .doc = "reads another file in place of this keyword",
    };
}

KeywordSchema include_path() {
    return {
        .name = "*INCLUDE_PATH",
        .cards = {{
            .name = "Path",
            .fields = {{.name = "PATH", .column = 1, .width = 80, .type = A, .doc = "directory searched for includes"}},
            .repeat = CardRepeat::Repeated,
        }},
        .doc = "directories searched for *INCLUDE files, also from nested includes",
    };
}

KeywordSchema include_path_relative() {
    return {
        .name = "*INCLUDE_PATH_RELATIVE",
        .cards = {{
            .name = "Path",
            // pydyna gives this a single 512-character field; we keep the A80 card of *INCLUDE_PATH.
            .fields =
                {{.name = "PATH", .column = 1, .width = 80, .type = A, .doc = "directory relative to the main file"}},
            .repeat = CardRepeat::Repeated,
        }},
        .doc = "include search directories relative to the main file's folder",
    };
}

KeywordSchema include_transform() {
    return {
        .name = "*INCLUDE_TRANSFORM",
        .cards =
            {
                file_name_card("FILENAME", "file to read with offsets and scaling"),
                {
                    .name = "Offsets",
                    .fields =
                        {
                            {.name = "IDNOFF",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "node id offset"},
                            {.name = "IDEOFF",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "element id offset"},
                            {.name = "IDPOFF",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "part id offset"},
                            {.name = "IDMOFF",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "material id offset"},
                            {.name = "IDSOFF",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "set id offset"},
                            {.name = "IDFOFF",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "function / curve id offset"},
                            {.name = "IDDOFF",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "*DEFINE_* id offset"},
                        },
                },
                {
                    .name = "Labels",
                    .fields =
                        {
                            {.name = "IDROFF",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "offset of the other id kinds"},
                            unused(11),
                            {.name = "PREFIX", .column = 21, .width = 10, .type = A, .doc = "prefix for labels"},
                            {.name = "SUFFIX", .column = 31, .width = 10, .type = A, .doc = "suffix for labels"},
                        },
                },
                {
                    .name = "Scaling",
                    .fields =
                        {
                            {.name = "FCTMAS",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "mass scale factor"},
                            {.name = "FCTTIM",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "time scale factor"},
                            {.name = "FCTLEN",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "length scale factor"},
                            {.name = "FCTTEM", .column = 31, .width = 10, .type = A, .doc = "temperature conversion"},
                            {.name = "INCOUT1",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 1,
                             .choices = off_on(),
                             .doc = "write the transformed data to a file"},
                            {.name = "FCTCHG", .column = 51, .width = 10, .type = F, .doc = "charge scale factor"},
                        },
                },
                {
                    .name = "Transform",
                    .fields = {{
                        .name = "TRANID",
                        .column = 1,
                        .width = 10,
                        .type = I,
                        .default_value = 0,
                        .doc = "*DEFINE_TRANSFORMATION id",
                    }},
                },
            },
        .doc = "include with id offsets, unit scaling and a transformation (OpenRadioss ignores the scaling)",
    };
}

}  // namespace

std::vector<KeywordSchema> parameter_include_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(parameter());
    k.push_back(parameter_expression());
    k.push_back(parameter_duplication());
    k.push_back(include());
    k.push_back(include_path());
    k.push_back(include_path_relative());
    k.push_back(include_transform());
    return k;
}

}  // namespace sphdeck::keywords::tables
