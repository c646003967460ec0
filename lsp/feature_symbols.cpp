// textDocument/documentSymbol: the outline of one file: its keyword blocks, *PART blocks with a
// child per part (id and heading), Radioss headers with their titles.
#include <fmt/format.h>
#include <map>

#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

// LSP SymbolKind values.
constexpr int kStructSymbol = 23;  // a keyword block
constexpr int kObjectSymbol = 19;  // a part

nlohmann::json line_range(const grammar::SourceMap& sources, grammar::FileId file, std::uint32_t first,
                          std::uint32_t last) {
    const auto length = static_cast<std::uint32_t>(sources.line_text(file, last).size());
    return {{"start", position_json(sources, file, first, 1)}, {"end", position_json(sources, file, last, length + 1)}};
}

// The model's sections, materials, EOS and parts of one file by the line of their id field, so
// each block finds its own with a lookup (decks of thousands of parts have thousands of blocks).
struct FileItems {
    std::map<std::uint32_t, std::string> ids;                // line -> "id 3"
    std::multimap<std::uint32_t, const model::Part*> parts;  // line -> part

    FileItems(const model::Model& m, grammar::FileId file) {
        auto add = [&](const grammar::Span& span, const std::string& id) {
            if (span.file == file) ids.emplace(span.line, fmt::format("id {}", id));
        };
        for (const auto& x : m.sections) add(x.span, x.id);
        for (const auto& x : m.materials) add(x.span, x.id);
        for (const auto& x : m.equations_of_state) add(x.span, x.id);
        for (const auto& p : m.parts)
            if (p.span.file == file) parts.emplace(p.span.line, &p);
    }
};

nlohmann::json dyna_symbol(const CheckedDeck& deck, const grammar::Block& block, const FileItems& items) {
    const auto& raw = deck.result.deck;
    const std::uint32_t last = block_last_line(raw, block);
    nlohmann::json symbol = {{"name", display_text(block.keyword)},
                             {"kind", kStructSymbol},
                             {"range", line_range(raw.sources, block.span.file, block.span.line, last)},
                             {"selectionRange", range_json(raw.sources, block.span)}};
    std::string detail;
    if (auto id = items.ids.lower_bound(block.span.line); id != items.ids.end() && id->first <= last)
        detail = id->second;
    if (block.keyword.rfind("*PART", 0) == 0) {
        nlohmann::json children = nlohmann::json::array();
        for (auto it = items.parts.lower_bound(block.span.line); it != items.parts.end() && it->first <= last; ++it) {
            const model::Part& part = *it->second;
            // The heading line comes before the PID card (*PART: heading + data per part).
            const std::uint32_t first = part.span.line > block.span.line + 1 ? part.span.line - 1 : part.span.line;
            children.push_back({{"name", fmt::format("part {}", part.id)},
                                {"detail", display_text(part.heading)},
                                {"kind", kObjectSymbol},
                                {"range", line_range(raw.sources, block.span.file, first, part.span.line)},
                                {"selectionRange", range_json(raw.sources, part.span)}});
        }
        if (children.size() == 1)
            detail = children[0]["name"].get<std::string>() + " " + children[0]["detail"].get<std::string>();
        if (!children.empty()) symbol["children"] = std::move(children);
    }
    if (!detail.empty()) symbol["detail"] = display_text(detail);
    return symbol;
}

nlohmann::json radioss_symbol(const CheckedDeck& deck, const grammar::Block& block, int version) {
    const auto& raw = deck.result.deck;
    const std::uint32_t last = block_last_line(raw, block);
    nlohmann::json symbol = {{"name", display_text(block.arguments.empty() ? block.keyword : block.arguments)},
                             {"kind", block.keyword.rfind("/PART", 0) == 0 ? kObjectSymbol : kStructSymbol},
                             {"range", line_range(raw.sources, block.span.file, block.span.line, last)},
                             {"selectionRange", range_json(raw.sources, block.span)}};
    const auto* spec = radioss_keyword(block);
    if (spec && spec->title && block.line_count > 0 && !grammar::radioss::is_v4(version)) {
        std::string title(grammar::trim_blanks(raw.text(*raw.begin_lines(block))));
        if (!title.empty()) symbol["detail"] = display_text(title);
    }
    return symbol;
}

}  // namespace

nlohmann::json document_symbols(const CheckedDeck& deck, grammar::FileId file) {
    nlohmann::json out = nlohmann::json::array();
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return out;
    const bool radioss = deck.result.model.radioss.has_value();
    const int version = radioss ? model::radioss_version(raw) : 0;
    const FileItems items(deck.result.model, file);
    for (const grammar::Block& block : raw.blocks) {
        if (block.span.file != file || block.keyword.empty()) continue;
        out.push_back(radioss ? radioss_symbol(deck, block, version) : dyna_symbol(deck, block, items));
    }
    return out;
}

}  // namespace sphdeck::lsp
