#include "model/repeated_line.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

std::string_view without_trailing_blanks(std::string_view text) {
    const std::size_t end = text.find_last_not_of(" \t\r");
    return end == std::string_view::npos ? std::string_view{} : text.substr(0, end + 1);
}

}  // namespace

bool repeats_line_above(const grammar::RawDeck& deck, const grammar::Block& block, grammar::CardLinePtr line) {
    if (line == deck.begin_lines(block)) return false;
    const grammar::CardLine& above = line[-1];
    if (above.file != line->file) return false;  // comment lines between them are no matter
    const std::string_view text = without_trailing_blanks(deck.text(*line));
    return !text.empty() && text == without_trailing_blanks(deck.text(above));
}

bool diagnose_repeated_line(const grammar::RawDeck& deck, const grammar::Block& block,
                            std::span<const RepeatedLine> copies, const ReadsWithout& reads_without,
                            std::vector<diag::Diagnostic>& out, std::size_t from) {
    const auto found = std::span<const diag::Diagnostic>(out).subspan(from);
    const RepeatedLine* cause = nullptr;
    for (const RepeatedLine& c : copies)
        if (std::any_of(found.begin(), found.end(),
                        [&](const diag::Diagnostic& d) { return misread_from(d, block, *c.line); }) &&
            reads_without(c.line)) {
            cause = &c;
            break;
        }
    if (!cause) return false;
    const grammar::CardLine& copy = *cause->line;
    const std::string_view text = deck.text(copy);
    const auto first = static_cast<std::uint32_t>(std::min(text.find_first_not_of(' '), text.size()) + 1);
    const std::string card = cause->card->name.empty() ? std::string("a card") : std::string(cause->card->name);
    diag::Diagnostic d{
        "DK036",
        diag::Severity::Warning,
        fmt::format("this line repeats the data line before it: LS-DYNA reads the copy as {} of {}, so the "
                    "lines after it are read one card late (the block reads cleanly without it)",
                    card, block.keyword),
        grammar::Span{copy.file, copy.line, first, static_cast<std::uint32_t>(text.size() + 1)},
        {}};
    // Unsafe: which of the two lines was meant, and whether a card was meant to follow in its place, is a
    // judgement; a comment keeps the text.
    d.fixes.push_back(
        {"make the copy a comment ('$'), so that the lines after it are read as the cards they were "
         "typed for",
         false,
         {{grammar::Span{copy.file, copy.line, 1, 1}, "$"}}});
    fold_explained(out, from, std::move(d), [&](const diag::Diagnostic& f) { return misread_from(f, block, copy); });
    return true;
}

}  // namespace sphdeck::model
