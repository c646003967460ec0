// One fixed-format card line in its canonical layout: each number right-aligned in its own columns, text
// fields as written, trailing blanks dropped. The solver reads the same values before and after: LS-DYNA
// reads blanks in a numeric field as null (BN) and OpenRadioss trims its cells, so a number may move
// inside its field; a blank field stays blank, a text field keeps its bytes. A line whose reading is in
// any doubt (a value across a field boundary, text outside the fields, a tab, a blank inside a value) is
// not laid out: the caller leaves it exactly as written.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "grammar/fields.hpp"

namespace sphdeck::edit {

// How a field's text is laid out.
enum class CellKind : std::uint8_t {
    Number,  // integer or real (or a `&name`): right-aligned
    Label,   // an id that may be a name: right-aligned when it is a number, else as written
    Text,    // kept byte for byte in its columns
    Unused,  // must be blank
};

enum class LineVerdict : std::uint8_t { Same, Changed, Doubt };

struct LineLayout {
    LineVerdict verdict = LineVerdict::Same;
    std::string_view doubt;  // why the line is left as written (static text), when Doubt
};

// Lays out `text` (no line break) with its fields at `slots` (widened for the block's format) of
// kinds `kinds` into `out` (reused). `out` is meaningful only when the verdict is Changed.
LineLayout layout_fixed_line(std::string_view text, std::span<const grammar::FixedField> slots,
                             std::span<const CellKind> kinds, std::string& out);

// The cheap test the bulk lines (*NODE, *ELEMENT_SPH) take first: `text` (known to hold no tab and no
// comma) is laid out already, numbers only: every number ends on its field's last column with no blank
// inside, nothing lies outside the fields or in an unused one, no trailing blank. Such a line is Same.
bool already_laid_out(std::string_view text, std::span<const grammar::FixedField> slots,
                      std::span<const CellKind> kinds);

// A line no finding can hold back, for a format without the findings (format_deck_without_findings):
// laid out already (already_laid_out) and every value a plain number its field reads without remark: an
// integer of at most nine digits, or in a real field (bit i of `integer_fields` clear: field i reads a
// real) a decimal number with an optional exponent of at most three digits; no parameter, comma or tab.
bool plain_laid_out(std::string_view text, std::span<const grammar::FixedField> slots, std::span<const CellKind> kinds,
                    std::uint64_t integer_fields);

// A free-format (comma) line rewritten in fixed columns (`--to fixed`): every value must fit its field.
LineLayout free_to_fixed(std::string_view text, std::span<const grammar::FixedField> slots,
                         std::span<const CellKind> kinds, std::string& out);

}  // namespace sphdeck::edit
