#include "grammar/line_tokens.hpp"

#include <algorithm>

#include "grammar/value.hpp"

namespace sphdeck::grammar {

using keywords::FieldType;

std::vector<LineToken> line_tokens(std::string_view text) {
    std::vector<LineToken> tokens;
    // A card line holds up to 10 fields: one allocation for nearly every line, not four as it grows.
    tokens.reserve(std::min<std::size_t>(text.size() / 2 + 1, 16));
    for_each_token(text, [&](const LineToken& t) {
        tokens.push_back(t);
        return true;
    });
    return tokens;
}

bool reads_as(std::string_view token, FieldType type) {
    const ValueToken value = classify_value(token, type == FieldType::Real ? ValueShape::Real : ValueShape::Integer);
    if (value.shape == ValueShape::Parameter) return true;
    switch (type) {
        case FieldType::Real: return to_real(value).status == NumberStatus::Ok;
        case FieldType::Integer: return to_integer(value).status == NumberStatus::Ok;
        case FieldType::Label:
        case FieldType::Text: return true;
        case FieldType::Unused: return false;
    }
    return false;
}

}  // namespace sphdeck::grammar
