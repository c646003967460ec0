// Two card lines made one, or one broken in two, inside a keyword whose cards are read once. A line end
// deleted (the second line's text goes on from the first's last character) leaves the block a card short: the
// second card's values are read into the first card's empty fields, or past its columns, or as the end of a
// *PART heading, and "missing its Card 2" lands on the keyword line (DK037). A line end typed inside a card
// sends the rest of the line to a line of its own, read as the next card, and every line after it one card
// late (DK038). Either way the symptoms name other lines; the cause is found by trying the mend: the block,
// split or joined there, reads without a finding, its values in their fields.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// A line of a block as a replay reads it: its place in the deck (for the spans) and a text, the deck's or a mended one.
struct ReplayLine {
    grammar::CardLinePtr line = nullptr;
    std::string_view text;
};

// The card each replayed line is read as, when the block so read makes no finding and misses no card (none for
// lines past the last card); nothing otherwise. The caller decodes (model/deck_check.cpp).
using Replay = std::function<std::optional<std::vector<const keywords::CardSpec*>>(std::span<const ReplayLine>)>;

// A data line read as a card read once, as the walk met it (card: none for a line past the keyword's last card).
struct ReadOnceLine {
    grammar::CardLinePtr line = nullptr;
    const keywords::CardSpec* card = nullptr;
};

// Whether the words of `text` sit in `card`'s fields as a line of it would hold them: each word ends at the end of
// a field or starts at the start of one (the right- or left-aligned habit), and none is wider than its field.
bool words_in_place(std::string_view text, const keywords::CardSpec& card, grammar::CardFormat format);

// DK037 at the first of `lines` (in block order) from whose line on the block reads a card short (the keyword's
// missing card on its keyword line, or a reading finding of out[from, end) on the line itself; no line past the
// last card) and which, broken after one of its words (in the blanks that put the next word in a field of one of
// the keyword's `cards`), makes the block read cleanly, both pieces' words in the fields of the cards they are then
// read as. Its findings become the cause's notes; its fix (unsafe) breaks the line there. Returns whether it fired.
bool diagnose_joined_line(const grammar::RawDeck& deck, const grammar::Block& block,
                          std::span<const keywords::CardSpec* const> cards, std::span<const ReadOnceLine> lines,
                          const Replay& replay, std::vector<diag::Diagnostic>& out, std::size_t from);

// DK037 on lines of `card`, the card the block repeats (nodes, particles, a curve's points), whose text past the
// card's fields (`past_fields`, the walk's first few) or, when every line of the block is one of `card`
// (`only_card`), past its last column (DK006 in out[from, end)) comes from a second line of it: broken after one
// of its words, both pieces read as lines of `card` without a finding, their words in its fields. At most a few
// lines a block; DK006 becomes the cause's note.
void diagnose_joined_repeated_lines(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const keywords::CardSpec& card, bool only_card,
                                    std::span<const grammar::CardLinePtr> past_fields,
                                    std::vector<diag::Diagnostic>& out, std::size_t from);

// DK038 at the first of `lines` (in block order) that stands right under another data line of the block (no
// comment between them) from which the block misreads, and which, joined to the end of that line with its words in
// the fields of that line's card, makes the block read cleanly. Its fix (unsafe) joins it to the line above and
// makes it a comment. Returns whether it fired.
bool diagnose_split_line(const grammar::RawDeck& deck, const grammar::Block& block, std::span<const ReadOnceLine> lines,
                         const Replay& replay, std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
