// A `*PART` whose heading line was forgotten: LS-DYNA reads its PID/SECID/MID line as the heading (any text
// is a heading) and the next line, or the next keyword, as card 2, so the part is missing or wrong and the
// findings land on the keyword line ("missing its Card 2"), on the next part's heading, on every particle
// of the part. The cause is the line a person typed: a heading that reads as a card of integers (DK032). The
// title line of a keyword's `_TITLE` option (*MAT_NULL_TITLE, *SECTION_SPH_TITLE) left out is read alike: the
// first card's line as the title, the keyword then missing that card.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/fields.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// Whether `text` reads as `card` (the card after the heading): two integers at least, each word an integer
// whole in one of the card's integer fields (or, in free format, each value an integer).
bool reads_as_integer_card(std::string_view text, std::span<const grammar::FixedField> slots,
                           const keywords::CardSpec& card);

// Whether `text` reads as `card` (the card after a `_TITLE` option's title): two words at least, each whole in
// one of the card's fields, an integer in an integer field, a number in a real field, any word in a label field.
bool reads_as_card(std::string_view text, std::span<const grammar::FixedField> slots, const keywords::CardSpec& card);

// Whether `text`, read as `card`, holds a real (a decimal point or an exponent) in an integer or id field:
// the line after a lost heading read as card 2 (*PART_INERTIA's XC, YC, ZC as PID, SECID, MID, which take
// labels, so nothing else says so).
bool reals_in_id_fields(std::string_view text, std::span<const grammar::FixedField> slots,
                        const keywords::CardSpec& card);

// DK032 at `heading` (a heading line that reads as the next card), when the block misread after it (a
// reading finding in out[from, end), or `reals_read_as_ids`: the line after it holds reals where its ids are
// read); the block's reading findings become its notes.
void diagnose_missing_heading(const grammar::RawDeck& deck, const grammar::Block& block,
                              const grammar::CardLine& heading, const keywords::CardSpec& next_card,
                              bool reals_read_as_ids, std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
