#include "lsp/text_change.hpp"

#include <cstring>
#include <string_view>
#include <utility>

#include "lsp/text_position.hpp"

namespace sphdeck::lsp {
namespace {
// The byte offset in `text` of an LSP position.
std::size_t offset_of(const std::string& text, TextPosition position) {
    std::size_t line_start = 0;
    for (std::uint32_t line = 0; line < position.line; ++line) {
        const void* newline = std::memchr(text.data() + line_start, '\n', text.size() - line_start);
        if (!newline) return text.size();  // past the last line: its end
        line_start = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
    }
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    if (line_end > line_start && text[line_end - 1] == '\r') --line_end;  // "\r\n": the '\r' ends the line too
    const std::string_view line(text.data() + line_start, line_end - line_start);
    return line_start + byte_offset(line, position.character);
}
}  // namespace

bool apply_change(std::string& text, const nlohmann::json& change) {
    if (!change.is_object()) return false;
    const auto new_text = change.find("text");
    if (new_text == change.end() || !new_text->is_string()) return false;
    const auto range = change.find("range");
    if (range == change.end() || range->is_null()) {
        text = new_text->get<std::string>();
        return true;
    }
    if (!range->is_object() || !range->contains("start") || !range->contains("end")) return false;
    TextPosition start, end;
    if (!parse_position(range->at("start"), start) || !parse_position(range->at("end"), end)) return false;
    std::size_t from = offset_of(text, start), to = offset_of(text, end);
    if (from > to) std::swap(from, to);
    text.replace(from, to - from, new_text->get_ref<const std::string&>());
    return true;
}

}  // namespace sphdeck::lsp
