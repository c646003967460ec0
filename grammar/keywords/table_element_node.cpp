// *ELEMENT_SPH and *NODE (lsdyna-sph-cards.md §3, §4; lsdyna-format.md §3, §6).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

KeywordSchema element_sph() {
    return {
        .name = "*ELEMENT_SPH",
        .cards = {{
            .name = "Particle",
            .fields =
                {
                    {.name = "NID",
                     .column = 1,
                     .width = 8,
                     .type = I,
                     .required = true,
                     .doc = "node id; also the element id"},
                    {.name = "PID", .column = 9, .width = 8, .type = I, .required = true, .doc = "part id"},
                    {.name = "MASS",
                     .column = 17,
                     .width = 16,
                     .type = F,
                     .default_value = 0.0,  // pydyna; 0 or blank is a massless particle (lint error)
                     .doc = "> 0: particle mass; < 0: |MASS| is the particle volume"},
                    // Sources disagree on NEND's width (lsdyna-sph-cards.md §3, §24): PRIMER and the
                    // converter notes quoting R16 give I8 (columns 33-40); pydyna and LS-PrePost
                    // 4.10.5 output give 10 (33-42). Chosen: read 33-42; non-blank columns 41-42
                    // get a warning elsewhere.
                    {.name = "NEND",
                     .column = 33,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "optional: generate particles NID..NEND with the same PID and MASS"},
                },
            .repeat = CardRepeat::Repeated,
            .doc = "one line per particle: 2I8, E16, I8 (I10: 2I10, E16, I10)",
        }},
        .doc = "SPH particles: node, part and mass (or volume) per particle",
        .options = {{
            .suffix = "VOLUME",
            .doc = "MASS is always a volume (same effect as a negative MASS)",
        }},
    };
}

KeywordSchema node() {
    return {
        .name = "*NODE",
        .cards = {{
            .name = "Node",
            .fields =
                {
                    {.name = "NID", .column = 1, .width = 8, .type = I, .required = true, .doc = "node id"},
                    {.name = "X", .column = 9, .width = 16, .type = F, .default_value = 0.0, .doc = "x coordinate"},
                    {.name = "Y", .column = 25, .width = 16, .type = F, .default_value = 0.0, .doc = "y coordinate"},
                    {.name = "Z", .column = 41, .width = 16, .type = F, .default_value = 0.0, .doc = "z coordinate"},
                    // Values 0-7 are UNVERIFIED: no range here.
                    {.name = "TC",
                     .column = 57,
                     .width = 8,
                     .type = I,
                     .default_value = 0,
                     .doc = "translational constraint code"},
                    {.name = "RC",
                     .column = 65,
                     .width = 8,
                     .type = I,
                     .default_value = 0,
                     .doc = "rotational constraint code"},
                },
            .repeat = CardRepeat::Repeated,
            .doc = "one line per node: I8, 3E16, 2I8 (I10: I10, 3E16, 2I10; long: I20, 3E20, 2I20)",
        }},
        .doc = "nodes: id and coordinates",
    };
}

}  // namespace

std::vector<KeywordSchema> element_node_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(element_sph());
    k.push_back(node());
    return k;
}

}  // namespace sphdeck::keywords::tables
