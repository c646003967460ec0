// RAD040: the OpenRadioss starter's own value checks (lint/starter_checks.hpp), at the field the
// starter rejects: each /MAT, /EOS or /PROP block whose reader the table knows is read again through its
// layout for the deck's version, with the reader's defaults applied before the test, as the
// starter does. A card the block does not hold reads as blanks, as the starter reads it: its
// finding goes on the block's last line and names the missing card.
#include <fmt/format.h>

#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/radioss/reader.hpp"
#include "lint/rules_radioss.hpp"
#include "lint/starter_checks.hpp"
#include "model/radioss_card_decoder.hpp"
#include "model/radioss_card_sequence.hpp"

namespace sphdeck::lint::radioss {
namespace {

namespace rad = grammar::radioss;
using model::RadiossValue;

// The fields one block holds, by name, for the checks and their conditions.
class BlockValues final : public rad::EarlierValues {
public:
    void add(const RadiossValue& v) {
        if (v.spec && !v.spec->name.empty()) values_.push_back(v);
    }
    const RadiossValue* find(std::string_view field) const {
        for (const RadiossValue& v : values_)
            if (v.spec->name == field) return &v;
        return nullptr;
    }
    double operator()(std::string_view field) const override {
        const RadiossValue* v = find(field);
        return v && v->valid ? v->number : 0.0;
    }

private:
    std::vector<RadiossValue> values_;
};

const rad::FormatSpec* format_of(const StarterLaw& law, int version) {
    if (law.layout.empty()) {
        const rad::KeywordSpec* generated = rad::generated::keyword_named(law.names.front());
        return generated ? &generated->format_for(version) : nullptr;
    }
    for (const rad::FormatSpec& f : law.layout)
        if (f.since <= version) return &f;
    return &law.layout.back();
}

// The card of `format` that holds `field`, or cards.size().
std::size_t card_holding(const rad::FormatSpec& format, std::string_view field) {
    for (std::size_t k = 0; k < format.cards.size(); ++k)
        if (format.cards[k].repeat == rad::Repeat::Once && format.cards[k].index(field) < format.cards[k].fields.size())
            return k;
    return format.cards.size();
}

// Whether a card read once is in the block, by its condition on the fields before it.
bool present(const rad::CardSpec& card, const BlockValues& read) {
    return card.when.empty() || rad::generated::condition_holds(card.when, read);
}

// The card's number as a person counts them after the title: the cards before it that are present.
std::size_t card_number(const rad::FormatSpec& format, std::size_t card, const BlockValues& read) {
    std::size_t n = 1;
    for (std::size_t k = 0; k < card; ++k) n += present(format.cards[k], read);
    return n;
}

class BlockCheck {
public:
    BlockCheck(RuleContext& c, const grammar::Block& block, const StarterLaw& law, const rad::FormatSpec& format,
               int version)
        : c_(c), block_(block), law_(law), format_(format), version_(version) {}

    void run() {
        read();
        for (const StarterCheck& check : law_.checks)
            if (check.reported_by.empty()) apply(check);
    }

private:
    // The block's lines through the law's cards, up to the first card kept as text.
    void read() {
        grammar::CardLinePtr line = c_.deck.begin_lines(block_);
        grammar::CardLinePtr end = c_.deck.end_lines(block_);
        if (!rad::is_v4(version_) && line != end) ++line;  // the title
        std::vector<diag::Diagnostic> ignored;             // the model's reading reported them
        model::RadiossCardDecoder decoder(c_.deck, ignored);
        model::RadiossCardSequence sequence(format_.cards);
        decoded_.assign(format_.cards.size(), false);
        std::vector<RadiossValue> values;
        for (; line != end; ++line) {
            const auto next = sequence.next(c_.deck.text(*line));
            if (next.step == model::RadiossCardSequence::Step::Blank) continue;
            if (next.step == model::RadiossCardSequence::Step::Past) break;
            if (format_.cards[next.index].repeat == rad::Repeat::Repeated) break;
            decoder.decode(*line, format_.cards[next.index], version_, false, values);
            sequence.advance(next.index, values);
            decoded_[next.index] = true;
            for (const RadiossValue& v : values) read_.add(v);
            last_ = line;
        }
    }

    void apply(const StarterCheck& check) {
        const std::size_t card = card_holding(format_, check.field);
        if (card == format_.cards.size()) return;  // not read in this format
        const RadiossValue* v = read_.find(check.field);
        if (!v && (decoded_[card] || !present(format_.cards[card], read_))) return;  // a card not read
        if (v && v->explicit_value && !v->valid) return;  // a parameter or bad text (DK003): unknown
        if (!check.when.empty() && !rad::generated::condition_holds(check.when, read_)) return;
        double value = v ? v->number : 0.0;
        if (value == 0.0 && check.zero_means != 0.0) value = check.zero_means;
        if (allowed(check.allowed, value)) return;
        const std::string starter =
            fmt::format("the starter stops (starter message {}: \"{}\")", check.message, check.text);
        if (v) {
            const std::string written = v->explicit_value ? std::string(v->text) : std::string("blank (0)");
            report(v->span,
                   fmt::format("{} {} in {}: {}; expected {} {}", check.label, written, block_.keyword, starter,
                               check.label, expected(check.allowed)),
                   check);
            return;
        }
        // The block ends before the card: its fields read as blanks.
        const grammar::Span at =
            last_ ? grammar::Span{last_->file, last_->line, 1, c_.deck.length(*last_) + 1} : block_.span;
        report(at,
               fmt::format("{} ends before card {} (the one with {}): {} reads 0 and {}; add the card with {} {}",
                           block_.keyword, card_number(format_, card, read_), check.label, check.label, starter,
                           check.label, expected(check.allowed)),
               check);
    }

    void report(grammar::Span at, std::string message, const StarterCheck& check) {
        diag::Diagnostic& d = c_.report("RAD040", at, std::move(message));
        d.notes.push_back(
            {grammar::Span{}, fmt::format("OpenRadioss starter/source/{}/{}", reader_folder(law_), check.source)});
    }

    RuleContext& c_;
    const grammar::Block& block_;
    const StarterLaw& law_;
    const rad::FormatSpec& format_;
    int version_;
    BlockValues read_;
    std::vector<bool> decoded_;
    grammar::CardLinePtr last_ = nullptr;
};

// Blocks of the engine deck (<run>_0001.rad and its includes) are no starter input.
bool starter_in_engine_file(const grammar::RawDeck& deck, const grammar::Block& block) {
    const grammar::FileId root = deck.sources.include_chain(block.span.file).front();
    return rad::is_engine_file_name(deck.sources.file(root).display_name);
}

}  // namespace

void check_starter_values(RuleContext& c) {
    const int version = c.model.radioss->version;
    for (const grammar::Block& block : c.deck.blocks) {
        if (!block.keyword.starts_with("/MAT/") && !block.keyword.starts_with("/EOS/") &&
            !block.keyword.starts_with("/PROP/"))
            continue;
        const StarterLaw* law = starter_law_of(block.keyword);
        if (!law || starter_in_engine_file(c.deck, block)) continue;
        const rad::FormatSpec* format = format_of(*law, version);
        if (!format) continue;
        BlockCheck(c, block, *law, *format, version).run();
    }
}

}  // namespace sphdeck::lint::radioss
