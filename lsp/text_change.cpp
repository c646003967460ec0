#include "lsp/text_change.hpp"

#include <cstring>
#include <string_view>
#include <utility>

namespace sphdeck::lsp {
namespace {
// The byte offset in `text` of an LSP position.
std::size_t byte_offset_of(std::string_view text, TextPosition position) {
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

std::optional<ChangeEvent> read_change(const nlohmann::json& change) {
    if (!change.is_object()) return std::nullopt;
    const auto new_text = change.find("text");
    if (new_text == change.end() || !new_text->is_string()) return std::nullopt;
    ChangeEvent out;
    out.text = &new_text->get_ref<const std::string&>();
    const auto range = change.find("range");
    if (range == change.end() || range->is_null()) return out;
    if (!range->is_object() || !range->contains("start") || !range->contains("end")) return std::nullopt;
    if (!parse_position(range->at("start"), out.start) || !parse_position(range->at("end"), out.end))
        return std::nullopt;
    if (out.end.line < out.start.line || (out.end.line == out.start.line && out.end.character < out.start.character))
        std::swap(out.start, out.end);
    out.whole = false;
    return out;
}

std::optional<std::string> changed_text(std::string_view text, const nlohmann::json& change) {
    const auto event = read_change(change);
    if (!event) return std::nullopt;
    const std::string& inserted = *event->text;
    if (event->whole) return inserted;
    std::size_t from = byte_offset_of(text, event->start), to = byte_offset_of(text, event->end);
    if (from > to) std::swap(from, to);
    // One pass: the text before, the new text, the text after.
    std::string out;
    out.reserve(text.size() - (to - from) + inserted.size());
    out.append(text.substr(0, from)).append(inserted).append(text.substr(to));
    return out;
}

bool apply_change(std::string& text, const nlohmann::json& change) {
    auto changed = changed_text(text, change);
    if (!changed) return false;
    text = std::move(*changed);
    return true;
}

}  // namespace sphdeck::lsp
