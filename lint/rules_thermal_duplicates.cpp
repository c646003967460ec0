#include "lint/rules_thermal_duplicates.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "grammar/fields.hpp"

namespace sphdeck::lint {
namespace {

struct ThermalId {
    long long id = 0;
    grammar::Span span;  // the id as written
};

// An integer parameter's value (or a real one's, when whole) for `&name`, as the block sees it.
std::optional<long long> parameter_id(const grammar::RawDeck& deck, const grammar::Block& b, grammar::FileId file,
                                      std::string_view name) {
    const grammar::Parameter* p = deck.parameters.find(name, file, b.parameter_epoch).parameter;
    if (!p || p->type == grammar::ParameterType::Character || p->number != std::floor(p->number) ||
        std::abs(p->number) > 1e15)
        return std::nullopt;
    return static_cast<long long>(p->number);
}

// TMID: the first field of the first card (after the title line of _TITLE), a plain integer or `&name` of a
// parameter defined before it; nullopt otherwise (free format, an expression: left alone).
std::optional<ThermalId> thermal_id(const grammar::RawDeck& deck, const grammar::Block& b) {
    grammar::CardLinePtr line = deck.begin_lines(b) + keywords::title_lines(b.keyword);
    if (line >= deck.end_lines(b)) return std::nullopt;
    const std::string_view text = deck.text(*line);
    if (grammar::is_free_format(text)) return std::nullopt;
    const std::size_t width = b.format == grammar::CardFormat::Long ? 20 : 10;
    const std::string_view field = text.substr(0, std::min(text.size(), width));
    const std::size_t begin = field.find_first_not_of(' ');
    if (begin == std::string_view::npos) return std::nullopt;
    const std::size_t end = field.find_last_not_of(" \r") + 1;
    long long id = 0;
    if (field[begin] == '&') {
        const auto value = parameter_id(deck, b, line->file, field.substr(begin + 1, end - begin - 1));
        if (!value) return std::nullopt;
        id = *value;
    } else {
        auto [stop, ec] = std::from_chars(field.data() + begin, field.data() + end, id);
        if (ec != std::errc() || stop != field.data() + end) return std::nullopt;
    }
    return ThermalId{id, grammar::Span{line->file, line->line, static_cast<std::uint32_t>(begin + 1),
                                       static_cast<std::uint32_t>(end + 1)}};
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
