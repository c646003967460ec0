#include "model/decimal_comma.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "grammar/value.hpp"

namespace sphdeck::model {
namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool separator(char c) { return c == ' ' || c == ',' || c == '\t'; }

std::string shown_reading(std::string_view text) {
    constexpr std::size_t limit = 40;
    return text.size() > limit ? std::string(text.substr(0, limit)) + "..." : std::string(text);
}

}  // namespace

std::optional<DecimalComma> find_decimal_comma(std::string_view text, std::span<const grammar::FixedField> fields) {
    const std::size_t first = text.find(',');
    if (first == std::string_view::npos) return std::nullopt;
    const bool padded = first >= 2 && text[0] == ' ' && text[1] == ' ';
    std::size_t comma = first;
    while (comma != std::string_view::npos &&
           !(comma > 0 && comma + 1 < text.size() && digit(text[comma - 1]) && digit(text[comma + 1])))
        comma = text.find(',', comma + 1);
    if (comma == std::string_view::npos) return std::nullopt;
    std::size_t from = comma, to = comma + 1;
    while (from > 0 && !separator(text[from - 1])) --from;
    while (to < text.size() && !separator(text[to])) ++to;
    // Unpadded (every line of a free-format deck comes here): the word must end at its field's end before a
    // blank (not a comma: `0.002,1000,5` is free format), tested before any text is built.
    const bool in_field = std::any_of(fields.begin(), fields.end(), [&](const grammar::FixedField& f) {
        return f.width > 1 && from >= f.start && to == std::size_t{f.start} + f.width;
    });
    if (!padded && (!in_field || (to < text.size() && text[to] != ' ' && text[to] != '\t'))) return std::nullopt;
    DecimalComma found{from, to,
                       std::string(text.substr(from, comma - from)) + "." +
                           std::string(text.substr(comma + 1, to - comma - 1))};
    // And read as one number with the point (`0.002,1000` would make two points).
    if (!padded && grammar::parse_real(found.meant).status != grammar::NumberStatus::Ok) return std::nullopt;
    return found;
}

namespace {

diag::Diagnostic decimal_comma_finding(const DecimalComma& comma, const grammar::CardLine& line,
                                       std::string_view solver, std::string_view reading) {
    return diag::Diagnostic{
        "DK031",
        diag::Severity::Warning,
        fmt::format("a comma inside a fixed-format field: {} reads this line as free format{}; a decimal comma? "
                    "write {}",
                    solver, reading.empty() ? "" : fmt::format(" ({})", reading), shown_reading(comma.meant)),
        grammar::Span{line.file, line.line, static_cast<std::uint32_t>(comma.begin + 1),
                      static_cast<std::uint32_t>(comma.end + 1)},
        {}};
}

bool symptom_of_comma(const diag::Diagnostic& d, const grammar::CardLine& line) {
    static constexpr std::string_view codes[] = {"DK002", "DK003", "DK004", "DK005", "DK007"};
    return d.span.file == line.file && d.span.line == line.line &&
           std::find(std::begin(codes), std::end(codes), d.code) != std::end(codes);
}

}  // namespace

void report_decimal_comma(const DecimalComma& comma, const grammar::CardLine& line, std::string_view solver,
                          std::string_view reading, std::vector<diag::Diagnostic>& found, std::size_t first) {
    diag::Diagnostic d = decimal_comma_finding(comma, line, solver, reading);
    const auto from = found.begin() + static_cast<std::ptrdiff_t>(first);
    for (auto it = from; it != found.end(); ++it) {
        if (!symptom_of_comma(*it, line)) continue;
        if (it->severity == diag::Severity::Error) d.severity = diag::Severity::Error;
        d.notes.push_back({it->span, fmt::format("so {} ({})", it->message, it->code)});
    }
    found.erase(std::remove_if(from, found.end(), [&](const diag::Diagnostic& f) { return symptom_of_comma(f, line); }),
                found.end());
    found.push_back(std::move(d));
}

}  // namespace sphdeck::model
