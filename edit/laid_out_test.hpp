// The quick test the bulk lines (*NODE, *ELEMENT_SPH: millions of them) take before `format` reads them:
// is the line laid out already? One pass over the line's bytes, its end found on the way. The card's
// fields are turned into column masks once (LaidOutTest), so that a line costs a few mask operations for
// all its fields together rather than a loop over them (issue 40 item 5: half of `format --check`'s time
// was this test, field by field).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "edit/format_line.hpp"
#include "grammar/fields.hpp"

namespace sphdeck::edit {

class LaidOutTest {
public:
    LaidOutTest(std::span<const grammar::FixedField> slots, std::span<const CellKind> kinds);

    // `rest` runs from a card line's first byte to its file's end. The line's length (without "\r\n")
    // when it holds no comma or tab and already_laid_out passes it; nullopt when not: the caller reads the
    // line as usual.
    std::optional<std::size_t> length(std::string_view rest) const;
    // The bytes of `rest` the test may read: a shorter `rest` must end where the file does.
    std::size_t look_ahead() const { return std::max(mask_columns, last_ + 2); }

private:
    __extension__ using Mask = unsigned __int128;  // bit c: column c of the line
    static constexpr std::size_t mask_columns = 128;

    std::span<const grammar::FixedField> slots_;
    std::span<const CellKind> kinds_;
    bool masks_ = false;        // the fields fit the masks, in order: else the test goes byte by byte
    std::size_t last_ = 0;      // the fields' last column + 1: no laid-out line is longer
    Mask numbers_ = 0;          // the columns of the number and label fields: every other column is blank
    Mask ends_ = 0;             // their last columns: where a value may end
    std::vector<Mask> labels_;  // each label field's columns (a label must be an integer to line up)

    std::optional<std::size_t> by_masks(std::string_view rest) const;
};

}  // namespace sphdeck::edit
