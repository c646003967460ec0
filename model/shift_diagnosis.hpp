// The cause behind a block's reading findings when it is one: a line shifted a few columns off its
// fields (DK029) or a block written in other field widths (DK030). Runs once per block on the lines
// that produced a finding or sit under a `$#` header (a few, never every line of a bulk block); the
// findings that follow from the cause on those lines become notes of the one finding that names it.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/lone_value_shift.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

struct SuspectLine {
    grammar::CardLinePtr line = nullptr;
    const keywords::CardSpec* card = nullptr;
};

// At most this many lines of a block are looked at.
inline constexpr std::size_t max_suspect_lines = 64;

// The comment line right above `line` that starts with `marker`, or empty: `$#` in LS-DYNA (LS-PrePost's
// and pydyna's field names), `#` in OpenRadioss (HyperMesh's and the QA decks' cell names).
std::string_view header_above(const grammar::RawDeck& deck, const grammar::CardLine& line,
                              std::string_view marker = "$#");

// Diagnoses `block` from its suspect lines; its findings are out[from, end), and stay there unless
// folded into a cause.
void diagnose_shifts(const grammar::RawDeck& deck, const grammar::Block& block, std::span<const SuspectLine> suspects,
                     std::vector<diag::Diagnostic>& out, std::size_t from);

// DK029 for a line of one value pushed into the next field (grammar/lone_value_shift.hpp), the deck's
// numbers all right-aligned otherwise. Its fix is not safe, the evidence being the deck's habit, unless the
// line as written is `refused` (an error: a required field left blank) and reads when moved back: then the
// author evidently meant it there (`          6         0` under *SECTION_SPH, SECID blank).
diag::Diagnostic lone_value_finding(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const grammar::CardLine& line, const keywords::CardSpec& card,
                                    const grammar::LoneShift& shift, std::span<const grammar::FixedField> slots,
                                    bool refused = false);

// The reading findings a shift or a wrong width explains (DK002-DK008): folded into the cause.
bool follows_from_shift(std::string_view code);

// The findings that name a misreading's cause, whose consequences become their notes: a line shifted off its
// fields (DK029), a block in other widths (DK030), a heading or title left out (DK032), a keyword without its
// '*' (DK033), a blank line read as a card (DK034), a card cut above a line (DK035), a line pasted twice (DK036).
bool misreading_cause(std::string_view code);

// A reading finding of `block` (DK002-DK009, DK013) on `line` or after it, or the keyword's missing card on its
// keyword line: what a line read as a card too many or too few (a blank line, a copy, a card cut) makes.
bool misread_from(const diag::Diagnostic& d, const grammar::Block& block, const grammar::CardLine& line);

// Moves `d` into `cause` as a note "message [CODE]" at its span ("column N: message [CODE]" without a
// span when it is on the cause's line).
void fold_into(diag::Diagnostic& cause, diag::Diagnostic&& d);

// Folds the findings of out[from, end) that `explained` accepts into `cause` (which becomes as grave as the
// gravest of them), keeps the others in order, and appends `cause`.
void fold_explained(std::vector<diag::Diagnostic>& out, std::size_t from, diag::Diagnostic cause,
                    const std::function<bool(const diag::Diagnostic&)>& explained);

}  // namespace sphdeck::model
