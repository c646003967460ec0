// textDocument/completion: keyword names at the start of a line (`*` LS-DYNA, `/` Radioss), the
// allowed values of an enum field, the ids of the right kind in an id field.
#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <set>
#include <string>

#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/parameters.hpp"
#include "engine/id_lookup.hpp"
#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

namespace rad = grammar::radioss;

constexpr std::size_t kMaxItems = 200;  // a list longer than this is cut and marked incomplete

// LSP CompletionItemKind values.
constexpr int kKeyword = 14;
constexpr int kEnumMember = 20;
constexpr int kReference = 18;
constexpr int kValue = 12;

struct Edit {
    std::uint32_t line = 0;            // 0-based
    std::uint32_t start = 0, end = 0;  // UTF-16 characters
};

nlohmann::json completion_item(std::string label, int kind, std::string detail, const Edit& edit,
                               std::string documentation = {}) {
    nlohmann::json out = {{"label", label},
                          {"kind", kind},
                          {"textEdit",
                           {{"range",
                             {{"start", {{"line", edit.line}, {"character", edit.start}}},
                              {"end", {{"line", edit.line}, {"character", edit.end}}}}},
                            {"newText", label}}}};
    if (!detail.empty()) out["detail"] = std::move(detail);
    if (!documentation.empty()) out["documentation"] = std::move(documentation);
    return out;
}

nlohmann::json list(nlohmann::json items, bool incomplete) {
    return {{"isIncomplete", incomplete}, {"items", std::move(items)}};
}

bool starts_with_upper(std::string_view name, std::string_view prefix) {
    if (name.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(name[i])) != std::toupper(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

// Keyword names starting with the typed text: hand-written tables first (with their docs), then
// the generated layouts; sorted by name within each, at most kMaxItems.
nlohmann::json keyword_items(std::string_view typed, const Edit& edit) {
    std::vector<std::pair<std::string, std::string>> found;  // name, doc
    std::set<std::string, std::less<>> seen;
    auto add = [&](std::string_view name, std::string_view doc) {
        if (!starts_with_upper(name, typed) || seen.count(name)) return;
        seen.emplace(name);
        found.emplace_back(std::string(name), std::string(doc));
    };
    for (const auto& k : keywords::all_keywords()) {
        add(k.name, k.doc);
        for (auto alias : k.aliases) add(alias, k.doc);
    }
    const std::size_t hand = found.size();
    for (const auto& e : keywords::generated::layouts()) add(e.name, "layout generated from pydyna");
    std::sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(hand));
    nlohmann::json items = nlohmann::json::array();
    for (std::size_t i = 0; i < found.size() && i < kMaxItems; ++i) {
        auto it = completion_item(found[i].first, kKeyword, found[i].second, edit);
        it["sortText"] = fmt::format("{:05}", i);
        items.push_back(std::move(it));
    }
    return list(std::move(items), found.size() > kMaxItems);
}

nlohmann::json radioss_keyword_items(std::string_view typed, const Edit& edit) {
    nlohmann::json items = nlohmann::json::array();
    for (const auto& k : rad::all_keywords()) {
        if (starts_with_upper(k.name, typed))
            items.push_back(completion_item(std::string(k.name), kKeyword, std::string(k.summary), edit));
        for (auto alias : k.aliases)
            if (starts_with_upper(alias, typed))
                items.push_back(completion_item(std::string(alias), kKeyword, std::string(k.summary), edit));
    }
    // The other keywords of the starter's CFG files (grammar/radioss/generated/), after the tables'.
    std::size_t generated = 0;
    for (const auto& k : rad::generated::keywords()) {
        if (!starts_with_upper(k.name, typed)) continue;
        std::size_t segments = 0;
        if (const auto* hand = rad::find_keyword(k.name, &segments); hand && hand->name == k.name) continue;
        if (++generated > 200) break;  // a bare '/' matches them all
        items.push_back(
            completion_item(std::string(k.name), kKeyword, k.engine ? "engine keyword" : "starter keyword", edit));
    }
    return list(std::move(items), generated > 200);
}

// The ids of `kind` the deck defines, with their titles.
void id_items(const CheckedDeck& deck, const std::string& kind, const Edit& edit, nlohmann::json& items) {
    std::set<std::string> seen;
    for (const auto& use : definitions_of(deck.result, kind)) {
        if (!seen.insert(use.id).second) continue;
        if (items.size() >= kMaxItems) break;
        items.push_back(
            completion_item(display_text(use.id), kReference, display_text(describe(deck.result, use)), edit));
    }
}

// The token being typed: the run of characters that are not blanks or commas around the cursor.
Edit token_edit(std::string_view text, std::uint32_t line0, std::uint32_t byte) {
    std::uint32_t start = std::min<std::uint32_t>(byte, static_cast<std::uint32_t>(text.size()));
    while (start > 0 && text[start - 1] != ' ' && text[start - 1] != ',' && text[start - 1] != '\t') --start;
    std::uint32_t end = start;
    while (end < text.size() && text[end] != ' ' && text[end] != ',' && text[end] != '\t') ++end;
    end = std::max(end, std::min<std::uint32_t>(byte, static_cast<std::uint32_t>(text.size())));
    return {line0, utf16_offset(text, start), utf16_offset(text, end)};
}

nlohmann::json field_items(const CheckedDeck& deck, const grammar::Block& block, std::uint32_t line,
                           std::uint32_t column, const Edit& edit) {
    const auto& raw = deck.result.deck;
    // The card line under the cursor, or the card a line typed since would be read as.
    const std::optional<CardAt> at = card_at(raw, block, line, false);
    if (!at) return list(nlohmann::json::array(), false);
    const auto index = at->field_at_cursor(column);
    if (!index) return list(nlohmann::json::array(), false);
    const keywords::FieldSpec& field = at->dyna_card->fields[*index];
    nlohmann::json items = nlohmann::json::array();
    for (const auto& c : field.choices) {
        auto choice =
            completion_item(std::to_string(c.value), kEnumMember, std::string(c.meaning), edit,
                            fmt::format("{} = {}: {}{}", field.name, c.value, c.meaning,
                                        c.since.empty() ? std::string() : fmt::format(" (since {})", c.since)));
        // The meaning beside the value in the list itself, in the manual's order.
        choice["labelDetails"] = {{"description", display_text(c.meaning)}};
        choice["sortText"] = fmt::format("{:05}", items.size());
        items.push_back(std::move(choice));
    }
    for (auto word : field.text_choices)
        items.push_back(completion_item(std::string(word), kValue, std::string(field.name), edit));
    const std::optional<keywords::KeywordMatch> match = decodable_match(block);
    if (auto role = dyna_id_role(match->schema->name, field); role && !role->defines)
        id_items(deck, role->kind, edit, items);
    return list(std::move(items), false);
}

nlohmann::json radioss_field_items(const CheckedDeck& deck, const grammar::Block& block, std::uint32_t line,
                                   std::uint32_t column, const Edit& edit) {
    nlohmann::json items = nlohmann::json::array();
    const std::optional<CardAt> at = card_at(deck.result.deck, block, line, true);
    if (!at || !at->radioss->card) return list(std::move(items), false);
    const auto index = at->field_at_cursor(column);
    if (!index) return list(std::move(items), false);
    if (auto role = radioss_id_role(*at->radioss->values[*index].spec)) id_items(deck, role->kind, edit, items);
    return list(std::move(items), false);
}

}  // namespace

nlohmann::json completion(const CheckedDeck& deck, grammar::FileId file, TextPosition position) {
    const auto& raw = deck.result.deck;
    if (file >= raw.sources.size()) return list(nlohmann::json::array(), false);
    const LineColumn at = line_column(raw.sources, file, position);
    const std::string_view text = raw.sources.line_text(file, at.line);
    const std::uint32_t byte = at.column - 1;
    const std::string_view typed = text.substr(0, std::min<std::size_t>(byte, text.size()));
    const bool radioss = deck.result.model.radioss.has_value();
    const bool keyword_start = !typed.empty() && (typed[0] == '*' || (radioss && typed[0] == '/')) &&
                               typed.find_first_of(" ,\t") == std::string_view::npos;
    if (keyword_start) {
        // The whole name is replaced, also when the cursor stands inside it.
        std::size_t end = text.find_first_of(" ,\t", typed.size());
        if (end == std::string_view::npos) end = text.size();
        const Edit edit{position.line, 0, utf16_offset(text, static_cast<std::uint32_t>(end))};
        return radioss ? radioss_keyword_items(typed, edit) : keyword_items(typed, edit);
    }
    if (!text.empty() && (text[0] == '$' || text[0] == '#')) return list(nlohmann::json::array(), false);
    const grammar::Block* block = block_at(raw, file, at.line);
    if (!block || at.line == block->span.line) return list(nlohmann::json::array(), false);
    const Edit edit = token_edit(text, position.line, byte);
    return radioss ? radioss_field_items(deck, *block, at.line, at.column, edit)
                   : field_items(deck, *block, at.line, at.column, edit);
}

}  // namespace sphdeck::lsp
