#include "model/radioss_unknown_causes.hpp"

#include <fmt/format.h>
#include <cctype>
#include <string>

#include "grammar/fields.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/keyword_lookup.hpp"
#include "grammar/value.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

namespace {

bool is_number_token(std::string_view s) {
    return !s.empty() && grammar::parse_integer(s).status == grammar::NumberStatus::Ok;
}

std::string listed(const std::vector<std::string>& options) {
    constexpr std::size_t shown = 8;
    std::string out;
    for (std::size_t k = 0; k < options.size() && k < shown; ++k) out += (k ? ", " : "") + options[k];
    if (options.size() > shown) out += fmt::format(" and {} more", options.size() - shown);
    return out;
}

// "/GRSH3N/1" or "/GRSH3N": the family alone, then ids.
std::optional<diag::Diagnostic> option_missing(const grammar::Block& block,
                                               const std::vector<std::string_view>& segments) {
    for (std::size_t k = 1; k < segments.size(); ++k)
        if (!is_number_token(grammar::trim_blanks(segments[k]))) return std::nullopt;
    const std::string family = "/" + std::string(grammar::trim_blanks(segments.front()));
    const auto options = rad::options_below(family);
    if (options.empty()) return std::nullopt;
    std::string message = fmt::format("{} lacks its {}: the header is {}/<{}>/<id>", block.keyword,
                                      family.rfind("/GR", 0) == 0 ? "group type" : "option", family,
                                      family.rfind("/GR", 0) == 0 ? "type" : "option");
    if (const rad::KeywordSpec* k = rad::find_generated(family + "/" + options.front()); k && k->title)
        message += ", followed by a title line";
    message += fmt::format(" ({} is one of {})", family.rfind("/GR", 0) == 0 ? "type" : "option", listed(options));
    diag::Diagnostic d{"DK001", diag::Severity::Error, std::move(message), block.span, {}};
    d.notes.push_back({grammar::Span{}, "sphdeck reads the deck without this block: its cards are not checked"});
    return d;
}

// "/INCLUDE "mesh.inc"": OpenRadioss reads `#include mesh.inc`.
std::optional<diag::Diagnostic> include_keyword(const grammar::RawDeck& deck, const grammar::Block& block) {
    const std::string_view line = deck.sources.line_text(block.span.file, block.span.line);
    const std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string_view::npos || line.substr(at, 8).size() < 8) return std::nullopt;
    std::string word(line.substr(at + 1, 7));
    for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (line[at] != '/' || word != "INCLUDE") return std::nullopt;
    if (at + 8 < line.size() && std::string_view(" \t/\"'").find(line[at + 8]) == std::string_view::npos)
        return std::nullopt;  // another name (/INCLUDE_LS-DYNA is a keyword)
    std::string_view file = grammar::trim_blanks(line.substr(at + 8));
    if (!file.empty() && file.front() == '/') file = grammar::trim_blanks(file.substr(1));
    if (file.size() >= 2 && (file.front() == '"' || file.front() == '\'') && file.back() == file.front())
        file = file.substr(1, file.size() - 2);
    std::string message = "OpenRadioss has no /INCLUDE keyword: a file is included by a line ";
    const std::string replacement = file.empty() ? std::string("#include <file>") : fmt::format("#include {}", file);
    message += fmt::format("'{}'", replacement);
    diag::Diagnostic d{"DK001", diag::Severity::Error, std::move(message), block.span, {}};
    d.notes.push_back({grammar::Span{}, "sphdeck reads the deck without this block and the file it names"});
    if (!file.empty()) {
        grammar::Span whole = block.span;
        whole.column = static_cast<std::uint32_t>(at + 1);
        whole.end_column = static_cast<std::uint32_t>(line.size() + 1);
        d.fixes.push_back({fmt::format("write '{}'", replacement), false, {{whole, replacement}}});
    }
    return d;
}

}  // namespace

std::optional<diag::Diagnostic> unknown_header_cause(const grammar::RawDeck& deck, const grammar::Block& block) {
    if (auto include = include_keyword(deck, block)) return include;
    const auto segments = rad::path_segments(block.keyword);
    if (segments.empty()) return std::nullopt;
    return option_missing(block, segments);
}

}  // namespace sphdeck::model
