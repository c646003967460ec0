// *SET_NODE_LIST and *SET_PART_LIST (lsdyna-sph-cards.md §20).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

// Card 1 of both list sets: id, four attributes, solver (ITS only on node sets).
std::vector<FieldSpec> set_header(std::string_view what) {
    return {
        {.name = "SID", .column = 1, .width = 10, .type = I, .required = true, .doc = what},
        {.name = "DA1", .column = 11, .width = 10, .type = F, .default_value = 0.0, .doc = "first attribute"},
        {.name = "DA2", .column = 21, .width = 10, .type = F, .default_value = 0.0, .doc = "second attribute"},
        {.name = "DA3", .column = 31, .width = 10, .type = F, .default_value = 0.0, .doc = "third attribute"},
        {.name = "DA4", .column = 41, .width = 10, .type = F, .default_value = 0.0, .doc = "fourth attribute"},
        {.name = "SOLVER",
         .column = 51,
         .width = 10,
         .type = A,
         .doc = "solver the set belongs to",
         .default_text = "MECH",
         .text_choices = {"MECH", "CESE", "ICFD"}},
    };
}

// Eight ids of 10 columns per line, repeated until the next keyword.
CardSpec node_ids() {
    return {
        .name = "Ids",
        .fields =
            {
                {.name = "NID1", .column = 1, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID2", .column = 11, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID3", .column = 21, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID4", .column = 31, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID5", .column = 41, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID6", .column = 51, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID7", .column = 61, .width = 10, .type = I, .doc = "node id"},
                {.name = "NID8", .column = 71, .width = 10, .type = I, .doc = "node id"},
            },
        .repeat = CardRepeat::Repeated,
        .doc = "eight node ids per line",
    };
}

CardSpec part_ids() {
    return {
        .name = "Ids",
        .fields =
            {
                {.name = "PID1", .column = 1, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID2", .column = 11, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID3", .column = 21, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID4", .column = 31, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID5", .column = 41, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID6", .column = 51, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID7", .column = 61, .width = 10, .type = I, .doc = "part id"},
                {.name = "PID8", .column = 71, .width = 10, .type = I, .doc = "part id"},
            },
        .repeat = CardRepeat::Repeated,
        .doc = "eight part ids per line",
    };
}

// `_GENERATE`: ranges (first, last) instead of the id list.
OptionSpec generate_option() {
    return {
        .suffix = "GENERATE",
        .cards_after = {{
            .name = "Ranges",
            .fields =
                {
                    {.name = "B1BEG", .column = 1, .width = 10, .type = I, .doc = "first id of range 1"},
                    {.name = "B1END", .column = 11, .width = 10, .type = I, .doc = "last id of range 1"},
                    {.name = "B2BEG", .column = 21, .width = 10, .type = I, .doc = "first id of range 2"},
                    {.name = "B2END", .column = 31, .width = 10, .type = I, .doc = "last id of range 2"},
                    {.name = "B3BEG", .column = 41, .width = 10, .type = I, .doc = "first id of range 3"},
                    {.name = "B3END", .column = 51, .width = 10, .type = I, .doc = "last id of range 3"},
                    {.name = "B4BEG", .column = 61, .width = 10, .type = I, .doc = "first id of range 4"},
                    {.name = "B4END", .column = 71, .width = 10, .type = I, .doc = "last id of range 4"},
                },
            .repeat = CardRepeat::Repeated,
            .doc = "four id ranges per line",
        }},
        .replaces_last = 1,
        .doc = "ranges of ids (first, last) instead of an id list",
    };
}

KeywordSchema set_node_list() {
    std::vector<FieldSpec> header = set_header("node set id");
    header.push_back({.name = "ITS",
                      .column = 61,
                      .width = 10,
                      .type = I,
                      .default_value = 1,
                      .choices = {{1, "tied contact coupling"}, {2, "solid-in-shell immersed coupling"}, {3, ""}},
                      .doc = "two-scale co-simulation coupling type"});
    return {
        .name = "*SET_NODE_LIST",
        .aliases = {"*SET_NODE"},  // pydyna codegen/manifest.json
        .cards = {{.name = "Card 1", .fields = std::move(header)}, node_ids()},
        .doc = "node set: eight node ids per line",
        .options = {title_option(), generate_option()},
    };
}

KeywordSchema set_part_list() {
    return {
        .name = "*SET_PART_LIST",
        // The manual's *SET_PART_{OPTION} takes a blank option for the list, as *SET_NODE does; pydyna
        // has no *SET_PART class (its manifest aliases *SET_NODE only). Corpus: pydyna's
        // run/case-keywords/projectile.k writes *SET_PART with an SID card and a PID card.
        .aliases = {"*SET_PART"},
        .cards = {{.name = "Card 1", .fields = set_header("part set id")}, part_ids()},
        .doc = "part set: eight part ids per line",
        .options = {title_option(), generate_option()},
    };
}

}  // namespace

std::vector<KeywordSchema> set_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(set_node_list());
    k.push_back(set_part_list());
    return k;
}

}  // namespace sphdeck::keywords::tables
