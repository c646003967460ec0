// The OpenRadioss side of `sphdeck format`: each card line of a starter keyword the tables describe
// (grammar/radioss/cards.hpp) laid out in its cells in the deck's format version: integers and reals
// right-aligned (the starter reads a cell's number wherever it sits in the cell), text cells as written.
// Headers, titles, comment lines, engine (list-directed) input and free lines are kept as written.
#include <map>

#include "edit/format_sink.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/reader.hpp"
#include "model/radioss_card_sequence.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::edit::detail {
namespace {

namespace rad = grammar::radioss;

CellKind kind_of(rad::Cell cell) {
    switch (cell) {
        case rad::Cell::Int:
        case rad::Cell::Real: return CellKind::Number;
        case rad::Cell::Text:
        case rad::Cell::Text20:
        case rad::Cell::Line: return CellKind::Text;
        case rad::Cell::Skip:
        case rad::Cell::Skip20: return CellKind::Unused;
    }
    return CellKind::Text;
}

struct CellColumns {
    std::vector<grammar::FixedField> slots;
    std::vector<CellKind> kinds;
    std::uint64_t integer_fields = 0;  // bit i: cell i reads an integer
    bool numbers = false;              // a card of text only (a title, a name) is kept as written
};

class ColumnCache {
public:
    explicit ColumnCache(int version) : version_(version) {}
    const CellColumns& of(const rad::CardSpec& card) {
        auto [it, added] = cache_.try_emplace(&card);
        if (!added) return it->second;
        CellColumns& c = it->second;
        c.slots = rad::layout(card, version_);
        for (const auto& f : card.fields) {
            if (f.cell == rad::Cell::Int && c.kinds.size() < 64) c.integer_fields |= std::uint64_t{1} << c.kinds.size();
            c.kinds.push_back(kind_of(f.cell));
            c.numbers = c.numbers || c.kinds.back() == CellKind::Number;
        }
        return c;
    }

private:
    int version_;
    std::map<const rad::CardSpec*, CellColumns> cache_;
};

// Blocks of an engine deck (_0001.rad) or before /END/ENGINE in a one-file deck: list-directed input.
class EngineBlocks {
public:
    explicit EngineBlocks(const grammar::RawDeck& deck) : deck_(deck) {
        for (std::size_t i = 0; i < deck.blocks.size(); ++i)
            if (deck.blocks[i].keyword == "/END/ENGINE") last_end_engine_[root(deck.blocks[i])] = i;
    }
    bool engine(const grammar::Block& block) const {
        const grammar::FileId r = root(block);
        if (rad::is_engine_file_name(deck_.sources.file(r).display_name)) return true;
        auto it = last_end_engine_.find(r);
        return it != last_end_engine_.end() && static_cast<std::size_t>(&block - deck_.blocks.data()) < it->second;
    }

private:
    grammar::FileId root(const grammar::Block& b) const { return deck_.sources.include_chain(b.span.file).front(); }
    const grammar::RawDeck& deck_;
    std::map<grammar::FileId, std::size_t> last_end_engine_;
};

void format_block(const FormatScope& scope, const grammar::Block& block, int version, ColumnCache& columns,
                  LineChanges& out) {
    if (block.keyword.empty() || block.keyword[0] != '/') return;
    const rad::KeywordSpec* keyword = rad::find_keyword(block.keyword);
    if (!keyword || !keyword->decoded || keyword->engine) {
        if (block.line_count > 0) scope.give_up();  // lines it does not lay out: their findings unknown
        return;
    }
    const grammar::RawDeck& deck = scope.deck;
    const rad::FormatSpec& format = keyword->format_for(version);
    grammar::CardLinePtr l = deck.begin_lines(block);
    grammar::CardLinePtr end = deck.end_lines(block);
    if (keyword->title && !rad::is_v4(version) && l != end) {  // the title line: text
        if (scope.formats(l->file) && !has_letter(deck.text(*l))) scope.give_up();
        ++l;
    }
    model::RadiossCardSequence sequence(format.cards);
    std::vector<diag::Diagnostic> dropped;
    model::RadiossCardDecoder decoder(deck, dropped);
    std::vector<model::RadiossValue> values;
    std::string buffer;
    for (; l != end; ++l) {
        const std::string_view text = deck.text(*l);
        const auto next = sequence.next(text);
        if (next.step == model::RadiossCardSequence::Step::Past) {
            scope.give_up();
            return;
        }
        if (next.step == model::RadiossCardSequence::Step::Blank) continue;
        const rad::CardSpec& card = format.cards[next.index];
        const CellColumns& c = columns.of(card);
        // Commas: the starter's free reading of some cards; kept as written.
        if (c.numbers && scope.formats(l->file) && text.find(',') == std::string_view::npos)
            format_card_line(scope, *l, text, {c.slots, c.kinds, c.integer_fields}, true, buffer, out);
        else if (scope.formats(l->file) && (c.numbers || !has_letter(text)))
            scope.give_up();  // a free line, or a name of numbers: may be a misreading's cause
        if (sequence.needs_values(next.index)) {
            decoder.decode(*l, card, version, false, values, {}, keyword->trailing_checked);
            dropped.clear();
        }
        sequence.advance(next.index, values);
    }
}

}  // namespace

void format_radioss(const FormatScope& scope, LineChanges& out) {
    const int version = model::radioss_version(scope.deck);
    ColumnCache columns(version);
    const EngineBlocks engine(scope.deck);
    for (const grammar::Block& block : scope.deck.blocks) {
        if (scope.abandoned()) return;
        if (!scope.formats(block.span.file) || engine.engine(block)) continue;
        format_block(scope, block, version, columns, out);
    }
}

}  // namespace sphdeck::edit::detail
