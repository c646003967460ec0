#include "model/radioss_straddles.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "grammar/fields.hpp"
#include "grammar/shifted_line.hpp"
#include "grammar/value.hpp"
#include "model/radioss_lone_shifts.hpp"
#include "model/shift_diagnosis.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::model {
namespace {

using grammar::radioss::Cell;
using keywords::FieldType;

bool numeric_straddle(Cell c) { return c == Cell::Int || c == Cell::Real; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// A number glued across the end of cell `cell`: the boundary's two sides are not blank and the run
// of characters around it reads as one number. Values packed against each other are not one: a cell
// filled from its first column, or a next value that ends at its cell's end (machine-written decks
// write ids and full-width reals touching, "      10621.52587890625000E-05").
struct Straddle {
    std::size_t cell = 0;
    std::size_t begin = 0, boundary = 0, end = 0;  // 0-based columns of the run
    std::size_t split = 0;                         // a glued pair's second value starts here (0: the run is one number)
};

// The text of columns [from, to) of `text`, blanks trimmed (empty past its end): what the starter reads there.
std::string_view cell_text(std::string_view text, std::size_t from, std::size_t to) {
    return grammar::trim_blanks(from < text.size() ? text.substr(from, std::min(to, text.size()) - from)
                                                   : std::string_view{});
}

// Machine-written decks glue a value to the next when that one fills its cell ("0.01.00000000000000E+31":
// '0.0' ends cell i, the 20-character real fills cell i + 1). Such a run moved a few columns reads as no
// number across the boundary, and the starter cuts both values. The run is a glued pair when its last
// cell-width characters and the rest before them are numbers; it is reported unless the cells it touches
// read the same values as with the pair moved back.
std::optional<Straddle> glued_pair(std::string_view text, const grammar::radioss::CardSpec& card,
                                   std::span<const grammar::FixedField> positions, std::size_t i, std::size_t s,
                                   std::size_t b, std::size_t e) {
    constexpr std::size_t most_columns_off = 4;  // a slip of the hand, not another layout
    if (i + 1 >= positions.size() || i + 1 >= card.fields.size() || !numeric_straddle(card.fields[i + 1].cell))
        return std::nullopt;
    const std::size_t width = positions[i + 1].width;
    if (e - s <= width) return std::nullopt;
    const std::size_t split = e - width;
    if (split == b || (split > b ? split - b : b - split) > most_columns_off) return std::nullopt;
    const grammar::RealValue first = grammar::parse_real(text.substr(s, split - s));
    const grammar::RealValue second = grammar::parse_real(text.substr(split, e - split));
    if (first.status != grammar::NumberStatus::Ok || second.status != grammar::NumberStatus::Ok) return std::nullopt;
    // What the starter reads in the cells the pair touches, as written and with the pair moved back.
    const std::size_t off = split > b ? split - b : b - split;
    if (split > b && s < off) return std::nullopt;
    const std::string pair(text.substr(s, e - s));
    const std::string meant =
        split > b ? std::string(text.substr(0, s - off)) + pair + std::string(off, ' ') + std::string(text.substr(e))
                  : std::string(text.substr(0, s)) + std::string(off, ' ') + pair +
                        std::string(text.substr(std::min(e + off, text.size())));
    const auto number_of = [](std::string_view cell) -> std::optional<double> {  // a blank cell reads 0
        if (cell.empty()) return 0.0;
        const grammar::RealValue v = grammar::parse_real(cell);
        return v.status == grammar::NumberStatus::Ok ? std::optional<double>(v.value) : std::nullopt;
    };
    bool same = true;
    for (std::size_t k = i; k < std::min(i + 3, positions.size()) && same; ++k) {
        const std::size_t from = positions[k].start, to = from + positions[k].width;
        const std::string_view now = cell_text(text, from, to), then = cell_text(meant, from, to);
        const std::optional<double> a = number_of(now), z = number_of(then);
        same = now == then || (a && z && *a == *z);
    }
    if (same) return std::nullopt;  // read the same: nothing to say
    return Straddle{i, s, b, e, split};
}

std::vector<Straddle> straddles(std::string_view text, const grammar::radioss::CardSpec& card,
                                std::span<const grammar::FixedField> positions) {
    std::vector<Straddle> out;
    for (std::size_t i = 0; i < positions.size() && i < card.fields.size(); ++i) {
        const std::size_t b = std::size_t{positions[i].start} + positions[i].width;
        if (b == 0 || b >= text.size() || blank(text[b - 1]) || blank(text[b])) continue;
        if (!numeric_straddle(card.fields[i].cell)) continue;
        if (i + 1 < positions.size() && positions[i + 1].start != b) continue;  // not adjacent
        // A one-column cell (the /BCS dof flags '111 110') is always filled from its first column: a run
        // from it into a wider cell (dof6 '10' over columns 10-11) is still one value across the boundary.
        const bool flag_into_wider = positions[i].width == 1 && i + 1 < positions.size() && positions[i + 1].width > 1;
        std::size_t s = b, e = b;
        while (s > 0 && !blank(text[s - 1])) --s;
        while (e < text.size() && !blank(text[e])) ++e;
        const bool packed =
            (s == positions[i].start && !flag_into_wider) ||
            (i + 1 < positions.size() && e == std::size_t{positions[i + 1].start} + positions[i + 1].width);
        if (packed) continue;
        if (grammar::parse_real(text.substr(s, e - s)).status != grammar::NumberStatus::Ok) {
            if (const std::optional<Straddle> pair = glued_pair(text, card, positions, i, s, b, e))
                out.push_back(*pair);
            continue;
        }
        // A zero across the boundary ('.000000000' read as '.00000' and '0000') changes no value, unless
        // the next cell holds a value of its own that the lost zeros are then read with (BS '0.0' one
        // column past 80 makes IFORM '0        1': the starter reads IFORM 0).
        const grammar::RealValue whole = grammar::parse_real(text.substr(s, e - s));
        const grammar::RealValue kept = grammar::parse_real(text.substr(s, b - s));
        const grammar::RealValue lost = grammar::parse_real(text.substr(b, e - b));
        const std::size_t next_end =
            i + 1 < positions.size() ? std::size_t{positions[i + 1].start} + positions[i + 1].width : e;
        // The next cell's own value, read with the lost zeros: harmless when it is blank or zero too
        // ('0000      .000000000' is 0 either way).
        const std::string_view own = e >= text.size()
                                         ? std::string_view{}
                                         : grammar::trim_blanks(text.substr(e, next_end > e ? next_end - e : 0));
        const grammar::RealValue own_value = grammar::parse_real(own);
        const bool next_clear =
            own.empty() || (own_value.status == grammar::NumberStatus::Ok && own_value.value == 0.0);
        // What the starter reads in the cell: its first word (sscanf stops at a blank), the run's part in it when
        // the run starts the cell's text ("0       .000000000E" before "00" reads 0).
        const std::string_view cell = cell_text(text, positions[i].start, b);
        const grammar::RealValue read =
            cell.data() < text.data() + s ? grammar::parse_real(cell.substr(0, cell.find(' '))) : kept;
        if (whole.value == 0.0 && read.status == grammar::NumberStatus::Ok && read.value == 0.0 &&
            lost.status == grammar::NumberStatus::Ok && lost.value == 0.0 && next_clear)
            continue;
        out.push_back({i, s, b, e});
    }
    return out;
}

std::string straddle_cell_columns(const grammar::FixedField& f) {
    return fmt::format("columns {}-{}", f.start + 1, f.start + f.width);
}

diag::Diagnostic straddle_finding(const grammar::CardLine& line, std::string_view text,
                                  const grammar::radioss::CardSpec& card,
                                  std::span<const grammar::FixedField> positions, const Straddle& s) {
    const auto& here = card.fields[s.cell];
    const std::string_view whole = text.substr(s.begin, s.end - s.begin);
    const std::string_view kept = text.substr(s.begin, s.boundary - s.begin);
    const std::string_view lost = text.substr(s.boundary, s.end - s.boundary);
    // The starter reads a cell's first word (sscanf stops at a blank, meci_data_reader.cpp): a word before the
    // run in its cell is what the cell reads, and the run's part in the cell is dropped.
    const std::string_view first_word = [&] {
        const std::string_view cell = cell_text(text, positions[s.cell].start, s.boundary);
        return cell.substr(0, std::min(cell.find(' '), cell.size()));
    }();
    const std::string read = first_word.data() < kept.data()
                                 ? fmt::format("'{}' (the cell's first word; '{}' dropped)", first_word, kept)
                                 : fmt::format("'{}'", kept);
    std::string where;
    if (s.cell + 1 >= card.fields.size() || s.cell + 1 >= positions.size())
        where = fmt::format("'{}' past the last cell is not read", lost);
    else if (card.fields[s.cell + 1].cell == Cell::Skip || card.fields[s.cell + 1].cell == Cell::Skip20)
        where = fmt::format("'{}' falls in an unused cell and is lost", lost);
    else
        where = fmt::format("'{}' is read as the start of {} ({})", lost, card.fields[s.cell + 1].name,
                            straddle_cell_columns(positions[s.cell + 1]));
    diag::Diagnostic d{"RAD030",
                       diag::Severity::Error,
                       fmt::format("'{}' straddles the end of cell {} ({}): the starter reads {} as {} and {}", whole,
                                   here.name, straddle_cell_columns(positions[s.cell]), here.name, read, where),
                       grammar::Span{line.file, line.line, static_cast<std::uint32_t>(s.begin + 1),
                                     static_cast<std::uint32_t>(s.end + 1)},
                       {}};
    // Safe fix: the number moved left by the columns it overruns, to end at its cell's end, when blanks
    // of its own cell stand before it: it is then read whole in its cell and nothing else moves. Not when
    // another word stands before it in the cell: the cell would still read that word.
    const std::size_t overrun = s.end - s.boundary;
    if (first_word.data() >= kept.data() && s.begin >= positions[s.cell].start + overrun &&
        text.substr(s.begin - overrun, overrun).find_first_not_of(' ') == std::string_view::npos)
        d.fixes.push_back({fmt::format("move '{}' {} column{} left, to end at column {}, the end of {}", whole, overrun,
                                       overrun == 1 ? "" : "s", s.boundary, here.name),
                           true,
                           {{grammar::Span{line.file, line.line, static_cast<std::uint32_t>(s.begin - overrun + 1),
                                           static_cast<std::uint32_t>(s.end + 1)},
                             std::string(whole) + std::string(s.end < text.size() ? overrun : 0, ' ')}}});
    return d;
}

// A glued pair moved off its cells: both values named, what the starter reads in the two cells, where the
// rest goes; a safe fix moves the pair back (blanks of its own cells make room for it).
diag::Diagnostic glued_pair_finding(const grammar::CardLine& line, std::string_view text,
                                    const grammar::radioss::CardSpec& card,
                                    std::span<const grammar::FixedField> positions, const Straddle& s) {
    const auto& here = card.fields[s.cell];
    const auto& next = card.fields[s.cell + 1];
    const std::string_view first = text.substr(s.begin, s.split - s.begin);
    const std::string_view second = text.substr(s.split, s.end - s.split);
    const bool right = s.split > s.boundary;
    const std::size_t off = right ? s.split - s.boundary : s.boundary - s.split;
    const std::size_t next_end = std::size_t{positions[s.cell + 1].start} + positions[s.cell + 1].width;
    std::string message = fmt::format(
        "'{}' and '{}' are written glued {} column{} {} of the end of cell {} ({}): the starter reads {} as '{}' and "
        "{} as '{}'",
        first, second, off, off == 1 ? "" : "s", right ? "right" : "left", here.name,
        straddle_cell_columns(positions[s.cell]), here.name, cell_text(text, positions[s.cell].start, s.boundary),
        next.name, cell_text(text, s.boundary, next_end));
    if (right) {
        const std::string_view lost = text.substr(next_end, s.end - next_end);
        if (s.cell + 2 >= card.fields.size() || s.cell + 2 >= positions.size())
            message += fmt::format(", and '{}' past the last cell is not read", lost);
        else
            message += fmt::format(", and '{}' is read as the start of {}", lost, card.fields[s.cell + 2].name);
    }
    diag::Diagnostic d{"RAD030",
                       diag::Severity::Error,
                       std::move(message),
                       grammar::Span{line.file, line.line, static_cast<std::uint32_t>(s.begin + 1),
                                     static_cast<std::uint32_t>(s.end + 1)},
                       {}};
    // Safe fix: the pair moved back by the columns it is off, into blanks (of its first cell when it moves
    // left, of the next cell's end or the line's end when it moves right): each value then fills its cell.
    const std::string_view pair = text.substr(s.begin, s.end - s.begin);
    const std::size_t from = right ? s.begin - std::min(s.begin, off) : s.end;
    const bool room =
        right ? s.begin >= positions[s.cell].start + off &&
                    text.substr(from, off).find_first_not_of(' ') == std::string_view::npos
              : text.substr(std::min(from, text.size()), off).find_first_not_of(' ') == std::string_view::npos;
    if (room) {
        const std::size_t edit_begin = right ? from : s.begin;
        const std::size_t edit_end = right ? s.end : std::min(s.end + off, text.size());
        const std::size_t pad = s.end < text.size() ? off : 0;  // no blanks left at a line's end
        const std::string replacement =
            right ? std::string(pair) + std::string(pad, ' ') : std::string(off, ' ') + std::string(pair);
        d.fixes.push_back({fmt::format("move '{}' and '{}' {} column{} {}, to fill {} and {}", first, second, off,
                                       off == 1 ? "" : "s", right ? "left" : "right", here.name, next.name),
                           true,
                           {{grammar::Span{line.file, line.line, static_cast<std::uint32_t>(edit_begin + 1),
                                           static_cast<std::uint32_t>(edit_end + 1)},
                             replacement}}});
    }
    return d;
}

bool within(const diag::Diagnostic& d, const grammar::CardLine& line, std::size_t begin, std::size_t end) {
    return d.span.file == line.file && d.span.line == line.line && d.span.column >= 1 && d.span.column - 1 >= begin &&
           d.span.column - 1 < end;
}

// Moves the findings of out[from, end) that `take` accepts into notes of `cause`, then appends it.
template <class Take>
void fold_and_add(std::vector<diag::Diagnostic>& out, std::size_t from, diag::Diagnostic cause, Take take) {
    std::vector<diag::Diagnostic> kept;
    for (std::size_t i = from; i < out.size(); ++i) {
        if (take(out[i]))
            fold_into(cause, std::move(out[i]));
        else
            kept.push_back(std::move(out[i]));
    }
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    for (auto& d : kept) out.push_back(std::move(d));
    out.push_back(std::move(cause));
}

// One value typed across a cell boundary while every other value of the line ends at its cell's end
// (right-aligned, as written): the line is not shifted, only that value moved (RAD030), whatever a
// shift of the whole line would also explain.
bool one_value_moved(std::string_view text, const std::vector<Straddle>& glued,
                     std::span<const grammar::FixedField> positions) {
    if (glued.size() != 1) return false;
    std::size_t others = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (blank(text[i])) {
            ++i;
            continue;
        }
        const std::size_t begin = i;
        while (i < text.size() && !blank(text[i])) ++i;
        if (begin == glued[0].begin) continue;
        const bool at_cell_end = std::any_of(positions.begin(), positions.end(), [&](const grammar::FixedField& f) {
            return std::size_t{f.start} + f.width == i && begin >= f.start;
        });
        if (!at_cell_end) return false;
        ++others;
    }
    return others > 0;
}

}  // namespace

void diagnose_radioss_line(const grammar::CardLine& line, std::string_view text, const grammar::radioss::CardSpec& card,
                           std::span<const grammar::FixedField> positions, std::string_view keyword,
                           std::string_view header, std::vector<diag::Diagnostic>& out, std::size_t from) {
    auto glued = straddles(text, card, positions);
    const bool suspect = !glued.empty() || out.size() > from;
    if (!suspect && header.empty()) return;
    // A cell the newest format leaves unused may hold a value of an older format's field there (/PROP/SHELL's
    // Istrain in columns 11-20, unused since format 2025): the starter skips it, but it is aligned to that
    // cell all the same, so it counts as a placed number when the line's alignment is judged.
    std::vector<FieldType> types = radioss_field_types(card);
    for (FieldType& t : types)
        if (t == FieldType::Unused) t = FieldType::Real;
    // Under a header, values past the card's last field (a newer format's, or text the starter
    // ignores) are no evidence either way: the line is judged up to a few columns past the card.
    std::string_view probe = text;
    // A last cell kept as text (the rest of /MAT's E, nu card) is no cell to align a value to: a shift
    // that moves a number there empties a cell the starter reads. The line is judged up to it.
    const bool rest_as_text = positions.size() > 1 && positions.size() == card.fields.size() &&
                              card.fields.back().cell == grammar::radioss::Cell::Line;
    const std::span<const grammar::FixedField> cells = rest_as_text ? positions.first(positions.size() - 1) : positions;
    if (rest_as_text) {
        types.resize(cells.size());
        if (probe.size() > std::size_t{positions.back().start}) probe = probe.substr(0, positions.back().start);
    }
    if (!header.empty() && !cells.empty()) {
        const std::size_t limit = std::size_t{cells.back().start} + cells.back().width + 4;
        if (probe.size() > limit) probe = probe.substr(0, limit);
    }
    // Without a header, one value typed across a boundary among right-aligned ones is RAD030, not a shift.
    std::optional<grammar::LineShift> shift;
    if (!header.empty() || !one_value_moved(text, glued, positions))
        shift = grammar::find_shift(probe, header, cells, types);
    if (shift && probe.size() != text.size()) {
        // The fix moves the whole line, its tail included.
        const int n = shift->columns;
        if (n > 0 && text.substr(0, static_cast<std::size_t>(n)).find_first_not_of(' ') != std::string_view::npos)
            shift.reset();
        else {
            shift->realigned = text::shift_line(text, n);
        }
    }
    // On the header's word alone, only a shift that changes what is read: a value written a few columns
    // inside its cell is read the same.
    if (shift && !suspect && !shift->changes_reading) return;
    if (shift) {
        const int n = std::abs(shift->columns);
        diag::Diagnostic d{"DK029",
                           shift->changes_reading ? diag::Severity::Error : diag::Severity::Warning,
                           fmt::format("line shifted {} column{} {} of the cells of {}", n, n == 1 ? "" : "s",
                                       shift->columns > 0 ? "right" : "left", keyword),
                           grammar::Span{line.file, line.line,
                                         static_cast<std::uint32_t>(text.find_first_not_of(' ') + 1),
                                         static_cast<std::uint32_t>(text.size() + 1)},
                           {}};
        if (shift->from_header)
            d.notes.push_back({grammar::Span{}, "the `#` comment above names the cells at their columns"});
        d.fixes.push_back(
            diag::Fix{fmt::format("move the values {} column{} {} into their cells", n, n == 1 ? "" : "s",
                                  shift->columns > 0 ? "left" : "right"),
                      true,
                      {text::whole_line_edit(line.file, line.line, text.size(), std::move(shift->realigned))}});
        const bool explains = d.severity == diag::Severity::Error;  // a shift that changes no value explains nothing
        fold_and_add(out, from, std::move(d), [&](const diag::Diagnostic&) { return explains; });
        return;
    }
    for (const Straddle& s : glued) {
        const std::size_t begin = positions[s.cell].start;
        const std::size_t end = s.cell + 1 < positions.size()
                                    ? std::size_t{positions[s.cell + 1].start} + positions[s.cell + 1].width
                                    : text.size() + 1;
        const std::size_t fold_end = std::max(end, s.end);  // a glued pair's tail past the next cell too
        fold_and_add(out, from,
                     s.split != 0 ? glued_pair_finding(line, text, card, positions, s)
                                  : straddle_finding(line, text, card, positions, s),
                     [&](const diag::Diagnostic& d) { return d.code != "RAD030" && within(d, line, begin, fold_end); });
    }
}

}  // namespace sphdeck::model
