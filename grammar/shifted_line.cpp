#include "grammar/shifted_line.hpp"

#include <algorithm>
#include <array>

#include "grammar/value.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::grammar {
namespace {

using keywords::FieldType;

constexpr int max_shift = 4;  // "a few columns": a blank typed or deleted, not a rewritten line

bool text_card(const keywords::CardSpec& card) {
    return !card.fields.empty() && card.fields[0].type == FieldType::Text && card.fields[0].width >= 70;
}

bool cuttable(std::string_view text) { return text.find('\t') == std::string_view::npos && !is_free_format(text); }
bool cuttable(std::string_view text, const keywords::CardSpec& card) { return cuttable(text) && !text_card(card); }

std::size_t slot_end(const FixedField& f) { return std::size_t{f.start} + f.width; }

// Every token, moved `shift` left, ends at its field's end (or, unless `right_only`, starts at its start).
bool aligned(const std::vector<LineToken>& tokens, std::span<const FixedField> slots, int shift, bool right_only) {
    return std::all_of(tokens.begin(), tokens.end(), [&](const LineToken& t) {
        const auto b = static_cast<std::ptrdiff_t>(t.begin) - shift, e = static_cast<std::ptrdiff_t>(t.end) - shift;
        const FixedField& s = slots[t.slot];
        return e == static_cast<std::ptrdiff_t>(slot_end(s)) ||
               (!right_only && b == static_cast<std::ptrdiff_t>(s.start));
    });
}

// A `$#` (OpenRadioss: `#`) header whose names all end at field ends: the deck's writer right-aligns
// to the fields.
bool header_aligned(std::string_view header, std::span<const FixedField> slots, std::size_t fields) {
    const std::size_t marker = header.substr(0, 2) == "$#" ? 2 : header.substr(0, 1) == "#" ? 1 : 0;
    if (marker == 0) return false;
    std::size_t names = 0;
    bool all_at_ends = true;
    for_each_token(header.substr(marker), [&](const LineToken& t) {
        ++names;
        const std::size_t end = marker + t.end;  // a column of the header line
        all_at_ends = false;
        for (std::size_t s = 0; s < slots.size() && s < fields && !all_at_ends; ++s)
            all_at_ends = slot_end(slots[s]) == end;
        return all_at_ends;
    });
    return all_at_ends && names >= 2;
}

std::string_view shifted_field_text(std::string_view text, const FixedField& f) {
    if (f.start >= text.size()) return {};
    return trim_blanks(text.substr(f.start, f.width));
}

bool same_reading(std::string_view a, std::string_view b, std::span<const FixedField> slots) {
    for (const FixedField& f : slots)
        if (shifted_field_text(a, f) != shifted_field_text(b, f)) return false;
    const std::size_t end = slots.empty() ? 0 : slot_end(slots.back());
    return trim_blanks(a.size() > end ? a.substr(end) : std::string_view{}) ==
           trim_blanks(b.size() > end ? b.substr(end) : std::string_view{});
}

bool same_slots(std::span<const FixedField> a, std::span<const FixedField> b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const FixedField& x, const FixedField& y) {
        return x.start == y.start && x.width == y.width;
    });
}

// Standard widths with every 10-column field written in 8 (offsets follow).
std::vector<FixedField> narrowed_to_8(std::span<const FixedField> standard) {
    std::vector<FixedField> out;
    out.reserve(standard.size());
    std::uint32_t at = 0, prev_end = 0;
    for (const FixedField& f : standard) {
        at += f.start > prev_end ? f.start - prev_end : 0;  // a gap keeps its width
        const std::uint32_t w = f.width == 10 ? 8 : f.width;
        out.push_back({at, w});
        at += w;
        prev_end = f.start + f.width;
    }
    return out;
}

// Every field 8 wide, one after the other: how a person types a *NODE or *ELEMENT_SPH line (standard
// widths 8/16 mixed) when they take every field for 8 columns.
std::vector<FixedField> all_8_wide(std::span<const FixedField> standard) {
    std::vector<FixedField> out;
    out.reserve(standard.size());
    std::uint32_t at = 0;
    for (std::size_t i = 0; i < standard.size(); ++i, at += 8) out.push_back({at, 8});
    return out;
}

// `text` with the columns of its text fields, moved `shift` right, blanked: a text value's own alignment
// (LS-PrePost writes *SET_NODE_LIST's SOLVER `MECH` left-aligned, glued to DA4's `0.0`) is evidence
// neither for nor against a shift; the numbers decide.
// Into `out`, reusing its capacity (a line is tried at up to 9 shifts).
void without_text_fields(std::string_view text, std::span<const FixedField> slots, std::span<const FieldType> types,
                         int shift, std::string& out) {
    out.assign(text);
    for (std::size_t i = 0; i < slots.size() && i < types.size(); ++i) {
        if (types[i] != FieldType::Text) continue;
        const std::ptrdiff_t from = std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(slots[i].start) + shift);
        const std::ptrdiff_t to = static_cast<std::ptrdiff_t>(slot_end(slots[i])) + shift;
        for (std::ptrdiff_t c = from; c < to && c < static_cast<std::ptrdiff_t>(out.size()); ++c)
            out[static_cast<std::size_t>(c)] = ' ';
    }
}

// Every token placed in an integer field is written as an integer (or a parameter). A shift that would
// put a real such as `1.0` there is no reading the author evidently meant: read in place, that real sat in
// a real field (ENDTIM `1.0` moved into ENDCYC), and LS-DYNA's and the starter's readers differ on a real in an
// integer field (DK004).
bool integers_written_as_integers(std::string_view text, const std::vector<LineToken>& tokens,
                                  std::span<const FieldType> types) {
    return std::all_of(tokens.begin(), tokens.end(), [&](const LineToken& t) {
        if (t.slot >= types.size() || types[t.slot] != FieldType::Integer) return true;
        const ValueShape shape = classify_value(text.substr(t.begin, t.end - t.begin)).shape;
        return shape == ValueShape::Integer || shape == ValueShape::Parameter;
    });
}

}  // namespace

std::vector<FieldType> field_types(const keywords::CardSpec& card) {
    std::vector<FieldType> types;
    types.reserve(card.fields.size());
    for (const auto& f : card.fields) types.push_back(f.type);
    return types;
}

bool place_tokens(std::string_view text, std::span<LineToken> tokens, std::span<const FixedField> slots,
                  std::span<const FieldType> types, int shift) {
    const std::size_t fields = std::min(slots.size(), types.size());
    // Which fields hold a token: a bit each for the cards of up to 64 fields (every card but a few), else a
    // vector (this runs on every line the serial walk tallies).
    std::uint64_t taken_bits = 0;
    std::vector<bool> taken_many(fields > 64 ? fields : 0, false);
    const auto taken = [&](std::size_t s) { return fields > 64 ? taken_many[s] : ((taken_bits >> s) & 1U) != 0; };
    const auto take = [&](std::size_t s) {
        if (fields > 64)
            taken_many[s] = true;
        else
            taken_bits |= std::uint64_t{1} << s;
    };
    for (LineToken& t : tokens) {
        const auto b = static_cast<std::ptrdiff_t>(t.begin) - shift, e = static_cast<std::ptrdiff_t>(t.end) - shift;
        if (b < 0) return false;
        std::size_t s = 0;
        while (s < fields && !(static_cast<std::ptrdiff_t>(slots[s].start) <= b &&
                               e <= static_cast<std::ptrdiff_t>(slot_end(slots[s]))))
            ++s;
        if (s == fields || taken(s) || types[s] == FieldType::Unused) return false;
        if (!reads_as(text.substr(t.begin, t.end - t.begin), types[s])) return false;
        take(s);
        t.slot = s;
    }
    return true;
}

std::optional<LineShift> find_shift(std::string_view text, std::string_view header, std::span<const FixedField> slots,
                                    const keywords::CardSpec& card) {
    if (text_card(card)) return std::nullopt;
    const auto types = field_types(card);
    return find_shift(text, header, slots, types);
}

std::optional<LineShift> find_shift(std::string_view text, std::string_view header, std::span<const FixedField> slots,
                                    std::span<const FieldType> types) {
    if (!cuttable(text)) return std::nullopt;
    // Judged at each shift on the numbers alone: the text fields' columns, moved as far, are blanked.
    std::string numbers;
    without_text_fields(text, slots, types, 0, numbers);
    std::vector<LineToken> tokens = line_tokens(numbers);
    if (tokens.size() < 2) return std::nullopt;  // one value shows no consistent shift
    const bool by_header = header_aligned(header, slots, types.size());
    const bool clean = place_tokens(numbers, tokens, slots, types, 0);
    if (clean && (!by_header || aligned(tokens, slots, 0, true))) return std::nullopt;
    // Without text fields nothing is blanked: the same tokens at every shift (place_tokens sets each slot again).
    const bool text_fields = std::find(types.begin(), types.end(), FieldType::Text) != types.end();
    std::optional<LineShift> found;
    for (int n = -max_shift; n <= max_shift; ++n) {
        if (n == 0) continue;
        if (text_fields) {
            without_text_fields(text, slots, types, n, numbers);
            tokens.clear();
            for_each_token(numbers, [&](const LineToken& t) {
                tokens.push_back(t);
                return true;
            });
        }
        if (tokens.size() < 2 || !place_tokens(numbers, tokens, slots, types, n)) continue;
        if (!integers_written_as_integers(numbers, tokens, types)) continue;
        const bool header_says = by_header && aligned(tokens, slots, n, true);
        const bool straddles_say = !clean && aligned(tokens, slots, n, false);
        if (!header_says && !straddles_say) continue;
        if (found) return std::nullopt;  // two readings: not certain
        found = LineShift{n, false, header_says, text::shift_line(text, n)};
    }
    if (found) found->changes_reading = !same_reading(text, found->realigned, slots);
    return found;
}

std::optional<Straddle> find_straddle(std::string_view text, std::span<const FixedField> slots,
                                      const keywords::CardSpec& card) {
    if (!cuttable(text, card)) return std::nullopt;
    const auto types = field_types(card);
    const std::size_t fields = std::min(slots.size(), types.size());
    std::vector<LineToken> tokens = line_tokens(text);
    std::vector<bool> taken(fields, false);
    std::optional<Straddle> found;
    for (LineToken& t : tokens) {
        std::size_t s = 0;
        while (s < fields && !(slots[s].start <= t.begin && t.begin < slot_end(slots[s]))) ++s;
        if (s == fields || taken[s]) return std::nullopt;
        taken[s] = true;
        t.slot = s;
        if (t.end <= slot_end(slots[s])) continue;
        // Runs across the end of field s: one value, pushed right, short enough for its field.
        if (found || s + 1 >= fields || slots[s + 1].start != slot_end(slots[s])) return std::nullopt;
        if (t.begin == slots[s].start || t.end >= slot_end(slots[s + 1]) || t.end - t.begin > slots[s].width)
            return std::nullopt;
        const bool number_field =
            types[s] == FieldType::Integer || types[s] == FieldType::Real || types[s] == FieldType::Label;
        if (!number_field || types[s + 1] == FieldType::Text || taken[s + 1]) return std::nullopt;
        const std::string_view whole = text.substr(t.begin, t.end - t.begin);
        if (parse_real(whole).status != NumberStatus::Ok || !reads_as(whole, types[s])) return std::nullopt;
        taken[s + 1] = true;
        found = Straddle{s, t.begin, t.end, t.end - slot_end(slots[s]), std::nullopt};
    }
    if (!found) return std::nullopt;
    // The fix moves the whole line: only when it has the blanks to lose and no value changes field.
    const int n = static_cast<int>(found->overrun);
    if (text.find_first_not_of(' ') >= found->overrun) {
        std::vector<LineToken> moved = tokens;
        if (place_tokens(text, moved, slots, types, n) &&
            std::equal(moved.begin(), moved.end(), tokens.begin(),
                       [](const LineToken& a, const LineToken& b) { return a.slot == b.slot; }))
            found->realigned = text::shift_line(text, n);
    }
    return found;
}

bool reads_aligned(std::string_view text, std::span<const FixedField> slots, const keywords::CardSpec& card) {
    std::vector<LineToken> tokens = line_tokens(text);
    return place_tokens(text, tokens, slots, field_types(card), 0) && aligned(tokens, slots, 0, false);
}

std::optional<WrittenWidths> find_written_widths(std::string_view text, const keywords::CardSpec& card,
                                                 CardFormat format) {
    if (!cuttable(text, card)) return std::nullopt;
    std::vector<LineToken> tokens = line_tokens(text);
    if (tokens.size() < 2) return std::nullopt;
    // The layouts in the three formats (the one read among them), then 8-column variants of the standard one.
    constexpr CardFormat formats[] = {CardFormat::Standard, CardFormat::I10, CardFormat::Long};
    std::array<std::vector<FixedField>, 5> candidates;
    const std::size_t read_at =
        static_cast<std::size_t>(std::find(std::begin(formats), std::end(formats), format) - std::begin(formats));
    candidates[read_at] = keywords::layout(card, format);
    const std::vector<FixedField>& read = candidates[read_at];
    const auto types = field_types(card);
    if (place_tokens(text, tokens, read, types, 0)) return std::nullopt;
    for (std::size_t i = 0; i < std::size(formats); ++i)
        if (i != read_at) candidates[i] = keywords::layout(card, formats[i]);
    const std::vector<FixedField>& standard = candidates[0];
    candidates[3] = narrowed_to_8(standard);
    candidates[4] = all_8_wide(standard);
    std::optional<WrittenWidths> found;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const auto& c = candidates[i];
        if (same_slots(c, read)) continue;
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j) seen = seen || same_slots(candidates[j], c);
        if (seen || !place_tokens(text, tokens, c, types, 0) || !aligned(tokens, c, 0, false)) continue;
        if (found) return std::nullopt;
        found = WrittenWidths{c, describe_widths(c)};
    }
    return found;
}

std::optional<std::string> rewrite_fields(std::string_view text, std::span<const FixedField> from,
                                          std::span<const FixedField> to, const keywords::CardSpec& card) {
    if (!cuttable(text, card)) return std::nullopt;
    std::vector<LineToken> tokens = line_tokens(text);
    if (!place_tokens(text, tokens, from, field_types(card), 0)) return std::nullopt;
    std::string out;
    for (const LineToken& t : tokens) {
        if (t.slot >= to.size()) return std::nullopt;
        const std::size_t length = t.end - t.begin;
        const FixedField& slot = to[t.slot];
        if (length > slot.width) return std::nullopt;
        text::write_in_field(out, slot.start, slot.width, text.substr(t.begin, length),
                             card.fields[t.slot].type == FieldType::Text ? text::Align::Left : text::Align::Right);
    }
    return out;
}

std::string describe_widths(std::span<const FixedField> slots) {
    std::vector<std::uint32_t> widths;
    for (const FixedField& f : slots)
        if (std::find(widths.begin(), widths.end(), f.width) == widths.end()) widths.push_back(f.width);
    std::string out;
    for (std::uint32_t w : widths) out += (out.empty() ? "" : "/") + std::to_string(w);
    return out + "-column fields";
}

}  // namespace sphdeck::grammar
