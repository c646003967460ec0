// LSP positions: 0-based lines and characters counted in UTF-16 code units (the protocol's default
// encoding), against sphdeck's 1-based lines and byte columns. Decks are mostly ASCII, where the two
// columns agree; a UTF-8 title or comment shifts them, and bytes that are not UTF-8 count one each.
#pragma once

#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "text/source_map.hpp"

namespace sphdeck::lsp {

struct TextPosition {
    std::uint32_t line = 0;       // 0-based
    std::uint32_t character = 0;  // 0-based, UTF-16 code units
};

// The UTF-16 offset of byte offset `byte` (0-based) in `line_text`; past the end counts as the end.
std::uint32_t utf16_offset(std::string_view line_text, std::uint32_t byte);
// The byte offset (0-based) of UTF-16 offset `character` in `line_text`; past the end gives its size.
std::uint32_t byte_offset(std::string_view line_text, std::uint32_t character);

// {"line":..,"character":..} of a 1-based line and byte column of `file`.
nlohmann::json position_json(const grammar::SourceMap& sources, grammar::FileId file, std::uint32_t line,
                             std::uint32_t column);
// The LSP Range of a span ({"start":..,"end":..}); an invalid span gives the first line's start.
nlohmann::json range_json(const grammar::SourceMap& sources, const grammar::Span& span);

// Position -> 1-based line and byte column of `file` (what Span holds).
struct LineColumn {
    std::uint32_t line = 1;
    std::uint32_t column = 1;
};
LineColumn line_column(const grammar::SourceMap& sources, grammar::FileId file, TextPosition position);

// Reads {"line":..,"character":..}; false when the object is not one.
bool parse_position(const nlohmann::json& json, TextPosition& out);

}  // namespace sphdeck::lsp
