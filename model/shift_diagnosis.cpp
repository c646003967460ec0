#include "model/shift_diagnosis.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <optional>

#include <fmt/format.h>

#include "grammar/fields.hpp"
#include "grammar/shifted_line.hpp"
#include "model/card_decoder.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::model {
namespace {

constexpr std::size_t max_width_notes = 10;       // a block's folded findings shown as notes
constexpr std::size_t max_fix_lines = 100000;     // past this a block's rewrite is left to a script
constexpr std::size_t max_header_distance = 512;  // longest `$#` line looked back over

grammar::Span line_span(const grammar::RawDeck& deck, const grammar::CardLine& line, bool from_first_value) {
    const std::string_view text = deck.text(line);
    std::size_t first = 0;
    if (from_first_value)
        while (first < text.size() && text[first] == ' ') ++first;
    if (first == text.size()) first = 0;
    return grammar::Span{line.file, line.line, static_cast<std::uint32_t>(first + 1),
                         static_cast<std::uint32_t>(std::max<std::size_t>(text.size(), first + 1) + 1)};
}

diag::TextEdit whole_line_edit(const grammar::RawDeck& deck, const grammar::CardLine& line, std::string text) {
    return text::whole_line_edit(line.file, line.line, deck.text(line).size(), std::move(text));
}

std::string card_name(const keywords::CardSpec& card) {
    std::string name(card.name.empty() ? "card" : card.name);
    if (!name.empty()) name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
    return name;
}

std::string_view field_text(std::string_view text, const grammar::FixedField& f) {
    return f.start >= text.size() ? std::string_view{} : grammar::trim_blanks(text.substr(f.start, f.width));
}

// "as written BOXID holds '15' and IDIM '0'; moved back, BOXID holds '150'": the fields that change.
std::string reading_note(std::string_view written, std::string_view meant, std::span<const grammar::FixedField> slots,
                         const keywords::CardSpec& card) {
    std::string before, after;
    std::size_t shown = 0;
    for (std::size_t i = 0; i < slots.size() && i < card.fields.size() && shown < 4; ++i) {
        const std::string_view a = field_text(written, slots[i]), b = field_text(meant, slots[i]);
        if (a == b) continue;
        ++shown;
        before += fmt::format("{}{} '{}'", before.empty() ? "" : ", ", card.fields[i].name, a);
        after += fmt::format("{}{} '{}'", after.empty() ? "" : ", ", card.fields[i].name, b);
    }
    if (before.empty()) return {};
    return fmt::format("as written the fields read {}; with the values in their fields: {}", before, after);
}

// One value pushed across the end of its field (grammar::find_straddle): the solver reads its two
// parts in two fields, silently when both are numbers.
std::optional<diag::Diagnostic> straddling_value(const grammar::RawDeck& deck, const grammar::Block& block,
                                                 const SuspectLine& s, std::string_view text,
                                                 std::span<const grammar::FixedField> slots) {
    auto found = grammar::find_straddle(text, slots, *s.card);
    if (!found) return std::nullopt;
    const grammar::FixedField& left = slots[found->field];
    const std::size_t boundary = std::size_t{left.start} + left.width;
    const std::string_view whole = text.substr(found->begin, found->end - found->begin);
    const std::string_view kept = text.substr(found->begin, boundary - found->begin);
    const std::string_view lost = text.substr(boundary, found->end - boundary);
    const auto& here = s.card->fields[found->field];
    const auto& next = s.card->fields[found->field + 1];
    const std::string reading =
        next.type == keywords::FieldType::Unused
            ? fmt::format("read as {} {}; '{}' falls in an unused field and is lost", here.name, kept, lost)
            : fmt::format("read as {} {} and {} {}", here.name, kept, next.name, lost);
    diag::Diagnostic d{"DK029",
                       diag::Severity::Error,
                       fmt::format("'{}' runs across the end of {} (columns {}-{}) of {} {}: {}", whole, here.name,
                                   left.start + 1, boundary, block.keyword, card_name(*s.card), reading),
                       grammar::Span{s.line->file, s.line->line, static_cast<std::uint32_t>(found->begin + 1),
                                     static_cast<std::uint32_t>(found->end + 1)},
                       {}};
    const std::size_t n = found->overrun;
    if (found->realigned)
        d.fixes.push_back(diag::Fix{fmt::format("move the line {} column{} left: '{}' then ends at column {}, the "
                                                "end of {}",
                                                n, n == 1 ? "" : "s", whole, boundary, here.name),
                                    true,
                                    {whole_line_edit(deck, *s.line, std::move(*found->realigned))}});
    else
        d.notes.push_back({grammar::Span{}, fmt::format("moved {} column{} left, '{}' would end at column {}, the "
                                                        "end of {}",
                                                        n, n == 1 ? "" : "s", whole, boundary, here.name)});
    return d;
}

// `layout`: the line's card's in the block's format.
std::optional<diag::Diagnostic> shifted_line(const grammar::RawDeck& deck, const grammar::Block& block,
                                             const SuspectLine& s, const CardLayout& layout) {
    const std::string_view text = deck.text(*s.line);
    const std::span<const grammar::FixedField> slots = layout.positions;
    // A card that starts with a long text field (a title) is never looked at: its blanks are text.
    auto shift = layout.text_card ? std::optional<grammar::LineShift>{}
                                  : grammar::find_shift(text, header_above(deck, *s.line), slots, layout.types);
    if (!shift) return straddling_value(deck, block, s, text, slots);
    const int n = std::abs(shift->columns);
    const char* side = shift->columns > 0 ? "right" : "left";
    diag::Diagnostic d{"DK029",
                       shift->changes_reading ? diag::Severity::Error : diag::Severity::Warning,
                       fmt::format("line shifted {} column{} {} of the fields of {} {}", n, n == 1 ? "" : "s", side,
                                   block.keyword, card_name(*s.card)),
                       line_span(deck, *s.line, true),
                       {}};
    if (auto note = reading_note(text, shift->realigned, slots, *s.card); !note.empty())
        d.notes.push_back({grammar::Span{}, std::move(note)});
    if (shift->from_header)
        d.notes.push_back({grammar::Span{}, "the `$#` header above names the fields at their columns"});
    d.fixes.push_back(diag::Fix{fmt::format("move the values {} column{} {} into their fields", n, n == 1 ? "" : "s",
                                            shift->columns > 0 ? "left" : "right"),
                                true,
                                {whole_line_edit(deck, *s.line, std::move(shift->realigned))}});
    return d;
}

// Every line of the block written in `written` and not read cleanly as is (at `read`), rewritten in
// the columns every reader takes.
std::vector<diag::TextEdit> rewrite_block(const grammar::RawDeck& deck, const grammar::Block& block,
                                          const keywords::CardSpec& card, std::span<const grammar::FixedField> written,
                                          std::span<const grammar::FixedField> read,
                                          std::span<const grammar::FixedField> to_write) {
    std::vector<diag::TextEdit> edits;
    if (block.line_count > max_fix_lines) return edits;
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
        const std::string_view text = deck.text(*l);
        if (!grammar::reads_aligned(text, written, card) || grammar::reads_aligned(text, read, card)) continue;
        if (auto rewritten = grammar::rewrite_fields(text, written, to_write, card))
            edits.push_back(whole_line_edit(deck, *l, std::move(*rewritten)));
    }
    return edits;
}

std::optional<diag::Diagnostic> wrong_widths(const grammar::RawDeck& deck, const grammar::Block& block,
                                             std::span<const SuspectLine> suspects) {
    constexpr std::size_t tried = 8;
    // A width is a property of the block: most of its lines misread. One line off among lines that
    // read cleanly is that line's own shift (DK029 on it), not the block's widths at its first line.
    if (suspects.size() < max_suspect_lines && 2 * suspects.size() <= block.line_count) return std::nullopt;
    for (std::size_t i = 0; i < suspects.size() && i < tried; ++i) {
        const SuspectLine& s = suspects[i];
        auto written = grammar::find_written_widths(deck.text(*s.line), *s.card, block.format);
        if (!written) continue;
        // The other lines of the same card must agree: a width is a property of the block.
        for (const SuspectLine& other : suspects)
            if (other.card == s.card && !grammar::reads_aligned(deck.text(*other.line), written->slots, *s.card))
                return std::nullopt;
        const auto read = keywords::layout(*s.card, block.format);
        const auto to_write = keywords::layout_to_write(block.keyword, *s.card, block.format);
        const grammar::CardLine& first = deck.lines[block.first_line];
        diag::Diagnostic d{"DK030",
                           diag::Severity::Error,
                           fmt::format("lines written in {} where {} reads {}", written->described, block.keyword,
                                       grammar::describe_widths(read)),
                           line_span(deck, first, true),
                           {}};
        if (block.format != grammar::CardFormat::Standard)
            d.notes.push_back({block.span, fmt::format("the block is in {} format", grammar::to_string(block.format))});
        auto edits = rewrite_block(deck, block, *s.card, written->slots, read, to_write);
        if (!edits.empty())
            d.fixes.push_back(diag::Fix{fmt::format("rewrite {} line(s) of the block in {}", edits.size(),
                                                    grammar::describe_widths(read)),
                                        true, std::move(edits)});
        return d;
    }
    return std::nullopt;
}

}  // namespace

std::string_view header_above(const grammar::RawDeck& deck, const grammar::CardLine& line, std::string_view marker) {
    const std::string_view file = deck.sources.file(line.file).text;
    if (line.offset < 3 || line.offset > file.size() || file[line.offset - 1] != '\n') return {};
    std::size_t end = line.offset - 1;  // the '\n' ending the line above
    const std::size_t floor = end > max_header_distance ? end - max_header_distance : 0;
    // The line above's start: after the last '\n' in [floor, end) (memrchr: this runs for every card line of
    // an OpenRadioss deck, a byte loop over the line above was 8 % of reading a 1M-node one).
    std::size_t begin = floor;
#ifdef __GLIBC__
    if (const void* newline = ::memrchr(file.data() + floor, '\n', end - floor))
        begin = static_cast<std::size_t>(static_cast<const char*>(newline) - file.data()) + 1;
#else
    begin = end;
    while (begin > floor && file[begin - 1] != '\n') --begin;
#endif
    if (begin > 0 && file[begin - 1] != '\n') return {};  // longer than any header
    if (end > begin && file[end - 1] == '\r') --end;
    const std::string_view above = file.substr(begin, end - begin);
    return above.substr(0, marker.size()) == marker ? above : std::string_view{};
}

diag::Diagnostic lone_value_finding(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const grammar::CardLine& line, const keywords::CardSpec& card,
                                    const grammar::LoneShift& shift, std::span<const grammar::FixedField> slots,
                                    bool refused) {
    const std::string_view text = deck.text(line);
    const std::string_view value = text.substr(shift.begin, shift.end - shift.begin);
    const auto& meant = card.fields[shift.meant];
    const auto& read = card.fields[shift.read];
    const grammar::FixedField& f = slots[shift.meant];
    const int n = shift.columns;
    const std::string head = fmt::format("line shifted {} column{} right of the fields of {} {}", n, n == 1 ? "" : "s",
                                         block.keyword, card_name(card));
    const std::string what =
        shift.values == 1
            ? fmt::format("'{}' ends {} column{} past the end of {} (columns {}-{}) and is read as {}", value, n,
                          n == 1 ? "" : "s", meant.name, f.start + 1, f.start + f.width, read.name)
            : fmt::format("its {} values end {} column{} past the ends of their fields ('{}' is read as {}, not {})",
                          shift.values, n, n == 1 ? "" : "s", value, read.name, meant.name);
    diag::Diagnostic d{
        "DK029", diag::Severity::Error, fmt::format("{}: {}", head, what), line_span(deck, line, true), {}};
    if (auto note = reading_note(text, shift.realigned.value_or(std::string{}), slots, card);
        shift.realigned && !note.empty())
        d.notes.push_back({grammar::Span{}, std::move(note)});
    d.notes.push_back({grammar::Span{},
                       "nothing straddles a field end; the deck's other numbers end at their fields' "
                       "ends (right-aligned), these do not"});
    if (shift.realigned)
        d.fixes.push_back(
            diag::Fix{fmt::format("move the values {} column{} left into their fields", n, n == 1 ? "" : "s"),
                      refused,
                      {whole_line_edit(deck, line, *shift.realigned)}});
    return d;
}

bool follows_from_shift(std::string_view code) {
    static constexpr std::string_view codes[] = {"DK002", "DK003", "DK004", "DK005", "DK006", "DK007", "DK008"};
    return std::find(std::begin(codes), std::end(codes), code) != std::end(codes);
}

bool misreading_cause(std::string_view code) {
    static constexpr std::string_view codes[] = {"DK029", "DK030", "DK032", "DK033", "DK034",
                                                 "DK035", "DK036", "DK037", "DK038"};
    return std::find(std::begin(codes), std::end(codes), code) != std::end(codes);
}

bool misread_from(const diag::Diagnostic& d, const grammar::Block& block, const grammar::CardLine& line) {
    const bool reading = follows_from_shift(d.code) || d.code == "DK009" || d.code == "DK013";
    const bool after = d.span.file == line.file && d.span.line >= line.line;
    const bool keyword_line = d.code == "DK008" && d.span.file == block.span.file && d.span.line == block.span.line;
    return reading && (after || keyword_line);
}

void fold_explained(std::vector<diag::Diagnostic>& out, std::size_t from, diag::Diagnostic cause,
                    const std::function<bool(const diag::Diagnostic&)>& explained) {
    std::size_t kept = from;
    for (std::size_t i = from; i < out.size(); ++i) {
        if (explained(out[i])) {
            cause.severity = std::max(cause.severity, out[i].severity);
            fold_into(cause, std::move(out[i]));
            continue;
        }
        if (kept != i) out[kept] = std::move(out[i]);
        ++kept;
    }
    out.resize(kept);
    out.push_back(std::move(cause));
}

void fold_into(diag::Diagnostic& cause, diag::Diagnostic&& d) {
    // On the cause's own line a code frame would show the same line again: the column says where.
    if (d.span.valid() && d.span.file == cause.span.file && d.span.line == cause.span.line)
        cause.notes.push_back({grammar::Span{}, fmt::format("column {}: {} [{}]", d.span.column, d.message, d.code)});
    else
        cause.notes.push_back({d.span, fmt::format("{} [{}]", d.message, d.code)});
}

void diagnose_shifts(const grammar::RawDeck& deck, const grammar::Block& block, std::span<const SuspectLine> suspects,
                     std::vector<diag::Diagnostic>& out, std::size_t from) {
    if (suspects.empty()) return;
    std::vector<diag::Diagnostic> causes;
    const bool widths = [&] {
        auto d = wrong_widths(deck, block, suspects);
        if (d) causes.push_back(std::move(*d));
        return d.has_value();
    }();
    if (!widths) {
        const keywords::CardSpec* laid_out = nullptr;  // the suspects of a block mostly share a card
        const CardLayout* layout = nullptr;
        for (const SuspectLine& s : suspects) {
            if (s.card != laid_out) layout = &card_layout(*s.card, block.format), laid_out = s.card;
            if (auto d = shifted_line(deck, block, s, *layout)) causes.push_back(std::move(*d));
        }
    }
    if (causes.empty()) return;

    const grammar::CardLine& first = deck.lines[block.first_line];
    const grammar::CardLine& last = deck.lines[block.first_line + block.line_count - 1];
    std::size_t hidden = 0;
    std::vector<diag::Diagnostic> kept;
    for (std::size_t i = from; i < out.size(); ++i) {
        diag::Diagnostic& d = out[i];
        if (!follows_from_shift(d.code) || d.span.file != first.file) {
            kept.push_back(std::move(d));
            continue;
        }
        if (widths && d.span.line >= first.line && d.span.line <= last.line) {
            if (causes[0].notes.size() < max_width_notes)
                fold_into(causes[0], std::move(d));
            else
                ++hidden;
            continue;
        }
        // A shift that changes nothing read (a warning) explains none of the line's findings.
        auto cause = std::find_if(causes.begin(), causes.end(), [&](const diag::Diagnostic& c) {
            return c.span.line == d.span.line && c.severity == diag::Severity::Error;
        });
        if (!widths && cause != causes.end())
            fold_into(*cause, std::move(d));
        else
            kept.push_back(std::move(d));
    }
    if (hidden > 0)
        causes[0].notes.push_back(
            {grammar::Span{}, fmt::format("and {} more finding(s) on the lines of this block", hidden)});
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    for (auto& d : kept) out.push_back(std::move(d));
    for (auto& d : causes) out.push_back(std::move(d));
}

}  // namespace sphdeck::model
