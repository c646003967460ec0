// Which card each line of an LS-DYNA block is read as: model/deck_check.cpp's walk (conditional,
// optional and repeated cards, repeat groups) without its reports, shared by the position index
// (engine/position_index.cpp) and the formatter (edit/format_dyna.cpp).
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
        for (const auto& v : values)  // as model/deck_check.cpp: a blank field without default is 0
            if (v.spec->type != keywords::FieldType::Text && v.spec->type != keywords::FieldType::Unused)
                earlier_[std::string(v.spec->name)] = model::condition_value(v);
        ++next_;
    }
    // True when every further line is read as `card`: one repeated card, no group after it.
    bool only_repeats(const CardSpec& card) const { return card.repeat == CardRepeat::Repeated && group_ == 0; }

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
