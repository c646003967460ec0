// A decimal comma typed for a decimal point (`0,002` for `0.002`) in a fixed-format line. Both
// solvers read a line holding a comma as free format (the comma separates values), so the number is
// cut in two and every later value moves one field on, silently. One finder for both decoders (DK031).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/fields.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

struct DecimalComma {
    std::size_t begin = 0, end = 0;  // 0-based [begin, end) of the word holding the comma
    std::string meant;               // the word with a point for the comma
};

// A comma between two digits on a line written in fixed format: the line starts with two blanks (a
// fixed-format field's padding: a genuine free-format line is written from its first column, or with a
// blank after each comma), or the word holding the comma lies in one of `fields` and ends at its end (a value
// right-aligned in its field: ` 0,6000000` in columns 1-10, `1,00000000000000E-03` filling a 20-wide cell).
std::optional<DecimalComma> find_decimal_comma(std::string_view text, std::span<const grammar::FixedField> fields = {});

// DK031 at the word: "... `solver` reads this line as free format (`reading`); a decimal comma? write X".
// `reading`: the first fields as read, "ENDTIM 0, ENDCYC 2" (empty: none shown).
// One cause, one finding: the findings of `found` from `first` on that the free-format reading made on the
// line (a value cut in two or moved into another field: DK002-DK005, DK007) become its notes, and it is an
// error when one of them was (the solver stops at such a value); it is appended to `found`.
void report_decimal_comma(const DecimalComma& comma, const grammar::CardLine& line, std::string_view solver,
                          std::string_view reading, std::vector<diag::Diagnostic>& found, std::size_t first);

}  // namespace sphdeck::model
