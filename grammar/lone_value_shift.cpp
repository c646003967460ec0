#include "grammar/lone_value_shift.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "grammar/line_tokens.hpp"
#include "grammar/shifted_line.hpp"
#include "grammar/value.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::grammar {
namespace {

using keywords::FieldType;

constexpr std::size_t max_lone_shift = 4;  // "a few columns", as grammar/shifted_line.cpp

std::size_t lone_slot_end(const FixedField& f) { return std::size_t{f.start} + f.width; }

// A label field (an id that may be alphanumeric, *SECTION_SPH SECID) holds a number as a rule: a value moved
// back into it reads (the tally of a deck's habit counts integers and reals only, as before).
bool lone_number_field(FieldType t) { return t == FieldType::Integer || t == FieldType::Real || t == FieldType::Label; }

bool tallied_field(FieldType t, Judged judged) {
    return judged == Judged::Integers ? t == FieldType::Integer : t == FieldType::Integer || t == FieldType::Real;
}

bool judged_field(FieldType t, Judged judged) {
    return judged == Judged::Integers ? t == FieldType::Integer || t == FieldType::Label : lone_number_field(t);
}

// The field holding [begin, end) whole, or `fields` when none does.
std::size_t lone_field_of(std::size_t begin, std::size_t end, std::span<const FixedField> slots, std::size_t fields) {
    for (std::size_t s = 0; s < fields; ++s)
        if (slots[s].start <= begin && end <= lone_slot_end(slots[s])) return s;
    return fields;
}

}  // namespace

void tally_alignment(std::string_view text, std::span<const FixedField> slots, std::span<const FieldType> types,
                     AlignmentTally& tally, Judged judged) {
    const std::size_t fields = std::min(slots.size(), types.size());
    for_each_token(text, [&](const LineToken& t) {
        const std::size_t s = lone_field_of(t.begin, t.end, slots, fields);
        if (s == fields || !tallied_field(types[s], judged)) return true;
        if (t.end == lone_slot_end(slots[s]))
            ++tally.right;
        else
            ++tally.other;
        return true;
    });
}

std::optional<LoneShift> find_lone_shift(std::string_view text, std::span<const FixedField> slots,
                                         std::span<const FieldType> types, Judged judged) {
    constexpr std::size_t max_values = 8;
    if (text.find('\t') != std::string_view::npos || is_free_format(text)) return std::nullopt;
    // At most max_values tokens, kept on the stack: this runs on every line the serial walk decodes.
    std::array<LineToken, max_values> kept{};
    std::size_t count = 0;
    bool too_many = false;
    for_each_token(text, [&](const LineToken& t) {
        if (count == max_values) return !(too_many = true);
        kept[count++] = t;
        return true;
    });
    const std::span<const LineToken> tokens(kept.data(), count);
    if (tokens.empty() || too_many) return std::nullopt;
    const std::size_t fields = std::min(slots.size(), types.size());
    // As written: every value whole in a number field, none judged at its field's end.
    std::size_t judged_values = 0;
    for (const LineToken& t : tokens) {
        const std::size_t k = lone_field_of(t.begin, t.end, slots, fields);
        // An integer pushed past the card's last cell (the starter drops it silently) is judged moved back.
        const bool past_last = judged == Judged::Integers && k == fields && fields > 0 &&
                               t.begin >= lone_slot_end(slots[fields - 1]) && types[fields - 1] == FieldType::Integer;
        if (past_last) {
            ++judged_values;
            continue;
        }
        if (k == fields || !lone_number_field(types[k])) return std::nullopt;
        if (!judged_field(types[k], judged)) continue;
        if (t.end == lone_slot_end(slots[k])) return std::nullopt;
        ++judged_values;
    }
    if (judged == Judged::Integers && judged_values < 2) return std::nullopt;
    std::optional<LoneShift> found;
    for (std::size_t n = 1; n <= max_lone_shift; ++n) {
        std::array<LineToken, max_values> moved_tokens = kept;
        const std::span<LineToken> moved(moved_tokens.data(), count);
        if (!place_tokens(text, moved, slots, types, static_cast<int>(n))) continue;
        const bool at_ends = std::all_of(moved.begin(), moved.end(), [&](const LineToken& t) {
            if (!lone_number_field(types[t.slot])) return false;
            return !judged_field(types[t.slot], judged) || t.end - n == lone_slot_end(slots[t.slot]);
        });
        if (!at_ends) continue;
        if (found) return std::nullopt;  // two readings: not certain
        const auto first_judged = std::find_if(moved.begin(), moved.end(),
                                               [&](const LineToken& t) { return judged_field(types[t.slot], judged); });
        const LineToken& first = first_judged != moved.end() ? *first_judged : moved.front();
        found = LoneShift{static_cast<int>(n), first.slot, lone_field_of(first.begin, first.end, slots, fields),
                          first.begin,         first.end,  judged == Judged::Integers ? judged_values : tokens.size(),
                          std::nullopt};
    }
    if (found && tokens.front().begin >= static_cast<std::size_t>(found->columns)) {
        found->realigned = text::shift_line(text, found->columns);
    }
    return found;
}

}  // namespace sphdeck::grammar
