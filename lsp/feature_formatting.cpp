// textDocument/formatting and textDocument/rangeFormatting: the edits of `sphdeck format`
// (edit/format_deck.hpp) for the file of the request, as LSP TextEdits. The editor's own options (tab
// size, spaces) do not apply: a deck's columns are fixed by its keywords.
#include "edit/format_deck.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {
namespace {

nlohmann::json text_edits(const CheckedDeck& deck, grammar::FileId file, std::uint32_t first_line,
                          std::uint32_t last_line) {
    nlohmann::json out = nlohmann::json::array();
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return out;
    const edit::FormatResult formatted = edit::format_deck(raw, deck.result.diagnostics, {file}, {});
    for (const diag::TextEdit& e : formatted.edits)
        if (e.span.line >= first_line && e.span.line <= last_line)
            out.push_back({{"range", range_json(raw.sources, e.span)}, {"newText", e.replacement}});
    return out;
}

}  // namespace

nlohmann::json formatting(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    return text_edits(deck, file, 1, UINT32_MAX);
}

nlohmann::json range_formatting(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    TextPosition start, end;
    if (!params.is_object() || !params.contains("range") || !params["range"].is_object() ||
        !params["range"].contains("start") || !params["range"].contains("end") ||
        !parse_position(params["range"]["start"], start) || !parse_position(params["range"]["end"], end))
        return nlohmann::json::array();
    // A range that ends at the start of a line does not take that line.
    const std::uint32_t last = end.character == 0 && end.line > start.line ? end.line : end.line + 1;
    return text_edits(deck, file, start.line + 1, last);
}

}  // namespace sphdeck::lsp
