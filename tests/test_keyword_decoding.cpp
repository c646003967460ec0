// Every card of every schema through the card decoder (issue 3): a blank card decodes to the
// documented defaults, a full card to its values (fixed, free and widened formats), every enum
// and range rejects a value outside it, and an explicit 0 means the default where it should.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "model/card_decoder.hpp"

namespace test_keyword_decoding_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::CardFormat;
using keywords::CardSpec;
using keywords::FieldSpec;
using keywords::FieldType;
using keywords::KeywordSchema;

namespace {

constexpr std::uint32_t kLine = 7;  // line number the test lines claim to be on

// One line decoded through one card, in a deck of its own (the values view into its text).
struct Decoded {
    grammar::RawDeck deck;
    std::vector<model::FieldValue> values;
    std::vector<diag::Diagnostic> diagnostics;

    Decoded(const CardSpec& card, const std::string& text, CardFormat format = CardFormat::Standard) {
        grammar::SourceFile file;
        file.path = file.display_name = "t.k";
        file.text = text;
        deck.sources.add(std::move(file));
        grammar::Block block;
        block.keyword = "*TEST";
        block.format = format;
        const grammar::CardLine line{0, kLine, 0};
        model::CardDecoder(deck, diagnostics).decode(block, line, card, values);
    }
    Decoded(const Decoded&) = delete;
    Decoded& operator=(const Decoded&) = delete;
};

// Every card of a schema: base cards and the cards its options add.
std::vector<const CardSpec*> every_card(const KeywordSchema& k) {
    std::vector<const CardSpec*> cards;
    for (const CardSpec& c : k.cards) cards.push_back(&c);
    for (const auto& o : k.options) {
        for (const CardSpec& c : o.cards_before) cards.push_back(&c);
        for (const CardSpec& c : o.cards_after) cards.push_back(&c);
    }
    return cards;
}

bool numeric(const FieldSpec& f) { return f.type != FieldType::Text && f.type != FieldType::Unused; }

// The decoder's rule: a card that starts with a long text field (title) is never free format.
bool text_card(const CardSpec& card) {
    return !card.fields.empty() && card.fields[0].type == FieldType::Text && card.fields[0].width >= 70;
}

std::string number_text(double v) {
    if (v == std::trunc(v) && std::fabs(v) < 1e9) return std::to_string(static_cast<long long>(v));
    return fmt::format("{:g}", v);
}

// A valid value for field `i`, different from its default and (outside enums) from the other
// fields, so that a field read from the wrong columns shows.
std::string valid_value(const FieldSpec& f, std::size_t i) {
    switch (f.type) {
        case FieldType::Unused: return "";
        case FieldType::Text: {
            if (f.text_choices.empty()) return "T" + std::to_string(i + 1);
            for (auto it = f.text_choices.rbegin(); it != f.text_choices.rend(); ++it)
                if (*it != f.default_text) return std::string(*it);
            return std::string(f.text_choices.back());
        }
        default: break;
    }
    if (!f.choices.empty()) {
        for (auto it = f.choices.rbegin(); it != f.choices.rend(); ++it) {
            const double v = static_cast<double>(it->value);
            if (f.default_value != v && !(f.zero_is_default && v == 0)) return std::to_string(it->value);
        }
        return std::to_string(f.choices.back().value);
    }
    const bool integral = f.type != FieldType::Real;
    double v = integral ? 10.0 * static_cast<double>(i + 1) + 3 : static_cast<double>(i + 1) + 0.25;
    if (f.max && v > *f.max) v = integral ? std::floor(*f.max) : *f.max - 0.25;
    if (f.min && v < *f.min) v = integral ? std::ceil(*f.min) : *f.min + 0.25;
    return number_text(v);
}

// Values just outside the field's enum or range (below and above); none when it has neither.
std::vector<std::string> invalid_values(const FieldSpec& f) {
    std::vector<std::string> out;
    auto avoid_zero = [&](double v, double step) { return f.zero_is_default && v == 0 ? v + step : v; };
    if (!f.choices.empty()) {
        long long top = f.choices.front().value;
        for (const auto& c : f.choices) top = std::max(top, c.value);
        out.push_back(number_text(avoid_zero(static_cast<double>(top + 1), 1)));
        return out;
    }
    if (f.min) out.push_back(number_text(avoid_zero(*f.min - 1, -1)));
    if (f.max) out.push_back(number_text(avoid_zero(*f.max + 1, 1)));
    return out;
}

// A fixed-format line with `values[i]` right-justified in field i's columns.
std::string fixed_line(const CardSpec& card, const std::vector<std::string>& values, CardFormat format) {
    const auto slots = keywords::layout(card, format);
    std::string line;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const auto& value = values[i];
        REQUIRE(value.size() <= slots[i].width);
        const std::size_t end = slots[i].start + slots[i].width;
        if (line.size() < end) line.resize(end, ' ');
        line.replace(end - value.size(), value.size(), value);
    }
    return line;
}

std::string free_line(const std::vector<std::string>& values) {
    std::string line;
    for (std::size_t i = 0; i < values.size(); ++i) line += (i ? "," : "") + values[i];
    return line;
}

std::vector<std::string> full_values(const CardSpec& card) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < card.fields.size(); ++i) values.push_back(valid_value(card.fields[i], i));
    return values;
}

std::string diagnostics_text(const std::vector<diag::Diagnostic>& ds) {
    std::string s;
    for (const auto& d : ds)
        s += fmt::format("[{} {}:{}-{} {}] ", d.code, d.span.line, d.span.column, d.span.end_column, d.message);
    return s;
}

// The decoded values must be exactly `values`, all explicit, without any diagnostic.
void check_full(const CardSpec& card, const std::vector<std::string>& values, const Decoded& d) {
    INFO("diagnostics: " << diagnostics_text(d.diagnostics));
    CHECK(d.diagnostics.empty());
    REQUIRE(d.values.size() == card.fields.size());
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        const FieldSpec& f = card.fields[i];
        const model::FieldValue& v = d.values[i];
        INFO("field " << f.name << " written as '" << values[i] << "'");
        CHECK(v.spec == &f);
        if (f.type == FieldType::Unused) continue;
        CHECK(v.explicit_value);
        CHECK(v.valid);
        CHECK(v.text == values[i]);
        if (numeric(f)) CHECK(v.number == std::stod(values[i]));
    }
}

// The span of a diagnostic lies inside field `i`'s columns on the test line.
bool inside_field(const diag::Diagnostic& d, const CardSpec& card, std::size_t i, CardFormat format) {
    const auto slot = keywords::layout(card, format)[i];
    return d.span.line == kLine && d.span.column >= slot.start + 1 &&
           d.span.end_column <= slot.start + slot.width + 1 && d.span.column < d.span.end_column;
}

}  // namespace

TEST_CASE("keyword decoding: a blank card decodes to the documented defaults") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            INFO(k.name << " / " << card->name);
            const Decoded d(*card, "");
            INFO("diagnostics: " << diagnostics_text(d.diagnostics));
            REQUIRE(d.values.size() == card->fields.size());
            std::size_t expected_dk008 = 0;
            for (std::size_t i = 0; i < card->fields.size(); ++i) {
                const FieldSpec& f = card->fields[i];
                const model::FieldValue& v = d.values[i];
                INFO("field " << f.name);
                CHECK_FALSE(v.explicit_value);
                CHECK_FALSE((f.required && f.default_value));  // a required field has no default
                if (f.default_value) {
                    CHECK(v.valid);
                    CHECK(v.number == *f.default_value);
                }
                const bool missing = f.required && !f.default_value;
                const auto at_field = std::count_if(d.diagnostics.begin(), d.diagnostics.end(), [&](const auto& x) {
                    return x.code == "DK008" && inside_field(x, *card, i, CardFormat::Standard);
                });
                CHECK(at_field == (missing ? 1 : 0));
                expected_dk008 += missing;
            }
            // Nothing but DK008, and only for the required fields.
            CHECK(d.diagnostics.size() == expected_dk008);
        }
    }
}

// *INCLUDE's FILENAME is a required text field: blank is DK008 like a numeric one.
TEST_CASE("keyword decoding: a blank required text field is reported") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            for (std::size_t i = 0; i < card->fields.size(); ++i) {
                const FieldSpec& f = card->fields[i];
                if (f.type != FieldType::Text || !f.required) continue;
                INFO(k.name << " / " << card->name << " / " << f.name);
                auto values = full_values(*card);
                values[i] = "";
                const Decoded d(*card, fixed_line(*card, values, CardFormat::Standard));
                INFO("diagnostics: " << diagnostics_text(d.diagnostics));
                REQUIRE(d.diagnostics.size() == 1);
                CHECK(d.diagnostics[0].code == "DK008");
                CHECK(inside_field(d.diagnostics[0], *card, i, CardFormat::Standard));
            }
        }
    }
}

TEST_CASE("keyword decoding: a full card decodes to its values in every format") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            INFO(k.name << " / " << card->name);
            const auto values = full_values(*card);
            for (CardFormat format : {CardFormat::Standard, CardFormat::I10, CardFormat::Long}) {
                const std::string line = fixed_line(*card, values, format);
                INFO("format " << static_cast<int>(format) << ": '" << line << "'");
                const Decoded d(*card, line, format);
                check_full(*card, values, d);
            }
            if (text_card(*card)) continue;  // a comma in a title is just text
            const std::string line = free_line(values);
            INFO("free format: '" << line << "'");
            const Decoded d(*card, line);
            check_full(*card, values, d);
        }
    }
}

TEST_CASE("keyword decoding: every enum and range rejects a value outside it") {
    std::size_t checked = 0;
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            for (std::size_t i = 0; i < card->fields.size(); ++i) {
                const FieldSpec& f = card->fields[i];
                if (!numeric(f)) continue;
                for (const std::string& bad : invalid_values(f)) {
                    INFO(k.name << " / " << card->name << " / " << f.name << " = " << bad);
                    auto values = full_values(*card);
                    values[i] = bad;
                    for (CardFormat format : {CardFormat::Standard, CardFormat::Long}) {
                        const Decoded d(*card, fixed_line(*card, values, format), format);
                        INFO("diagnostics: " << diagnostics_text(d.diagnostics));
                        REQUIRE(d.diagnostics.size() == 1);
                        CHECK(d.diagnostics[0].code == "DK007");
                        CHECK(inside_field(d.diagnostics[0], *card, i, format));
                        CHECK(d.diagnostics[0].message.find(std::string(f.name)) != std::string::npos);
                    }
                    ++checked;
                }
            }
        }
    }
    CHECK(checked > 30);  // the tables have many enums: an empty loop would prove nothing
}

// Text enums (*SET_NODE_LIST SOLVER: MECH, CESE, ICFD) reject other words.
TEST_CASE("keyword decoding: a text enum rejects a word outside it") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            for (std::size_t i = 0; i < card->fields.size(); ++i) {
                const FieldSpec& f = card->fields[i];
                if (f.text_choices.empty()) continue;
                INFO(k.name << " / " << card->name << " / " << f.name);
                auto values = full_values(*card);
                values[i] = "BOGUS";
                const Decoded d(*card, fixed_line(*card, values, CardFormat::Standard));
                INFO("diagnostics: " << diagnostics_text(d.diagnostics));
                REQUIRE(d.diagnostics.size() == 1);
                CHECK(d.diagnostics[0].code == "DK007");
                CHECK(inside_field(d.diagnostics[0], *card, i, CardFormat::Standard));
            }
        }
    }
}

TEST_CASE("keyword decoding: an explicit 0 means the default where the manual says so") {
    std::size_t checked = 0;
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            for (std::size_t i = 0; i < card->fields.size(); ++i) {
                const FieldSpec& f = card->fields[i];
                if (!f.zero_is_default) continue;
                INFO(k.name << " / " << card->name << " / " << f.name);
                REQUIRE(f.default_value.has_value());  // 0 means "the default": there must be one
                for (const char* zero : {"0", "0.0"}) {
                    if (f.type != FieldType::Real && std::string(zero) == "0.0") continue;
                    auto values = full_values(*card);
                    values[i] = zero;
                    const Decoded d(*card, fixed_line(*card, values, CardFormat::Standard));
                    INFO("written as " << zero << "; diagnostics: " << diagnostics_text(d.diagnostics));
                    CHECK(d.diagnostics.empty());
                    CHECK(d.values[i].explicit_value);
                    CHECK(d.values[i].valid);
                    CHECK(d.values[i].number == *f.default_value);
                }
                ++checked;
            }
        }
    }
    CHECK(checked > 0);
}

// card_layout keeps layouts across decks by the card's address: a card made where a dropped one lay (a test's, a
// caller's) must get its own layout, not the dropped card's.
TEST_CASE("card_layout: a card made at a dropped card's address gets its own layout") {
    const auto same_positions = [](const std::vector<grammar::FixedField>& a,
                                   const std::vector<grammar::FixedField>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                          [](const auto& x, const auto& y) { return x.start == y.start && x.width == y.width; });
    };
    std::optional<CardSpec> card;
    card.emplace(CardSpec{.fields = {{.name = "TITLE", .column = 1, .width = 80, .type = FieldType::Text}}});
    const CardSpec* first = &*card;
    const model::CardLayout& title = model::card_layout(*card, CardFormat::Standard);
    CHECK(title.title_card);
    CHECK(title.text_card);
    // The same columns, widths and types under a name that is no title: the cached layout no longer holds.
    card.reset();
    card.emplace(CardSpec{.fields = {{.name = "EXPR", .column = 1, .width = 80, .type = FieldType::Text}}});
    REQUIRE(&*card == first);
    CHECK_FALSE(model::card_layout(*card, CardFormat::Standard).title_card);
    // Other fields at the same address, in every format: the layout of the card there now.
    card.reset();
    card.emplace(CardSpec{.fields = {{.name = "NID", .column = 1, .width = 8, .type = FieldType::Integer},
                                     {.name = "X", .column = 9, .width = 16, .type = FieldType::Real}}});
    REQUIRE(&*card == first);
    for (CardFormat format : {CardFormat::Standard, CardFormat::I10, CardFormat::Long}) {
        CAPTURE(grammar::to_string(format));
        const model::CardLayout& l = model::card_layout(*card, format);
        CHECK(same_positions(l.positions, keywords::layout(*card, format)));
        CHECK(l.significant == keywords::significant_width(*card, format));
        CHECK(l.types == std::vector<FieldType>{FieldType::Integer, FieldType::Real});
        CHECK_FALSE(l.text_card);
        CHECK(l.plain == (format == CardFormat::Standard));
    }
    // A table's card: the same answer, asked again, from the same entry.
    const CardSpec& node = keywords::find_keyword("*NODE")->schema->cards.front();
    CHECK(&model::card_layout(node, CardFormat::I10) == &model::card_layout(node, CardFormat::I10));
    CHECK(same_positions(model::card_layout(node, CardFormat::I10).positions, keywords::layout(node, CardFormat::I10)));
}
}  // namespace test_keyword_decoding_cpp
