#include "edit/suppression_fixes.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "engine/position_index.hpp"
#include "lint/suppressions.hpp"

namespace sphdeck::edit {
namespace {

// Lines at the top of a file searched for a `disable-file=` directive to extend.
constexpr std::uint32_t kHeaderLines = 50;

// The 1-based column just after the last code of a well-formed directive of `scope` on a comment line
// (1-based `line`), or nullopt.
std::optional<std::uint32_t> directive_end(std::string_view text, grammar::FileId file, std::uint32_t line,
                                           char comment, lint::Suppression::Scope scope) {
    if (text.empty() || (text[0] != comment && text[0] != '$')) return std::nullopt;
    lint::Suppression directive;
    std::vector<diag::Diagnostic> problems;
    if (!lint::parse_suppression(text, file, line, directive, problems) || !problems.empty() ||
        directive.scope != scope || directive.items.empty())
        return std::nullopt;
    return directive.items.back().end_column;
}

// An insertion of `text` before 1-based `column` of `line`.
diag::Fix insertion(std::string description, grammar::FileId file, std::uint32_t line, std::uint32_t column,
                    std::string text) {
    return {std::move(description), false, {{grammar::Span{file, line, column, column}, std::move(text)}}};
}

}  // namespace

diag::Fix suppress_for_card(const grammar::RawDeck& deck, grammar::FileId file, std::uint32_t line,
                            std::string_view code, char comment) {
    const grammar::Block* block = engine::block_at(deck, file, line);
    const bool keyword_line = block && block->span.line == line;
    std::string description = fmt::format("suppress {} for this {}", code, keyword_line ? "keyword block" : "card");
    // A `disable=` directive just above takes the code too.
    if (line > 1) {
        const std::string_view above = deck.sources.line_text(file, line - 1);
        if (auto end = directive_end(above, file, line - 1, comment, lint::Suppression::Scope::NextBlock))
            return insertion(std::move(description), file, line - 1, *end, fmt::format(",{}", code));
    }
    return insertion(std::move(description), file, line, 1, fmt::format("{} sphdeck: disable={}\n", comment, code));
}

diag::Fix suppress_in_file(const grammar::SourceMap& sources, grammar::FileId file, std::string_view code,
                           char comment) {
    const std::uint32_t lines = std::min(sources.line_count(file), kHeaderLines);
    std::string description = fmt::format("suppress {} in this file", code);
    for (std::uint32_t l = 1; l <= lines; ++l)
        if (auto end = directive_end(sources.line_text(file, l), file, l, comment, lint::Suppression::Scope::File))
            return insertion(std::move(description), file, l, *end, fmt::format(",{}", code));
    std::uint32_t line = 1;
    if (comment == '#' && sources.line_text(file, 1).rfind("#RADIOSS", 0) == 0) line = 2;
    return insertion(std::move(description), file, line, 1,
                     fmt::format("{} sphdeck: disable-file={}\n", comment, code));
}

}  // namespace sphdeck::edit
