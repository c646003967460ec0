#include "cli/dump_cards.hpp"

#include <cmath>
#include <fmt/format.h>

#include "grammar/read_deck.hpp"
#include "engine/position_index.hpp"
#include "model/deck_check.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::cli {
namespace {

// A JSON string: plain ASCII copied, anything else through nlohmann-json (bytes that are not UTF-8
// become U+FFFD, as in the rest of the dump).
void append_string(std::string& out, std::string_view s) {
    bool plain = true;
    for (char c : s) plain = plain && c >= 0x20 && c < 0x7f && c != '"' && c != '\\';
    if (plain) {
        out += '"';
        out.append(s);
        out += '"';
        return;
    }
    out += nlohmann::json(std::string(s)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void append_number(std::string& out, double x) {
    if (std::isfinite(x))
        fmt::format_to(std::back_inserter(out), "{}", x);
    else
        out += "null";
}

// One card: {"keyword":..,"card":..,"file":..,"line":..,"values":[[NAME,TEXT,EXPLICIT,VALID,NUMBER]..]}.
template <typename Value, typename Skipped>
void append_card(std::string& out, std::string_view keyword, std::string_view card, const grammar::CardLine& line,
                 const std::vector<Value>& values, Skipped skipped) {
    if (out.size() > 1) out += ',';
    out += "{\"keyword\":";
    append_string(out, keyword);
    out += ",\"card\":";
    append_string(out, card);
    fmt::format_to(std::back_inserter(out), ",\"file\":{},\"line\":{},\"values\":[", line.file, line.line);
    bool first = true;
    for (const Value& v : values) {
        if (!v.spec || skipped(v)) continue;
        if (!first) out += ',';
        first = false;
        out += '[';
        append_string(out, v.spec->name);
        out += ',';
        append_string(out, v.text);
        out += v.explicit_value ? ",true," : ",false,";
        out += v.valid ? "true," : "false,";
        append_number(out, v.number);
        out += ']';
    }
    out += "]}";
}

}  // namespace

std::string cards_json(const grammar::RawDeck& deck) {
    std::string out = "[";
    if (grammar::format_of(deck) == grammar::DeckFormat::Radioss) {
        const int version = model::radioss_version(deck);
        const auto skipped = [](const model::RadiossValue& v) {
            return v.spec->cell == grammar::radioss::Cell::Skip || v.spec->cell == grammar::radioss::Cell::Skip20;
        };
        for (const grammar::Block& block : deck.blocks)
            engine::walk_radioss_block(deck, block, version,
                                       [&](grammar::CardLinePtr line, const engine::RadiossCard& c) {
                                           append_card(out, block.keyword, c.title ? "title" : "card", *line, c.values,
                                                       skipped);
                                           return true;
                                       });
    } else {
        const auto skipped = [](const model::FieldValue& v) { return v.spec->type == keywords::FieldType::Unused; };
        std::vector<diag::Diagnostic> dropped;
        model::check_deck(deck, dropped,
                          [&](const grammar::Block& block, const keywords::KeywordMatch&,
                              const keywords::CardSpec& card, grammar::CardLinePtr line,
                              const std::vector<model::FieldValue>& values) {
                              append_card(out, block.keyword, card.name, *line, values, skipped);
                          });
    }
    out += ']';
    return out;
}

nlohmann::ordered_json card_files_json(const grammar::RawDeck& deck) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (grammar::FileId id = 0; id < deck.sources.size(); ++id) out.push_back(deck.sources.file(id).display_name);
    return out;
}

}  // namespace sphdeck::cli
