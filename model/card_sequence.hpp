// Which card each line of an LS-DYNA block is read as (lsdyna-format.md §12): mandatory, optional
// trailing, conditional (present_if on an earlier field) and repeated cards, or a trailing group of cards
// repeated together (*PART). The one walk of the cards: the deck check (model/deck_check.cpp), the
// position index (engine/position_index.cpp) and the formatter (edit/format_dyna.cpp) all follow it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "grammar/keywords/schema.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

// Blocks the reader itself reads (deck_check.cpp skip_cards): not cut into cards.
inline bool read_by_reader(const std::string& keyword) {
    return keyword == "*COMMENT" || keyword.rfind("*INCLUDE", 0) == 0 || keyword.rfind("*PARAMETER", 0) == 0 ||
           keyword == "*END";
}

class CardSequence {
    using CardSpec = keywords::CardSpec;
    using CardRepeat = keywords::CardRepeat;

public:
    explicit CardSequence(const keywords::KeywordMatch& match)
        : cards_(keywords::cards_for(match)), group_(keywords::repeat_group_size(match)) {}

    // The card the next line is read as; nullptr past the block's cards or the known layout.
    const CardSpec* next() {
        while (next_ < cards_.size() && !applies(*cards_[next_])) ++next_;
        if (next_ < cards_.size() && cards_[next_]->unknown_layout) return nullptr;
        if (next_ >= cards_.size()) {
            if (group_ == 0) return nullptr;
            next_ = cards_.size() - group_;
        }
        return cards_[next_];
    }
    // Whether `advance` needs the line's decoded values (conditions read them); repeated cards never do.
    bool needs_values(const CardSpec& card) const { return card.repeat != CardRepeat::Repeated; }
    // After a line was decoded as `card` with `values`.
    void advance(const CardSpec& card, const std::vector<model::FieldValue>& values) {
        if (card.repeat == CardRepeat::Repeated) return;
        // A blank field without a default compares as 0, like a field not read: a card group read again
        // (*ELEMENT_SOLID's one- or two-line elements) must not see the last group's value. A value that
        // is not a number (reported) equals nothing.
        for (const auto& v : values)
            if (v.spec->type != keywords::FieldType::Text && v.spec->type != keywords::FieldType::Unused)
                earlier_[std::string(v.spec->name)] = model::condition_value(v);
        ++next_;
    }
    // True when a group of cards repeated together (*PART's heading and card 2) was just read whole: the
    // next line would start another group.
    bool group_done() const { return group_ > 0 && next_ >= cards_.size(); }
    // True when every further line is read as `card`: one repeated card, no group after it.
    bool only_repeats(const CardSpec& card) const { return card.repeat == CardRepeat::Repeated && group_ == 0; }

    // The keyword's cards, in order.
    const std::vector<const CardSpec*>& cards() const { return cards_; }
    // After next() gave nullptr: true when the layout is not known from here on (a generated layout's
    // undecidable card), false when the block has more lines than the keyword has cards.
    bool layout_unknown() const { return next_ < cards_.size(); }
    // The card listed after the one next() gave, or nullptr after the last.
    const CardSpec* card_after() const { return next_ + 1 < cards_.size() ? cards_[next_ + 1] : nullptr; }
    // When the block has ended: the first mandatory card it ended before (its condition holding), or nullptr.
    const CardSpec* missing_card() const {
        for (std::size_t i = next_; i < cards_.size(); ++i)
            if (cards_[i]->repeat == CardRepeat::Once && applies(*cards_[i])) return cards_[i];
        return nullptr;
    }

private:
    bool applies(const CardSpec& card) const {
        if (!card.present_if) return true;
        return card.present_if->holds_with([&](std::string_view field) {
            auto it = earlier_.find(std::string(field));
            return it == earlier_.end() ? 0.0 : it->second;
        });
    }

    std::vector<const CardSpec*> cards_;
    std::size_t group_ = 0;
    std::size_t next_ = 0;
    std::map<std::string, double> earlier_;
};

}  // namespace sphdeck::model
