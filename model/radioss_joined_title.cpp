#include "model/radioss_joined_title.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "model/radioss_card_decoder.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

namespace {

bool numeric(rad::Cell c) { return c == rad::Cell::Int || c == rad::Cell::Real; }

// Each word of `tail` ends at the end of a cell of `positions` (none past the last): a card line as the CFG formats
// write it.
bool words_at_cell_ends(std::string_view tail, std::span<const grammar::FixedField> positions) {
    std::size_t words = 0;
    for (std::size_t s = tail.find_first_not_of(' '); s != std::string_view::npos; s = tail.find_first_not_of(' ', s)) {
        const std::size_t e = std::min(tail.find(' ', s), tail.size());
        const bool at_end = std::any_of(positions.begin(), positions.end(), [&](const grammar::FixedField& f) {
            return f.start + f.width == e && f.start <= s;
        });
        if (!at_end) return false;
        ++words;
        s = e;
    }
    return words > 0;
}

}  // namespace

std::optional<diag::Diagnostic> diagnose_joined_title(const grammar::RawDeck& deck, const grammar::CardLine& title,
                                                      const rad::CardSpec& card, int version,
                                                      std::string_view keyword) {
    if (card.fields.empty() || !numeric(card.fields.front().cell)) return std::nullopt;
    const std::string_view text = deck.text(title);
    const std::size_t end = text.find_last_not_of(" \r") + 1;  // npos + 1 == 0: a blank title
    if (end == 0 || text.find_first_of(",\t") != std::string_view::npos) return std::nullopt;
    const auto positions = rad::layout(card, version);
    // The first number of the tail: after a run of two blanks at least that follows the title's words.
    for (std::size_t gap = text.find("  "); gap != std::string_view::npos && gap < end;
         gap = text.find("  ", text.find_first_not_of(' ', gap))) {
        const std::size_t number = text.find_first_not_of(' ', gap);
        if (number >= end) break;
        if (gap == 0 || text.find_first_not_of(' ') >= gap) continue;  // the title's own words come first
        // The column to break at: the tail's first number at the end of a cell of the card, from column 1.
        for (std::size_t q = gap; q < number; ++q) {
            const std::string_view tail = text.substr(q, end - q);
            if (!words_at_cell_ends(tail, positions)) continue;
            std::vector<diag::Diagnostic> found;
            RadiossCardDecoder decoder(deck, found);
            std::vector<RadiossValue> values;
            decoder.decode_text(title, tail, card, version, values);
            if (!found.empty()) continue;
            const auto column = static_cast<std::uint32_t>(q + 1);
            diag::Diagnostic d{
                "DK037",
                diag::Severity::Warning,
                fmt::format("two lines made one: the line end before column {} was deleted, so {}'s first card is "
                            "read as part of its title, and the block has no card line: the starter reads that card "
                            "blank (broken there, the card reads cleanly)",
                            column, keyword),
                grammar::Span{title.file, title.line, static_cast<std::uint32_t>(number + 1),
                              static_cast<std::uint32_t>(end + 1)},
                {}};
            d.fixes.push_back(
                {fmt::format("break the line before column {}, so that its text from there is the first card", column),
                 false,
                 {{grammar::Span{title.file, title.line, column, column}, "\n"}}});
            return d;
        }
    }
    return std::nullopt;
}

}  // namespace sphdeck::model
