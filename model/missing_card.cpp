#include "model/missing_card.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "model/card_ruler.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

// A card as the manual names it ("Card 2"); generated layouts name every card "Card": then by its place.
std::string card_label(const keywords::CardSpec& card, std::size_t index) {
    return card.name.empty() || card.name == "Card" ? fmt::format("card {}", index + 1) : std::string(card.name);
}

// The first few field names of a card, as a ruler writes them.
std::string field_names(const keywords::CardSpec& card) {
    constexpr std::size_t shown = 4;
    std::string names;
    std::size_t n = 0;
    for (const keywords::FieldSpec& f : card.fields) {
        if (f.type == keywords::FieldType::Unused) continue;
        if (n == shown) return names + ", ...";
        names += (n++ ? ", " : "") + std::string(f.name);
    }
    return names;
}

// Whether a blank line reads as `card` without an error: no required field lacks a default.
bool blank_reads(const keywords::CardSpec& card) {
    return std::none_of(card.fields.begin(), card.fields.end(),
                        [](const keywords::FieldSpec& f) { return f.required && !f.default_value; });
}

}  // namespace

std::optional<EarlyCardLine> early_card_line(const grammar::RawDeck& deck, const grammar::Block& block,
                                             grammar::CardLinePtr line, const keywords::CardSpec& read_as,
                                             std::span<const keywords::CardSpec* const> cards) {
    // A heading or title read from the line: decks write the next card's ruler above the title too
    // (`$      pid       sid       mid` over a *PART's heading), and a title line lost is DK032's.
    const bool text_card = std::all_of(read_as.fields.begin(), read_as.fields.end(), [](const keywords::FieldSpec& f) {
        return f.type == keywords::FieldType::Text || f.type == keywords::FieldType::Unused;
    });
    if (text_card) return std::nullopt;
    const std::string_view ruler = header_above(deck, *line, "$");
    const auto found = std::find(cards.begin(), cards.end(), &read_as);
    if (ruler.empty() || found == cards.end()) return std::nullopt;
    const RulerWords own = ruler_words(ruler, read_as);
    if (own.names_card()) return std::nullopt;
    const auto index = static_cast<std::size_t>(found - cards.begin());
    std::size_t named = index + 1;
    // The ruler names card k, and more of its words than of the card the line is read as.
    for (; named < cards.size(); ++named)
        if (const RulerWords words = ruler_words(ruler, *cards[named]); words.names_card() && words.named > own.named)
            break;
    if (named == cards.size()) return std::nullopt;
    // The rulers stacked right above the line, and whether one names the card it is read as.
    const grammar::CardLine& at = *line;
    std::size_t stacked = 0;
    bool own_above = false;
    for (std::uint32_t n = at.line - 1; n >= 1; --n) {
        const std::string_view text = deck.sources.line_text(at.file, n);
        if (text.substr(0, 1) != "$") break;
        ++stacked;
        own_above = own_above || ruler_names(text, *cards[index]);
    }
    if (own_above) {  // a header of several lines over as many data lines is no card cut
        std::size_t under = 1;
        for (grammar::CardLinePtr l = line + 1; l != deck.end_lines(block) && under < stacked; ++l, ++under)
            if (l->file != at.file || l->line != at.line + under) break;
        if (under >= stacked) return std::nullopt;
    }
    return EarlyCardLine{line,
                         {cards.begin() + static_cast<std::ptrdiff_t>(index),
                          cards.begin() + static_cast<std::ptrdiff_t>(named)},
                         cards[named],
                         index};
}

void diagnose_missing_card(const grammar::RawDeck& deck, const grammar::Block& block, const EarlyCardLine& early,
                           std::vector<diag::Diagnostic>& out, std::size_t from) {
    const grammar::CardLine& line = *early.line;
    const std::size_t count = early.missing.size();
    const std::size_t named_index = early.read_as_index + count;
    const std::string read_as = card_label(*early.missing.front(), early.read_as_index);
    const std::string named = card_label(*early.named, named_index);
    const std::string missing =
        count == 1 ? read_as : fmt::format("{} to {}", read_as, card_label(*early.missing.back(), named_index - 1));
    const std::string_view text = deck.text(line);
    const auto first = static_cast<std::uint32_t>(std::min(text.find_first_not_of(' '), text.size()) + 1);
    diag::Diagnostic d{
        "DK035",
        diag::Severity::Warning,
        fmt::format("{}'s {} seems missing above this line: the ruler above it names the fields of {}, "
                    "but LS-DYNA reads a keyword's cards in order, so this line is read as {} ({}) and the lines "
                    "after it {} card{} early",
                    block.keyword, missing, named, read_as, field_names(*early.missing.front()), count,
                    count == 1 ? "" : "s"),
        grammar::Span{line.file, line.line, first,
                      std::max<std::uint32_t>(static_cast<std::uint32_t>(text.size()) + 1, first + 1)},
        {}};
    // The ruler's own line: the cards go above it, so that it stays with the line it names.
    const std::uint32_t ruler_line = line.line - 1;
    if (std::all_of(early.missing.begin(), early.missing.end(),
                    [](const keywords::CardSpec* c) { return blank_reads(*c); }))
        d.fixes.push_back({fmt::format("insert {} blank line{} (a card of defaults each) above the ruler, "
                                       "for {}; then give {} the values it had",
                                       count, count == 1 ? "" : "s", missing, count == 1 ? "it" : "them"),
                           false,
                           {{grammar::Span{line.file, ruler_line, 1, 1}, std::string(count, '\n')}}});
    // The block's reading from this line on, and the keyword's last card found missing on its keyword line.
    fold_explained(out, from, std::move(d), [&](const diag::Diagnostic& f) { return misread_from(f, block, line); });
}

}  // namespace sphdeck::model
