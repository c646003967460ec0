#include "model/unknown_keywords.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grammar/keywords/keyword_names.hpp"
#include "grammar/keywords/schema.hpp"

namespace sphdeck::model {

namespace {
// Distinct misspelt names a deck gets suggestions for: each costs a pass over every known name,
// and a deck of thousands of made-up names (a fuzzer's) must stay fast.
constexpr std::size_t max_suggested_names = 64;
}  // namespace

const std::optional<std::string>& UnknownKeywords::suggestion(const std::string& keyword) {
    auto it = suggestions_.find(keyword);
    if (it != suggestions_.end()) return it->second;
    std::optional<std::string> s;
    if (suggestions_.size() < max_suggested_names) s = keywords::suggest_keyword(keyword);
    return suggestions_.emplace(keyword, std::move(s)).first->second;
}

void UnknownKeywords::add(const grammar::RawDeck& deck, const grammar::Block& block,
                          std::vector<diag::Diagnostic>& out) {
    // DK001's policy (grammar/keywords/keyword_names.hpp): a name some source knows is no error.
    if (keywords::known_by_name(block.keyword)) {
        auto& u = unchecked_[block.keyword];
        if (u.count++ == 0) u.first = block.span;
        return;
    }
    if (auto known = keywords::known_with_options(block.keyword)) {
        out.push_back({"DK001",
                       diag::Severity::Warning,
                       fmt::format("{} is {} with {} sphdeck's tables do not give it ({}): its cards are "
                                   "not checked, and LS-DYNA stops here if it does not accept {} either",
                                   block.keyword, known->base, known->options.size() > 1 ? "options" : "an option",
                                   fmt::join(known->options, ", "), known->options.size() > 1 ? "them" : "the option"),
                       block.span,
                       {}});
        return;
    }
    const std::optional<std::string>& better = suggestion(block.keyword);
    std::string message = fmt::format("unknown keyword {}: LS-DYNA stops at a keyword it does not know", block.keyword);
    if (better) message += fmt::format("; did you mean {}?", *better);
    diag::Diagnostic d{"DK001", diag::Severity::Error, std::move(message), block.span, {}};
    d.notes.push_back({grammar::Span{},
                       "sphdeck reads the deck without this block: its cards are not checked, "
                       "and what they define or set is missing from the model"});
    if (better) {
        // The name as written (the span covers '*' and the name, not a format suffix or arguments).
        const std::string_view line = deck.sources.line_text(block.span.file, block.span.line);
        const std::size_t from = block.span.column - 1;
        const std::size_t to = std::min<std::size_t>(block.span.end_column - 1, line.size());
        const std::string_view written = from < to ? line.substr(from, to - from) : std::string_view(block.keyword);
        d.fixes.push_back({fmt::format("replace {} with {}", block.keyword, *better),
                           false,
                           {{block.span, keywords::keyword_replacement(written, *better)}}});
    }
    out.push_back(std::move(d));
}

void UnknownKeywords::finish(std::vector<diag::Diagnostic>& out) const {
    for (const auto& [name, u] : unchecked_) {
        std::string message = fmt::format("{} has no card layout in sphdeck's tables: its cards are not checked", name);
        if (u.count > 1) message += fmt::format(" ({} blocks)", u.count);
        out.push_back({"DK001", diag::Severity::Info, std::move(message), u.first, {}});
    }
}

}  // namespace sphdeck::model
