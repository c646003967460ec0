#include "grammar/tab_expansion.hpp"

#include <vector>

namespace sphdeck::grammar {
namespace {

// The field of each blank-separated value of `text`, in order, or nullopt when a value lies across a
// field boundary, in a gap or past the last field, two values share a field, or a value is neither
// right- nor left-aligned in its field.
std::optional<std::vector<std::size_t>> fields_of_values(std::string_view text, std::span<const FixedField> positions) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        const std::size_t begin = i;
        while (i < text.size() && text[i] != ' ') ++i;
        std::size_t field = positions.size();
        for (std::size_t k = 0; k < positions.size(); ++k)
            if (begin >= positions[k].start && begin - positions[k].start < positions[k].width) field = k;
        if (field == positions.size() || i - positions[field].start > positions[field].width) return std::nullopt;
        // Laid out on purpose: the value starts at its field's start or ends at its end.
        if (begin != positions[field].start && i != std::size_t{positions[field].start} + positions[field].width)
            return std::nullopt;
        if (!out.empty() && out.back() == field) return std::nullopt;
        out.push_back(field);
    }
    return out;
}

}  // namespace

std::string expand_tabs(std::string_view text, std::size_t stop) {
    std::string out;
    out.reserve(text.size() + 16);
    for (char c : text) {
        if (c == '\t')
            out.append(stop - out.size() % stop, ' ');
        else
            out += c;
    }
    return out;
}

std::optional<std::string> expand_tabs_if_certain(std::string_view text, std::span<const FixedField> positions) {
    if (text.find('\t') == std::string_view::npos || text.find(',') != std::string_view::npos) return std::nullopt;
    const std::string at8 = expand_tabs(text, 8);
    const auto fields8 = fields_of_values(at8, positions);
    if (!fields8 || fields8->empty()) return std::nullopt;
    // An editor with tab stops every 4 columns showing the values in other fields, as cleanly: the
    // author's layout is a guess.
    if (const auto fields4 = fields_of_values(expand_tabs(text, 4), positions); fields4 && *fields4 != *fields8)
        return std::nullopt;
    return at8;
}

}  // namespace sphdeck::grammar
