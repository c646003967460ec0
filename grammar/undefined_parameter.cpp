#include "grammar/undefined_parameter.hpp"

#include <cctype>
#include <fmt/format.h>

#include "grammar/similar_names.hpp"

namespace sphdeck::grammar {

namespace {
bool starts_with_folded(std::string_view whole, std::string_view start) {
    if (start.size() >= whole.size()) return false;
    for (std::size_t i = 0; i < start.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(whole[i])) != std::toupper(static_cast<unsigned char>(start[i])))
            return false;
    return true;
}
}  // namespace

diag::Diagnostic undefined_parameter(const ParameterTable& table, const UndefinedReference& ref, Span span, FileId file,
                                     std::uint32_t epoch) {
    diag::Diagnostic d{"DK012", diag::Severity::Error, fmt::format("undefined parameter '{}'", ref.name), span, {}};
    const std::vector<std::string> names = table.visible_names(file, epoch);
    if (ref.fills_field) {
        // The field ends where the name ends: a longer defined name that starts the same way was cut.
        for (const std::string& n : names)
            if (starts_with_folded(n, ref.name)) {
                d.message = fmt::format(
                    "undefined parameter '{}': the name is longer than its field; '&{}' does not "
                    "fit in {} columns and is read as '&{}'",
                    ref.name, n, ref.field_width, ref.name);
                d.notes.push_back({Span{}, "use a shorter parameter name, or long format (+) for 20-column fields"});
                return d;
            }
    }
    const auto close = closest_names(ref.name, names, 1, true);
    if (close.empty()) return d;
    d.message += fmt::format("; did you mean '{}'?", close.front());
    if (ref.name_span.valid())
        d.fixes.push_back({fmt::format("use parameter '{}'", close.front()), false, {{ref.name_span, close.front()}}});
    return d;
}

UndefinedReference reference_in_field(const ValueToken& token, std::string_view field_text, Span field_span,
                                      std::uint32_t fixed_width) {
    UndefinedReference ref;
    ref.name = token.name;
    // The name is a view into the field's text: its columns follow from its place there.
    if (token.name.data() >= field_text.data() &&
        token.name.data() + token.name.size() <= field_text.data() + field_text.size()) {
        const auto at = static_cast<std::uint32_t>(token.name.data() - field_text.data());
        ref.name_span = Span{field_span.file, field_span.line, field_span.column + at,
                             field_span.column + at + static_cast<std::uint32_t>(token.name.size())};
        ref.fills_field =
            fixed_width > 0 && field_text.size() == fixed_width && at + token.name.size() == field_text.size();
        ref.field_width = fixed_width;
    }
    return ref;
}

}  // namespace sphdeck::grammar
