#include "grammar/realign.hpp"

#include <vector>

#include "grammar/fields.hpp"
#include "grammar/line_tokens.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::grammar {
using keywords::FieldType;

std::optional<std::string> realign_card(std::string_view text, const keywords::CardSpec& card,
                                        grammar::CardFormat format) {
    if (text.find('\t') != std::string_view::npos || grammar::is_free_format(text)) return std::nullopt;
    if (!card.fields.empty() && card.fields[0].type == FieldType::Text && card.fields[0].width >= 70)
        return std::nullopt;  // a title: its blanks are part of the text
    const auto slots = keywords::layout(card, format);
    std::vector<LineToken> tokens = line_tokens(text);
    std::vector<bool> taken(slots.size(), false);
    bool strays = false;
    for (LineToken& t : tokens) {
        std::size_t best = slots.size(), best_overlap = 0;
        bool tie = false;
        for (std::size_t s = 0; s < slots.size() && s < card.fields.size(); ++s) {
            const std::size_t lo = std::max<std::size_t>(t.begin, slots[s].start);
            const std::size_t hi = std::min<std::size_t>(t.end, slots[s].start + slots[s].width);
            const std::size_t overlap = hi > lo ? hi - lo : 0;
            if (overlap == 0) continue;
            if (overlap > best_overlap)
                best = s, best_overlap = overlap, tie = false;
            else if (overlap == best_overlap)
                tie = true;
        }
        if (best == slots.size() || tie || taken[best]) return std::nullopt;
        const auto& field = card.fields[best];
        if (field.type == FieldType::Unused || t.end - t.begin > slots[best].width) return std::nullopt;
        taken[best] = true;
        t.slot = best;
        const bool inside = t.begin >= slots[best].start && t.end <= slots[best].start + slots[best].width;
        if (!inside) {
            strays = true;
            if (!reads_as(text.substr(t.begin, t.end - t.begin), field.type)) return std::nullopt;
        }
    }
    if (!strays) return std::nullopt;
    std::string out;
    for (const LineToken& t : tokens) {
        const auto& slot = slots[t.slot];
        const std::size_t length = t.end - t.begin;
        const bool inside = t.begin >= slot.start && t.end <= slot.start + slot.width;
        const std::string_view value = text.substr(t.begin, length);
        if (inside)
            text::write_in_field(out, t.begin, length, value, text::Align::Left);  // stays where written
        else
            text::write_in_field(out, slot.start, slot.width, value,
                                 card.fields[t.slot].type == FieldType::Text ? text::Align::Left : text::Align::Right);
    }
    return out;
}

}  // namespace sphdeck::grammar
