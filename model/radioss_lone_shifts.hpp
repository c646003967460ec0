// OpenRadioss lines whose integers were all pushed a few columns right, each wholly into the next cell
// (`         3         1` typed one column late: every value read one cell on, the last one past the
// card and dropped). Nothing straddles and the starter refuses nothing, so only the deck's habit tells:
// when its other integers end at their cells' ends, these were meant one cell back (DK029). The LS-DYNA
// counterpart is model/deck_check.cpp's lone shifts (grammar/lone_value_shift.hpp); reals are not judged
// here, since machine-written decks write them from a fixed column ("      1.00000000    ").
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/fields.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/lone_value_shift.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// The field types of a card's cells (integer, real, text, unused), for the alignment tools of grammar/.
std::vector<keywords::FieldType> radioss_field_types(const grammar::radioss::CardSpec& card);

class RadiossLoneShifts {
public:
    // A fixed-format line read without a finding: tallied, or kept when its integers look pushed. Lines of
    // repeated cards (/NODE, /SHELL: millions of machine-written lines) are neither: the habit shows on
    // the cards read once, which are where a person edits.
    void note(const grammar::CardLine& line, std::string_view text, const grammar::radioss::CardSpec& card,
              std::span<const grammar::FixedField> positions, std::string_view keyword);
    // DK029 for the kept lines, when (all but 1% of) the deck's other integers end at their cells' ends.
    void report(std::vector<diag::Diagnostic>& out) const;

private:
    struct Candidate {
        grammar::Span span;          // the line, from its first value
        std::uint32_t line_end = 0;  // one past its last column
        std::string keyword, meant, read, value;
        grammar::LoneShift shift;
    };
    static constexpr std::size_t max_candidates = 64;
    const grammar::radioss::CardSpec* card_ = nullptr;  // the card of types_ (repeated cards: line after line)
    std::vector<keywords::FieldType> types_;
    std::size_t integer_cells_ = 0;
    grammar::AlignmentTally tally_;
    std::vector<Candidate> candidates_;
};

}  // namespace sphdeck::model
