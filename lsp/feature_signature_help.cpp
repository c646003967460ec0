// textDocument/signatureHelp: while a card line is typed, the card's fields as a signature
// ("*SECTION_SPH Card 1: SECID CSLH HMIN ...") with the field under the cursor active, blank part of
// a field included; the field's doc, type and columns as the parameter's documentation.
#include <fmt/format.h>
#include <string>

#include "grammar/fields.hpp"
#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"
#include "engine/field_at_column.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::lsp {
using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

namespace rad = grammar::radioss;

struct Parameter {
    std::string name;
    std::string documentation;
};

nlohmann::json signature(std::string title, const std::vector<Parameter>& parameters,
                         std::optional<std::size_t> active) {
    std::string label = title + ":";
    nlohmann::json params = nlohmann::json::array();
    for (const Parameter& p : parameters) {
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

// The field slot under `column` (1-based) when the line does not decode it: free format counts the
// commas before the cursor, fixed format takes the slot (or, at a slot's first column, the one the
// value being typed ends).
std::optional<std::size_t> typed_slot(const keywords::CardSpec& card, grammar::CardFormat format, std::string_view text,
                                      std::uint32_t column) {
    const std::uint32_t byte = column - 1;
    if (grammar::is_free_format(text)) {
        const std::string_view before = text.substr(0, std::min<std::size_t>(byte, text.size()));
        return static_cast<std::size_t>(std::count(before.begin(), before.end(), ','));
    }
    std::uint32_t at = byte;
    if (at > 0 && at <= text.size() && text[at - 1] != ' ') --at;  // still typing the value before
    const auto slots = keywords::layout(card, format);
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (at >= slots[i].start && at < slots[i].start + slots[i].width) return i;
    return std::nullopt;
}

nlohmann::json dyna_signature(const grammar::RawDeck& raw, const grammar::Block& block, std::uint32_t line,
                              std::uint32_t column) {
    const auto match = decodable_match(block);
    if (!match) return nullptr;
    const std::string_view text = raw.sources.line_text(block.span.file, line);
    const keywords::CardSpec* card = nullptr;
    std::optional<std::size_t> index;
    if (const grammar::CardLine* card_line = card_line_at(raw, block, line)) {
        if (auto decoded = dyna_card_at(raw, block, *card_line)) {
            card = decoded->card;
            index = dyna_field_at_column(*card, block.format, decoded->values, text, column);
        }
    } else {
        const grammar::CardLine* before = nullptr;
        for (const grammar::CardLine* l = raw.begin_lines(block); l != raw.end_lines(block) && l->line < line; ++l)
            before = l;
        card = dyna_card_after(raw, block, before);
    }
    if (!card || card->unknown_layout) return nullptr;
    if (!index) index = typed_slot(*card, block.format, text, column);
    const auto slots = keywords::layout(*card, block.format);
    std::vector<Parameter> parameters;
    std::optional<std::size_t> active;
    for (std::size_t i = 0; i < card->fields.size(); ++i) {
        const keywords::FieldSpec& f = card->fields[i];
        if (f.type == keywords::FieldType::Unused) continue;
        if (index && *index == i) active = parameters.size();
        std::string doc = fmt::format("**{}**: {}", f.name, f.doc);
        if (i < slots.size())
            doc += fmt::format(" (columns {}-{}, type {})", slots[i].start + 1, slots[i].start + slots[i].width,
                               keywords::to_string(f.type));
        parameters.push_back({std::string(f.name), std::move(doc)});
    }
    return signature(fmt::format("{} {}", block.keyword, card->name.empty() ? "card" : card->name), parameters, active);
}

nlohmann::json radioss_signature(const grammar::RawDeck& raw, const grammar::Block& block, std::uint32_t line,
                                 std::uint32_t column) {
    const rad::KeywordSpec* spec = radioss_keyword(block);
    const grammar::CardLine* card_line = card_line_at(raw, block, line);
    if (!spec || !card_line) return nullptr;
    auto card = radioss_card_at(raw, block, *card_line, model::radioss_version(raw));
    if (!card || !card->card) return nullptr;
    const auto index = radioss_field_at_column(*card, raw.text(*card_line), column);
    std::vector<Parameter> parameters;
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
