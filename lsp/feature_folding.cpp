// textDocument/foldingRange: one range per keyword block, and one per run of comment lines.
#include "lsp/deck_lookup.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {
namespace {

// A comment line of the deck's format: `$` in LS-DYNA decks; `#` (not `#include`) or `$` in Radioss.
bool comment_line(std::string_view text, bool radioss) {
    if (text.empty()) return false;
    if (text[0] == '$') return true;
    return radioss && text[0] == '#' && text.rfind("#include", 0) != 0 && text.rfind("#enddata", 0) != 0;
}

}  // namespace

nlohmann::json folding_ranges(const CheckedDeck& deck, grammar::FileId file) {
    nlohmann::json out = nlohmann::json::array();
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return out;
    for (const grammar::Block& block : raw.blocks) {
        if (block.span.file != file) continue;
        const std::uint32_t last = block_last_line(raw, block);
        if (last > block.span.line) out.push_back({{"startLine", block.span.line - 1}, {"endLine", last - 1}});
    }
    const bool radioss = deck.result.model.radioss.has_value();
    const std::uint32_t lines = raw.sources.line_count(file);
    for (std::uint32_t l = 1; l <= lines;) {
        if (!comment_line(raw.sources.line_text(file, l), radioss)) {
            ++l;
            continue;
        }
        std::uint32_t end = l;
        while (end + 1 <= lines && comment_line(raw.sources.line_text(file, end + 1), radioss)) ++end;
        if (end > l) out.push_back({{"startLine", l - 1}, {"endLine", end - 1}, {"kind", "comment"}});
        l = end + 1;
    }
    return out;
}

}  // namespace sphdeck::lsp
