// textDocument/foldingRange: one range per keyword block, and one per run of comment lines.
#include <cstring>

#include "engine/position_index.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
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
    // Comment runs: one pass over the file's text (a 2M-line deck is read line by line otherwise).
    const bool radioss = deck.result.model.radioss.has_value();
    const std::string_view text = raw.sources.file(file).text;
    std::uint32_t line = 1, run_start = 0, run_end = 0;  // run_start 0: no run open
    auto close_run = [&] {
        if (run_start != 0 && run_end > run_start)
            out.push_back({{"startLine", run_start - 1}, {"endLine", run_end - 1}, {"kind", "comment"}});
        run_start = 0;
    };
    for (std::size_t pos = 0; pos < text.size(); ++line) {
        const void* nl = std::memchr(text.data() + pos, '\n', text.size() - pos);
        const std::size_t end = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) : text.size();
        if (comment_line(text.substr(pos, std::min<std::size_t>(end - pos, 8)), radioss)) {
            if (run_start == 0) run_start = line;
            run_end = line;
        } else {
            close_run();
        }
        pos = end + 1;
    }
    close_run();
    return out;
}

}  // namespace sphdeck::lsp
