// Where /NODE lines define given node ids: REF006 names both places of a duplicated node, and the
// model keeps no per-node line (10 million nodes would pay for a rare report).
#include <algorithm>

#include "grammar/fields.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/value.hpp"
#include "model/radioss_card_decoder.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

std::map<long long, std::vector<grammar::Span>> radioss_node_lines(const grammar::RawDeck& deck,
                                                                   const std::set<long long>& ids) {
    std::map<long long, std::vector<grammar::Span>> found;
    if (ids.empty()) return found;
    const int version = radioss_version(deck);
    // The id is the first cell: 10 columns, 8 in V4 decks (radioss-format.md §2).
    const std::size_t width = rad::cell_width(rad::Cell::Int, version);
    for (const grammar::Block& b : deck.blocks) {
        const rad::KeywordSpec* spec = rad::find_keyword(b.keyword);
        if (!spec || spec->name != "/NODE" || !b.span.valid()) continue;
        // /NODE in the engine deck is not read (DK001), so its ids are no definitions.
        const grammar::FileId root = deck.sources.include_chain(b.span.file).front();
        if (rad::is_engine_file_name(deck.sources.file(root).display_name)) continue;
        const rad::CardSpec& card = spec->formats.front().cards.front();
        for (grammar::CardLinePtr l = deck.begin_lines(b); l != deck.end_lines(b); ++l) {
            std::string_view text = deck.text(*l);
            std::string_view first = grammar::is_free_format(text) ? text.substr(0, text.find(','))
                                                                   : text.substr(0, std::min(text.size(), width));
            grammar::IntegerValue id = grammar::parse_integer(first);
            if (id.status == grammar::NumberStatus::Ok && ids.count(id.value))
                found[id.value].push_back(radioss_field_span(deck, l.index(), card, version, 0));
        }
    }
    return found;
}

}  // namespace sphdeck::model
