// A line of short values pushed a few columns right, each wholly into the next field (`       1.0` typed
// `          1.0`: ENDTIM blank, ENDCYC 1.0). Nothing straddles and nothing is refused, so the line alone
// cannot tell it from a value written left in its field; the deck can: when every other number of the
// deck ends at its field's end (LS-PrePost, pydyna and most hand-written decks right-align), a lone value
// ending a few columns past the end of the blank field before it, and not at its own field's end, was
// meant for that field. model/deck_check.cpp tallies the deck and decides at its end.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "grammar/fields.hpp"
#include "grammar/keywords/schema.hpp"

namespace sphdeck::grammar {

// How the numbers of a deck's fixed-format lines sit in their fields.
struct AlignmentTally {
    std::uint64_t right = 0;  // end at their field's end
    std::uint64_t other = 0;  // start at its start only, or float inside it
};

// Which numbers a habit of alignment is judged on: every number, or the integers alone (machine-written
// OpenRadioss decks right-align integers but write reals from a fixed column, "      1.00000000    ").
enum class Judged { Numbers, Integers };

// Adds the numbers (Integer and Real fields; `Judged::Integers`: Integer fields only) of `text` that sit
// whole in one field of `slots`.
void tally_alignment(std::string_view text, std::span<const FixedField> slots,
                     std::span<const keywords::FieldType> types, AlignmentTally& tally,
                     Judged judged = Judged::Numbers);

struct LoneShift {
    int columns = 0;                       // > 0: right of the field it was meant for
    std::size_t meant = 0;                 // that field
    std::size_t read = 0;                  // the field it is read in
    std::size_t begin = 0, end = 0;        // 0-based [begin, end) of the (first) value
    std::size_t values = 1;                // on the line
    std::optional<std::string> realigned;  // the line moved `columns` left, when it has the blanks
};

// The values of `text` (one to eight), when none ends at its field's end and, moved `columns` (1 to 4)
// left, each ends at the end of a number field whose type reads it: a right-aligned line pushed so far
// right that nothing straddles (short values). `meant` and `read` are those of the first value.
// `Judged::Integers`: the line's integers (two at least) are judged so; its reals need only stay whole
// in fields that read them, and `meant`/`read` are those of the first integer.
std::optional<LoneShift> find_lone_shift(std::string_view text, std::span<const FixedField> slots,
                                         std::span<const keywords::FieldType> types, Judged judged = Judged::Numbers);

}  // namespace sphdeck::grammar
