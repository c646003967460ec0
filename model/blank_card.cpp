#include "model/blank_card.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {

bool blank_card_line(std::string_view text) { return text.find_first_not_of(" \t\r") == std::string_view::npos; }

bool diagnose_blank_card(const grammar::RawDeck& deck, const grammar::Block& block, const grammar::CardLine& blank,
                         const keywords::CardSpec& card, std::vector<diag::Diagnostic>& out, std::size_t from) {
    // What only a card too many explains: a required field left blank on the blank line itself, lines past the
    // keyword's last card, the keyword missing a card. Findings on the lines after it may have causes of their
    // own (a value typed wrong): the engine folds those the fix makes go away (engine/mended_consequences.cpp).
    const auto misread = [&](const diag::Diagnostic& d) {
        const bool on_blank = d.code == "DK008" && d.span.file == blank.file && d.span.line == blank.line;
        const bool extra = d.code == "DK009" && d.span.file == blank.file && d.span.line > blank.line;
        const bool keyword_line = d.code == "DK008" && d.span.file == block.span.file && d.span.line == block.span.line;
        return on_blank || extra || keyword_line;
    };
    if (std::none_of(out.begin() + static_cast<std::ptrdiff_t>(from), out.end(), misread)) return false;
    const std::string card_name = card.name.empty() ? std::string("a card") : std::string(card.name);
    diag::Diagnostic d{"DK034",
                       diag::Severity::Warning,
                       fmt::format("blank line read as {} of {}: LS-DYNA reads a blank line inside a keyword as a "
                                   "card of defaults, not as spacing, so the lines after it are read one card late",
                                   card_name, block.keyword),
                       grammar::Span{blank.file, blank.line, 1, std::max<std::uint32_t>(deck.length(blank) + 1, 2)},
                       {}};
    // Unsafe: the blank line may have been meant as a card of defaults, and a line after it too many.
    d.fixes.push_back(
        {"make the blank line a comment ('$'), so that the lines after it are read as the cards they "
         "were typed for",
         false,
         {{grammar::Span{blank.file, blank.line, 1, 1}, "$"}}});
    std::size_t kept = from;
    for (std::size_t i = from; i < out.size(); ++i) {
        if (misread(out[i])) {
            d.severity = std::max(d.severity, out[i].severity);
            fold_into(d, std::move(out[i]));
            continue;
        }
        if (kept != i) out[kept] = std::move(out[i]);
        ++kept;
    }
    out.resize(kept);
    out.push_back(std::move(d));
    return true;
}

}  // namespace sphdeck::model
