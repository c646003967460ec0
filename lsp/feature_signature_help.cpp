// textDocument/signatureHelp: while a card line is typed, the card's fields as a signature
// ("*SECTION_SPH Card 1: SECID CSLH HMIN ...") with the field under the cursor active, blank part of
// a field included; the field's doc, type and columns as the parameter's documentation.
#include <fmt/format.h>
#include <string>

#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {
using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

namespace rad = grammar::radioss;

struct SignatureParameter {
    std::string name;
    std::string documentation;
};

nlohmann::json signature(std::string title, const std::vector<SignatureParameter>& parameters,
                         std::optional<std::size_t> active) {
    std::string label = title + ":";
    nlohmann::json params = nlohmann::json::array();
    for (const SignatureParameter& p : parameters) {
        label += ' ';
        // Offsets into the label (UTF-16; field names are ASCII).
        params.push_back({{"label", {label.size(), label.size() + p.name.size()}},
                          {"documentation", display_text(p.documentation)}});
        label += p.name;
    }
    nlohmann::json sig = {{"label", display_text(label)}, {"parameters", std::move(params)}};
    nlohmann::json out = {{"signatures", {std::move(sig)}}, {"activeSignature", 0}};
    if (active) out["activeParameter"] = *active;
    return out;
}

nlohmann::json dyna_signature(const grammar::RawDeck& raw, const grammar::Block& block, std::uint32_t line,
                              std::uint32_t column) {
    // The decoded card line, or the card a line typed since would be read as.
    const std::optional<CardAt> at = card_at(raw, block, line, false);
    if (!at || at->dyna_card->unknown_layout) return nullptr;
    const keywords::CardSpec* card = at->dyna_card;
    std::optional<std::size_t> index = at->field_under(column);
    if (!index) index = at->typed_slot(column);
    std::vector<SignatureParameter> parameters;
    std::optional<std::size_t> active;
    for (std::size_t i = 0; i < card->fields.size(); ++i) {
        const keywords::FieldSpec& f = card->fields[i];
        if (f.type == keywords::FieldType::Unused) continue;
        if (index && *index == i) active = parameters.size();
        std::string doc = fmt::format("**{}**: {}", f.name, f.doc);
        if (auto columns = dyna_field_columns(*card, block.format, i))
            doc +=
                fmt::format(" (columns {}-{}, type {})", columns->first, columns->end - 1, keywords::to_string(f.type));
        parameters.push_back({std::string(f.name), std::move(doc)});
    }
    return signature(fmt::format("{} {}", block.keyword, card->name.empty() ? "card" : card->name), parameters, active);
}

nlohmann::json radioss_signature(const grammar::RawDeck& raw, const grammar::Block& block, std::uint32_t line,
                                 std::uint32_t column) {
    const rad::KeywordSpec* spec = radioss_keyword(block);
    const std::optional<CardAt> at = card_at(raw, block, line, true);
    if (!spec || !at || !at->radioss->card) return nullptr;
    const RadiossCard* card = &*at->radioss;
    const auto index = at->field_under(column);
    std::vector<SignatureParameter> parameters;
    std::optional<std::size_t> active;
    for (std::size_t i = 0; i < card->card->fields.size(); ++i) {
        const rad::FieldSpec& f = card->card->fields[i];
        if (f.cell == rad::Cell::Skip || f.cell == rad::Cell::Skip20) continue;
        if (index && *index == i) active = parameters.size();
        parameters.push_back({std::string(f.name), fmt::format("**{}**: {}", f.name, f.note)});
    }
    return signature(std::string(spec->name), parameters, active);
}

}  // namespace

nlohmann::json signature_help(const CheckedDeck& deck, grammar::FileId file, TextPosition position) {
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return nullptr;
    const LineColumn at = line_column(raw.sources, file, position);
    const std::string_view text = raw.sources.line_text(file, at.line);
    if (!text.empty() && (text[0] == '$' || text[0] == '#' || text[0] == '*' || text[0] == '/')) return nullptr;
    const grammar::Block* block = block_at(raw, file, at.line);
    if (!block || at.line == block->span.line) return nullptr;
    return deck.result.model.radioss ? radioss_signature(raw, *block, at.line, at.column)
                                     : dyna_signature(raw, *block, at.line, at.column);
}

}  // namespace sphdeck::lsp
