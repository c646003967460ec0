#include "model/radioss_lone_shifts.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "text/line_rewrite.hpp"

namespace sphdeck::model {

using grammar::radioss::Cell;
using keywords::FieldType;

std::vector<FieldType> radioss_field_types(const grammar::radioss::CardSpec& card) {
    std::vector<FieldType> types;
    for (const auto& f : card.fields) {
        switch (f.cell) {
            case Cell::Int: types.push_back(FieldType::Integer); break;
            case Cell::Real: types.push_back(FieldType::Real); break;
            case Cell::Skip:
            case Cell::Skip20: types.push_back(FieldType::Unused); break;
            default: types.push_back(FieldType::Text);
        }
    }
    return types;
}

void RadiossLoneShifts::note(const grammar::CardLine& line, std::string_view text,
                             const grammar::radioss::CardSpec& card, std::span<const grammar::FixedField> positions,
                             std::string_view keyword) {
    if (card.repeat == grammar::radioss::Repeat::Repeated) return;
    if (card_ != &card) {
        card_ = &card;
        types_ = radioss_field_types(card);
        integer_cells_ = static_cast<std::size_t>(std::count(types_.begin(), types_.end(), FieldType::Integer));
    }
    // A line of fewer than two integer cells is never judged pushed (find_lone_shift wants two).
    if (integer_cells_ >= 2 && candidates_.size() < max_candidates)
        if (auto shift = grammar::find_lone_shift(text, positions, types_, grammar::Judged::Integers)) {
            const auto end = static_cast<std::uint32_t>(text.size() + 1);
            const auto first = static_cast<std::uint32_t>(text.find_first_not_of(' ') + 1);
            Candidate c{grammar::Span{line.file, line.line, first, end},
                        end,
                        std::string(keyword),
                        std::string(card.fields[shift->meant].name),
                        std::string(card.fields[shift->read].name),
                        std::string(text.substr(shift->begin, shift->end - shift->begin)),
                        std::move(*shift)};
            candidates_.push_back(std::move(c));
            return;
        }
    grammar::tally_alignment(text, positions, types_, tally_, grammar::Judged::Integers);
}

void RadiossLoneShifts::report(std::vector<diag::Diagnostic>& out) const {
    constexpr std::uint64_t min_aligned = 4;  // a deck with fewer integers shows no habit
    if (tally_.right < min_aligned || tally_.other * 100 > tally_.right) return;
    for (const Candidate& c : candidates_) {
        const int n = c.shift.columns;
        diag::Diagnostic d{
            "DK029",
            diag::Severity::Error,
            fmt::format("line shifted {} column{} right of the cells of {}: its {} integers end {} column{} past "
                        "the ends of their cells ('{}' is read as {}, not {})",
                        n, n == 1 ? "" : "s", c.keyword, c.shift.values, n, n == 1 ? "" : "s", c.value, c.read,
                        c.meant),
            c.span,
            {}};
        d.notes.push_back({grammar::Span{},
                           "nothing straddles a cell end; the deck's other integers end at their "
                           "cells' ends (right-aligned), these do not"});
        if (c.shift.realigned)
            d.fixes.push_back(
                diag::Fix{fmt::format("move the values {} column{} left into their cells", n, n == 1 ? "" : "s"),
                          false,
                          {text::whole_line_edit(c.span.file, c.span.line, c.line_end - 1, *c.shift.realigned)}});
        out.push_back(std::move(d));
    }
}

}  // namespace sphdeck::model
