// Cutting a data line into fields (lsdyna-format.md §3-§6): fixed columns, or free comma
// format decided per line. Never splits on white space: fixed fields may touch.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar {

// A field's place in standard format: 0-based start column and width.
struct FixedField {
    std::uint32_t start = 0;
    std::uint32_t width = 0;
};

// Positions in another format: I10 widens fields narrower than 10 to 10, long widens fields
// narrower than 20 to 20 (PRIMER "Automatic promotion"); offsets follow cumulatively, and a
// gap between fields widens like an unused field of its width.
void widen(std::span<const FixedField> standard, CardFormat format, std::vector<FixedField>& out);

// Width past which the solver ignores a line: 80, or the widened end of the card's fields.
std::uint32_t significant_width(std::span<const FixedField> widened, CardFormat format);

struct Field {
    std::string_view text;  // raw, blanks included (fixed) or the token (free)
    Span span;
};

struct CutReport {
    bool free_format = false;
    bool has_tab = false;                 // DK016 (fixed format only)
    Span beyond;                          // DK006: text past the significant width, or extra free values
    std::uint32_t extra_values = 0;       // free format: values beyond the card's fields
    std::vector<std::uint32_t> too_long;  // DK005: indices of free tokens longer than their field
};

// Cuts `text` (the line of `line`) into one Field per entry of `positions` (already widened for
// the card's format) ; text past `significant` columns is reported in CutReport::beyond.
// Fields past the end of a short line are empty with their nominal span. `out` is reused.
// `allow_free` is false for text cards (titles, headings): a comma there is just text.
CutReport cut_fields(std::string_view text, const CardLine& line, std::span<const FixedField> positions,
                     std::uint32_t significant, std::vector<Field>& out, bool allow_free = true);

// True when a line uses free format: a comma outside parentheses (pydyna's rule; commas in
// `min(a,b)` do not count).
bool is_free_format(std::string_view text);

bool is_blank(std::string_view s);
// `s` without leading blanks and tabs, nor trailing blanks, tabs and '\r'.
std::string_view trim_blanks(std::string_view s);

// A tab where a run of blanks was meant (DK016 even when both tab readings agree): every value before the
// tab ends at its field's end, and after it a value spans two fields, shares one with another or lands in an unused
// one. `unused`: per field, whether the reader ignores it (a value moved into one is lost).
bool tab_pulls_values_off_fields(std::string_view text, std::span<const FixedField> positions,
                                 std::span<const unsigned char> unused = {});

}  // namespace sphdeck::grammar
