#include "model/blank_card.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "model/card_ruler.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

bool on_line(const diag::Diagnostic& d, const grammar::CardLine& l) {
    return d.span.file == l.file && d.span.line == l.line;
}

// What only a card too many explains: a required field blank on the blank line, lines past the keyword's last
// card, the keyword missing a card.
bool card_too_many(const diag::Diagnostic& d, const grammar::Block& block, const grammar::CardLine& blank) {
    return (d.code == "DK008" && on_line(d, blank)) ||
           (d.code == "DK009" && d.span.file == blank.file && d.span.line > blank.line) ||
           (d.code == "DK008" && d.span.file == block.span.file && d.span.line == block.span.line);
}

}  // namespace

bool blank_card_line(std::string_view text) { return text.find_first_not_of(" \t\r") == std::string_view::npos; }

bool diagnose_blank_card(const grammar::RawDeck& deck, const grammar::Block& block,
                         std::span<const BlankCardLine> blanks, const ReadsWithout& reads_without,
                         std::vector<diag::Diagnostic>& out, std::size_t from) {
    if (blanks.empty()) return false;
    const auto found = std::span<const diag::Diagnostic>(out).subspan(from);
    // A required field left blank on it: no card of defaults was meant.
    const BlankCardLine* cause = nullptr;
    bool proven = false;  // the block reads cleanly without it: every reading finding from it on is its doing
    for (const BlankCardLine& b : blanks)
        if (std::any_of(found.begin(), found.end(),
                        [&](const diag::Diagnostic& d) { return d.code == "DK008" && on_line(d, *b.line); })) {
            cause = &b;
            break;
        }
    // Else the first blank line whose leaving out reads the block cleanly, a card line before a title line.
    if (!cause && std::any_of(found.begin(), found.end(),
                              [&](const diag::Diagnostic& d) { return misread_from(d, block, *blanks.front().line); }))
        for (bool text : {false, true})
            for (const BlankCardLine& b : blanks)
                if (!cause && b.text_card == text && reads_without(b.line)) cause = &b, proven = true;
    // Else, when the block shows a card too many (lines past its last card, a card missing), the first blank
    // line read as a card of values (or a title): the lines after it may hold a mistake of their own as well.
    if (!cause)
        for (bool text : {false, true})
            for (const BlankCardLine& b : blanks)
                if (!cause && b.text_card == text &&
                    std::any_of(found.begin(), found.end(),
                                [&](const diag::Diagnostic& d) { return card_too_many(d, block, *b.line); }))
                    cause = &b;
    // Else a blank line between a `$#` ruler that names the card it was read as and the data line right after
    // it: the ruler was typed for that line, which is read one card late, silently when the next card's fields
    // take its values. (A ruler, a blank line and another ruler is a card of defaults written on purpose, as
    // pydyna writes one.)
    bool under_ruler = false;
    const auto data_right_after = [&](const BlankCardLine& b) {
        const grammar::CardLinePtr next = b.line + 1;
        return next.index() < block.first_line + block.line_count && next->file == b.line->file &&
               next->line == b.line->line + 1;
    };
    if (!cause)
        for (const BlankCardLine& b : blanks)
            if (!cause && !b.text_card && data_right_after(b) && ruler_names(header_above(deck, *b.line), *b.card) &&
                reads_without(b.line))
                cause = &b, proven = true, under_ruler = true;
    if (!cause) return false;
    if (!proven) proven = reads_without(cause->line);

    const grammar::CardLine& blank = *cause->line;
    const std::string card_name = cause->card->name.empty() ? std::string("a card") : std::string(cause->card->name);
    diag::Diagnostic d{"DK034",
                       diag::Severity::Warning,
                       fmt::format("blank line read as {} of {}: LS-DYNA reads a blank line inside a keyword as a "
                                   "card of defaults, not as spacing, so the lines after it are read one card late",
                                   card_name, block.keyword),
                       grammar::Span{blank.file, blank.line, 1, std::max<std::uint32_t>(deck.length(blank) + 1, 2)},
                       {}};
    if (under_ruler)
        d.notes.push_back(
            {grammar::Span{}, fmt::format("the `$#` comment above it names the fields of {}: it was typed for the line "
                                          "after the blank line, which is read as the next card",
                                          card_name)});
    // Unsafe: the blank line may have been meant as a card of defaults, and a line after it too many.
    d.fixes.push_back(
        {"make the blank line a comment ('$'), so that the lines after it are read as the cards they "
         "were typed for",
         false,
         {{grammar::Span{blank.file, blank.line, 1, 1}, "$"}}});
    fold_explained(out, from, std::move(d), [&](const diag::Diagnostic& f) {
        return proven ? misread_from(f, block, blank) : card_too_many(f, block, blank);
    });
    return true;
}

}  // namespace sphdeck::model
