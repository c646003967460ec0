#include "grammar/line_tokens.hpp"

#include "grammar/value.hpp"

namespace sphdeck::grammar {

using keywords::FieldType;

std::vector<LineToken> line_tokens(std::string_view text) {
    std::vector<LineToken> tokens;
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        LineToken t{i, i, 0};
        while (t.end < text.size() && text[t.end] != ' ') ++t.end;
        i = t.end;
        tokens.push_back(t);
    }
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
