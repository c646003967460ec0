// Applies LSP TextDocumentContentChangeEvents to a buffer: a whole new text, or a range (UTF-16
// positions, lines split at '\n' as the deck readers split them) replaced by new text.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "lsp/text_position.hpp"

namespace sphdeck::lsp {

// A change event read: the text it inserts and the range it replaces (none: the whole text), the
// range taken in order when reversed. nullopt when `change` is not a change event.
struct ChangeEvent {
    const std::string* text = nullptr;  // inside `change`
    bool whole = true;
    TextPosition start, end;
};
std::optional<ChangeEvent> read_change(const nlohmann::json& change);

// Applies one change to `text`. Positions past a line's end or past the last line clamp to them,
// a reversed range is taken in order. False (and `text` unchanged) when `change` is not a change event.
bool apply_change(std::string& text, const nlohmann::json& change);

// The same, building the changed text in one pass from `text` (left as it is: a check may still read
// it); nullopt when `change` is not a change event.
std::optional<std::string> changed_text(std::string_view text, const nlohmann::json& change);

}  // namespace sphdeck::lsp
