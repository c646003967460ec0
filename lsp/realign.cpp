#include "lsp/realign.hpp"

#include <vector>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"

namespace sphdeck::lsp {
namespace {

using keywords::FieldType;

struct Token {
    std::size_t begin = 0, end = 0;  // 0-based [begin, end)
    std::size_t slot = 0;
};

bool reads_as(std::string_view token, FieldType type) {
    const grammar::ValueToken value =
        grammar::classify_value(token, type == FieldType::Real ? grammar::ValueShape::Real : grammar::ValueShape::Integer);
    if (value.shape == grammar::ValueShape::Parameter) return true;
    switch (type) {
        case FieldType::Real: return grammar::to_real(value).status == grammar::NumberStatus::Ok;
        case FieldType::Integer: return grammar::to_integer(value).status == grammar::NumberStatus::Ok;
        case FieldType::Label:
        case FieldType::Text: return true;
        case FieldType::Unused: return false;
    }
    return false;
}

}  // namespace

std::optional<std::string> realign_card(std::string_view text, const keywords::CardSpec& card,
                                        grammar::CardFormat format) {
    if (text.find('\t') != std::string_view::npos || grammar::is_free_format(text)) return std::nullopt;
    if (!card.fields.empty() && card.fields[0].type == FieldType::Text && card.fields[0].width >= 70)
        return std::nullopt;  // a title: its blanks are part of the text
    const auto slots = keywords::layout(card, format);
    std::vector<Token> tokens;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        Token t{i, i, 0};
        while (t.end < text.size() && text[t.end] != ' ') ++t.end;
        i = t.end;
        tokens.push_back(t);
    }
    std::vector<bool> taken(slots.size(), false);
    bool strays = false;
    for (Token& t : tokens) {
        std::size_t best = slots.size(), best_overlap = 0;
        bool tie = false;
        for (std::size_t s = 0; s < slots.size() && s < card.fields.size(); ++s) {
            const std::size_t lo = std::max<std::size_t>(t.begin, slots[s].start);
            const std::size_t hi = std::min<std::size_t>(t.end, slots[s].start + slots[s].width);
            const std::size_t overlap = hi > lo ? hi - lo : 0;
            if (overlap == 0) continue;
            if (overlap > best_overlap) best = s, best_overlap = overlap, tie = false;
            else if (overlap == best_overlap) tie = true;
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
    for (const Token& t : tokens) {
        const auto& slot = slots[t.slot];
        const std::size_t length = t.end - t.begin;
        const bool inside = t.begin >= slot.start && t.end <= slot.start + slot.width;
        std::size_t at = t.begin;
        if (!inside) at = card.fields[t.slot].type == FieldType::Text ? slot.start : slot.start + slot.width - length;
        if (out.size() < at + length) out.resize(at + length, ' ');
        out.replace(at, length, text.substr(t.begin, length));
    }
    return out;
}

}  // namespace sphdeck::lsp
