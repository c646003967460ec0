#include "lint/rules_thermal_duplicates.hpp"

#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"

namespace sphdeck::lint {
namespace {

struct ThermalId {
    long long id = 0;
    grammar::Span span;  // the id as written
};

// TMID: the first field of the first card (after the title line of _TITLE), an integer or `&name` of a
// numeric parameter with a whole value defined before it; nullopt otherwise (free format, a label: left alone).
std::optional<ThermalId> thermal_id(const grammar::RawDeck& deck, const grammar::Block& b) {
    grammar::CardLinePtr line = deck.begin_lines(b) + keywords::title_lines(b.keyword);
    if (line >= deck.end_lines(b)) return std::nullopt;
    const std::string_view text = deck.text(*line);
    if (grammar::is_free_format(text)) return std::nullopt;
    const std::size_t width = b.format == grammar::CardFormat::Long ? 20 : 10;
    const grammar::ValueToken token = grammar::classify_value(text.substr(0, std::min(text.size(), width)));
    long long id = 0;
    if (token.shape == grammar::ValueShape::Parameter) {
        const grammar::Parameter* p = deck.parameters.find(token.name, line->file, b.parameter_epoch).parameter;
        if (!p || p->type == grammar::ParameterType::Character || p->number != std::floor(p->number) ||
            std::abs(p->number) > 1e15)
            return std::nullopt;
        id = static_cast<long long>(token.negated ? -p->number : p->number);
    } else {
        const grammar::IntegerValue v = grammar::to_integer(token);
        if (token.shape != grammar::ValueShape::Integer || v.status != grammar::NumberStatus::Ok) return std::nullopt;
        id = v.value;
    }
    return ThermalId{id, grammar::Span{line->file, line->line, static_cast<std::uint32_t>(token.offset + 1),
                                       static_cast<std::uint32_t>(token.offset + token.text.size() + 1)}};
}

}  // namespace

void check_thermal_material_duplicates(RuleContext& c, const model::CaseBlocks& cases) {
    std::map<long long, std::vector<grammar::Span>> seen;
    for (const grammar::Block& b : c.deck.blocks) {
        if (b.keyword.rfind("*MAT_THERMAL_", 0) != 0) continue;
        const auto tmid = thermal_id(c.deck, b);
        if (!tmid) continue;
        auto& earlier = seen[tmid->id];
        const std::string_view in_case = cases.case_of(tmid->span);
        for (const grammar::Span& first : earlier) {
            if (!model::same_run(cases.case_of(first), in_case)) continue;
            c.report("REF006", tmid->span, fmt::format("thermal material {} is defined twice", tmid->id))
                .notes.push_back({first, "first defined here"});
            break;
        }
        earlier.push_back(tmid->span);
    }
}

ThermalMaterialIds thermal_material_ids(const grammar::RawDeck& deck) {
    ThermalMaterialIds out;
    for (const grammar::Block& b : deck.blocks) {
        if (b.keyword.rfind("*MAT_THERMAL_", 0) != 0) continue;
        if (deck.begin_lines(b) + keywords::title_lines(b.keyword) >= deck.end_lines(b)) continue;  // no card
        if (const auto tmid = thermal_id(deck, b))
            out.ids.insert(std::to_string(tmid->id));
        else
            out.unreadable = true;
    }
    return out;
}

}  // namespace sphdeck::lint
