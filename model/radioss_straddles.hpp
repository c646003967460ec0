// OpenRadioss fixed cells read by their columns: a value written across a cell boundary is cut there
// (RAD030 says which part the starter keeps and where the rest goes), and a whole line moved a few
// columns off its cells is one DK029 with the realigned line as its fix. The findings of the line that
// follow (RAD025 in the next cell, not a number...) become notes of that one finding.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/fields.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// True when two non-blank characters touch across the end of a cell: the only lines besides those
// with findings that diagnose_radioss_line looks at (inline: it runs on every fixed line).
inline bool glued_across_cells(std::string_view text, std::span<const grammar::FixedField> positions) {
    for (const grammar::FixedField& f : positions) {
        const std::size_t b = std::size_t{f.start} + f.width;
        if (b >= text.size()) return false;
        if (b > 0 && text[b - 1] != ' ' && text[b] != ' ') return true;
    }
    return false;
}

// Looks at `line` (its `text`, fixed format, cut at `positions`) after its values were read, with the line's
// findings at out[from, end). `header`: the `#` comment line above (model::header_above), empty when none;
// with it a line whose values all end a few columns past the ends of the cells it names is shifted, when
// that changes what the starter reads (a one-column shift reads every value in the next cell, silently).
// Cheap when nothing is glued across a boundary, nothing was found and there is no header.
void diagnose_radioss_line(const grammar::CardLine& line, std::string_view text, const grammar::radioss::CardSpec& card,
                           std::span<const grammar::FixedField> positions, std::string_view keyword,
                           std::string_view header, std::vector<diag::Diagnostic>& out, std::size_t from);

}  // namespace sphdeck::model
