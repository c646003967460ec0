#include "model/missing_heading.hpp"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "grammar/line_tokens.hpp"
#include "grammar/value.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

bool integer_word(std::string_view word) {
    const grammar::IntegerValue v = grammar::parse_integer(word);
    return v.status == grammar::NumberStatus::Ok && word.find_first_of(".eEdD") == std::string_view::npos;
}

bool heading_finding(std::string_view code) { return follows_from_shift(code) || code == "DK009"; }

// An integer or id field, or one pydyna lays out as an integer (generated layouts: *PART_INERTIA's PID).
bool integer_typed(const keywords::FieldSpec& spec) {
    return spec.type == keywords::FieldType::Integer || spec.type == keywords::FieldType::Label || spec.pydyna_integer;
}

// How many words of the fixed-format `text` there are when each lies whole in one of `card`'s fields (its
// columns `slots`) and `fits(word, field)`; nothing at the first that does not.
template <typename Fits>
std::optional<std::size_t> words_in_fields(std::string_view text, std::span<const grammar::FixedField> slots,
                                           const keywords::CardSpec& card, Fits&& fits) {
    const auto fields = slots.first(std::min(slots.size(), card.fields.size()));
    std::size_t words = 0;
    bool all = true;
    grammar::for_each_token(text, [&](const grammar::LineToken& t) {
        const auto in = std::find_if(fields.begin(), fields.end(), [&](const grammar::FixedField& f) {
            return f.start <= t.begin && t.end <= std::size_t{f.start} + f.width;
        });
        all = in != fields.end() &&
              fits(text.substr(t.begin, t.end - t.begin), card.fields[static_cast<std::size_t>(in - fields.begin())]);
        words += all;
        return all;
    });
    return all ? std::optional<std::size_t>(words) : std::nullopt;
}

}  // namespace

bool reads_as_integer_card(std::string_view text, std::span<const grammar::FixedField> slots,
                           const keywords::CardSpec& card) {
    constexpr std::size_t min_values = 2;  // a lone number is a plausible heading ("1")
    std::size_t values = 0;
    if (grammar::is_free_format(text)) {
        std::size_t at = 0;
        while (at <= text.size()) {
            std::size_t comma = std::min(text.find(',', at), text.size());
            const std::string_view word = grammar::trim_blanks(text.substr(at, comma - at));
            if (!word.empty()) {
                if (!integer_word(word)) return false;
                ++values;
            }
            at = comma + 1;
        }
        return values >= min_values;
    }
    const std::optional<std::size_t> words =
        words_in_fields(text, slots, card, [](std::string_view word, const keywords::FieldSpec& spec) {
            return integer_typed(spec) && integer_word(word);
        });
    return words && *words >= min_values;
}

bool reads_as_card(std::string_view text, std::span<const grammar::FixedField> slots, const keywords::CardSpec& card) {
    if (grammar::is_free_format(text)) return false;
    const std::optional<std::size_t> words =
        words_in_fields(text, slots, card, [](std::string_view word, const keywords::FieldSpec& spec) {
            return spec.type == keywords::FieldType::Label ||
                   (spec.type == keywords::FieldType::Integer && integer_word(word)) ||
                   (spec.type == keywords::FieldType::Real &&
                    grammar::parse_real(word).status == grammar::NumberStatus::Ok);
        });
    return words && *words >= 2;
}

bool reals_in_id_fields(std::string_view text, std::span<const grammar::FixedField> slots,
                        const keywords::CardSpec& card) {
    if (grammar::is_free_format(text)) return false;
    const std::size_t fields = std::min(slots.size(), card.fields.size());
    for (std::size_t k = 0; k < fields; ++k) {
        if (!integer_typed(card.fields[k]) || slots[k].start >= text.size()) continue;
        const std::string_view word = grammar::trim_blanks(text.substr(slots[k].start, slots[k].width));
        const grammar::RealValue v = grammar::parse_real(word);
        if (v.status == grammar::NumberStatus::Ok && word.find_first_of(".eEdD") != std::string_view::npos) return true;
    }
    return false;
}

void diagnose_missing_heading(const grammar::RawDeck& deck, const grammar::Block& block,
                              const grammar::CardLine& heading, const keywords::CardSpec& next_card,
                              bool reals_read_as_ids, std::vector<diag::Diagnostic>& out, std::size_t from) {
    // The block's misreadings from the heading on (and "missing its Card 2" on its keyword line).
    const auto misread = [&](const diag::Diagnostic& d) {
        const bool after = d.span.file == heading.file && d.span.line >= heading.line;
        const bool keyword_line = d.span.file == block.span.file && d.span.line == block.span.line;
        return heading_finding(d.code) && (after || keyword_line);
    };
    if (!reals_read_as_ids && std::none_of(out.begin() + static_cast<std::ptrdiff_t>(from), out.end(), misread)) return;
    const std::string_view text = deck.text(heading);
    const auto first = static_cast<std::uint32_t>(std::min(text.find_first_not_of(' '), text.size()) + 1);
    // Generated layouts name their cards "Card": the one after the heading is card 2 (a title's: card 1).
    const bool part = block.keyword.rfind("*PART", 0) == 0;
    const std::string card =
        next_card.name.empty() || next_card.name == "Card" ? (part ? "card 2" : "card 1") : std::string(next_card.name);
    const std::string message =
        part ? fmt::format(
                   "{} heading line missing: this line of integers reads as {}'s {}, but LS-DYNA reads it as "
                   "the part's heading and the line after it as its {}",
                   block.keyword, block.keyword, card, card)
             : fmt::format(
                   "{} title line missing: this line reads as {}'s {}, but LS-DYNA reads it as the title "
                   "(the keyword's _TITLE option) and the line after it as its {}",
                   block.keyword, block.keyword, card, card);
    diag::Diagnostic d{"DK032",
                       diag::Severity::Warning,
                       message,
                       grammar::Span{heading.file, heading.line, first, static_cast<std::uint32_t>(text.size() + 1)},
                       {}};
    // Unsafe: which title the part had is not known; a blank heading is read as none.
    d.fixes.push_back({part ? "insert a blank heading line above it" : "insert a blank title line above it",
                       false,
                       {{grammar::Span{heading.file, heading.line, 1, 1}, "\n"}}});
    fold_explained(out, from, std::move(d), misread);
}

}  // namespace sphdeck::model
