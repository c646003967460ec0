// Internal to grammar/keywords/: the per-family schema tables and the helpers they share.
// Each table_*.cpp returns its keywords; registry.cpp concatenates them once.
#pragma once

#include <vector>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::keywords::tables {

// Short type names so a table row reads like the manual: `.type = I`.
inline constexpr FieldType I = FieldType::Integer;
inline constexpr FieldType F = FieldType::Real;
inline constexpr FieldType A = FieldType::Text;
inline constexpr FieldType IA = FieldType::Label;
inline constexpr FieldType U = FieldType::Unused;

// Columns the manual leaves unused (kept so that long and I10 offsets stay right).
inline FieldSpec unused(std::uint16_t column, std::uint16_t width = 10) {
    return {.name = "-", .column = column, .width = width, .type = U, .doc = "unused"};
}

// The 0/1 switch found on many cards.
inline std::vector<EnumChoice> off_on(std::string_view off = "off", std::string_view on = "on") {
    return {{0, off}, {1, on}};
}

// `_TITLE`: one A80 line right after the keyword line (lsdyna-format.md §11).
inline CardSpec title_card() {
    return {
        .name = "Title",
        .fields = {{.name = "TITLE", .column = 1, .width = 80, .type = A, .doc = "title of the entity"}},
        .doc = "title line of the _TITLE option",
    };
}

inline OptionSpec title_option() {
    return {
        .suffix = "TITLE",
        .cards_before = {title_card()},
        .doc = "adds a title line (A80) before the data cards",
    };
}

// `_ID`: an I10 id and an A70 heading before the data cards; the layout is per keyword
// (lsdyna-format.md §11), this is the common one.
inline OptionSpec id_option(std::string_view id_name, std::string_view id_doc) {
    return {
        .suffix = "ID",
        .cards_before = {{
            .name = "ID card",
            .fields =
                {
                    {.name = id_name, .column = 1, .width = 10, .type = I, .doc = id_doc},
                    {.name = "HEADING", .column = 11, .width = 70, .type = A, .doc = "heading"},
                },
            .doc = "id card of the _ID option",
        }},
        .doc = "adds an id card (I10 id + A70 heading) before the data cards",
    };
}

std::vector<KeywordSchema> control_keywords();
std::vector<KeywordSchema> section_keywords();
std::vector<KeywordSchema> element_node_keywords();
std::vector<KeywordSchema> part_keywords();
std::vector<KeywordSchema> boundary_keywords();
std::vector<KeywordSchema> define_keywords();
std::vector<KeywordSchema> material_keywords();
std::vector<KeywordSchema> eos_keywords();
std::vector<KeywordSchema> set_keywords();
std::vector<KeywordSchema> parameter_include_keywords();
std::vector<KeywordSchema> deck_keywords();  // *KEYWORD, *TITLE, *COMMENT, *END
std::vector<KeywordSchema> load_initial_keywords();

}  // namespace sphdeck::keywords::tables
