#include "grammar/lone_value_shift.hpp"

#include "grammar/line_tokens.hpp"
#include "grammar/value.hpp"

namespace sphdeck::grammar {
namespace {

using keywords::FieldType;

constexpr std::size_t max_shift = 4;  // "a few columns", as grammar/shifted_line.cpp

std::size_t slot_end(const FixedField& f) { return std::size_t{f.start} + f.width; }

bool number_field(FieldType t) { return t == FieldType::Integer || t == FieldType::Real; }

// The field holding [begin, end) whole, or `fields` when none does.
std::size_t field_of(std::size_t begin, std::size_t end, std::span<const FixedField> slots, std::size_t fields) {
    for (std::size_t s = 0; s < fields; ++s)
        if (slots[s].start <= begin && end <= slot_end(slots[s])) return s;
    return fields;
}

}  // namespace

void tally_alignment(std::string_view text, std::span<const FixedField> slots, std::span<const FieldType> types,
                     AlignmentTally& tally) {
    const std::size_t fields = std::min(slots.size(), types.size());
    for (const LineToken& t : line_tokens(text)) {
        const std::size_t s = field_of(t.begin, t.end, slots, fields);
        if (s == fields || !number_field(types[s])) continue;
        if (t.end == slot_end(slots[s])) ++tally.right;
        else ++tally.other;
    }
}

std::optional<LoneShift> find_lone_shift(std::string_view text, std::span<const FixedField> slots,
                                         std::span<const FieldType> types) {
    if (text.find('\t') != std::string_view::npos || is_free_format(text)) return std::nullopt;
    const auto tokens = line_tokens(text);
    if (tokens.size() != 1) return std::nullopt;
    const LineToken& t = tokens.front();
    const std::size_t fields = std::min(slots.size(), types.size());
    const std::size_t k = field_of(t.begin, t.end, slots, fields);
    if (k == 0 || k == fields || t.end == slot_end(slots[k])) return std::nullopt;
    const FixedField& before = slots[k - 1];
    if (slot_end(before) != slots[k].start || !number_field(types[k - 1]) || !number_field(types[k])) return std::nullopt;
    const std::size_t past = t.end - slot_end(before);
    if (past < 1 || past > max_shift || t.end - t.begin > before.width) return std::nullopt;
    const std::string_view value = text.substr(t.begin, t.end - t.begin);
    if (!reads_as(value, types[k - 1])) return std::nullopt;
    LoneShift out{static_cast<int>(past), k - 1, k, t.begin, t.end, std::nullopt};
    if (t.begin >= past) {
        std::string moved(text.substr(past));
        while (!moved.empty() && moved.back() == ' ') moved.pop_back();
        out.realigned = std::move(moved);
    }
    return out;
}

}  // namespace sphdeck::grammar
