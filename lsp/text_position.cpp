#include "lsp/text_position.hpp"

namespace sphdeck::lsp {
namespace {
// Length in bytes of the UTF-8 sequence led by `lead`, 1 for a byte that leads none (Latin-1 text).
std::uint32_t sequence_length(unsigned char lead) {
    if (lead >= 0xF0 && lead <= 0xF4) return 4;
    if (lead >= 0xE0) return lead <= 0xEF ? 3 : 1;
    if (lead >= 0xC2) return 2;
    return 1;
}

// Whether `text` holds a whole, well-formed sequence of `length` bytes at `at`.
bool well_formed(std::string_view text, std::size_t at, std::uint32_t length) {
    if (at + length > text.size()) return false;
    for (std::uint32_t k = 1; k < length; ++k)
        if ((static_cast<unsigned char>(text[at + k]) & 0xC0) != 0x80) return false;
    return true;
}

// Walks `text` one character at a time: bytes and UTF-16 units so far.
template <typename Stop>
void walk(std::string_view text, Stop stop) {
    std::uint32_t bytes = 0, units = 0;
    while (bytes < text.size()) {
        if (stop(bytes, units)) return;
        std::uint32_t length = sequence_length(static_cast<unsigned char>(text[bytes]));
        if (length > 1 && !well_formed(text, bytes, length)) length = 1;
        bytes += length;
        units += length == 4 ? 2 : 1;  // a 4-byte character is a surrogate pair in UTF-16
    }
    stop(bytes, units);
}
}  // namespace

std::uint32_t utf16_offset(std::string_view line_text, std::uint32_t byte) {
    std::uint32_t result = 0;
    walk(line_text, [&](std::uint32_t bytes, std::uint32_t units) {
        result = units;
        return bytes >= byte;
    });
    return result;
}

std::uint32_t byte_offset(std::string_view line_text, std::uint32_t character) {
    std::uint32_t result = 0;
    walk(line_text, [&](std::uint32_t bytes, std::uint32_t units) {
        result = bytes;
        return units >= character;
    });
    return result;
}

nlohmann::json position_json(const grammar::SourceMap& sources, grammar::FileId file, std::uint32_t line,
                             std::uint32_t column) {
    const std::uint32_t line0 = line > 0 ? line - 1 : 0;
    std::uint32_t character = column > 0 ? column - 1 : 0;
    if (file < sources.size() && line > 0) character = utf16_offset(sources.line_text(file, line), character);
    return {{"line", line0}, {"character", character}};
}

nlohmann::json range_json(const grammar::SourceMap& sources, const grammar::Span& span) {
    if (!span.valid()) return {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}};
    const std::uint32_t end = span.end_column > span.column ? span.end_column : span.column;
    return {{"start", position_json(sources, span.file, span.line, span.column)},
            {"end", position_json(sources, span.file, span.line, end)}};
}

LineColumn line_column(const grammar::SourceMap& sources, grammar::FileId file, TextPosition position) {
    LineColumn out;
    out.line = position.line + 1;
    out.column = position.character + 1;
    if (file < sources.size()) out.column = byte_offset(sources.line_text(file, out.line), position.character) + 1;
    return out;
}

bool parse_position(const nlohmann::json& json, TextPosition& out) {
    if (!json.is_object()) return false;
    const auto line = json.find("line");
    const auto character = json.find("character");
    if (line == json.end() || character == json.end()) return false;
    if (!line->is_number_integer() || !character->is_number_integer()) return false;
    const auto l = line->get<std::int64_t>(), c = character->get<std::int64_t>();
    if (l < 0 || c < 0 || l > 0xFFFFFFFE || c > 0xFFFFFFFE) return false;
    out.line = static_cast<std::uint32_t>(l);
    out.character = static_cast<std::uint32_t>(c);
    return true;
}

}  // namespace sphdeck::lsp
