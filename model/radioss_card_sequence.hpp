// Which card of a Radioss format each line of a block is read as: the cards read once in order,
// then a trailing repeated group cycling until the block ends; blank lines between records of a
// group are no records; a LIST card of the group (CFG `LIST("%20lg", V, nvarsph)`) takes as many
// lines as its count field on the group's first card says (none for 0); a card read once with a
// condition is passed over when the cards before it say it is absent. One walk for the reading
// (model/radioss_decoder.cpp) and the editor's lookups (engine/position_index.cpp).
#pragma once

#include <cstddef>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/radioss/cards.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::model {

class RadiossCardSequence {
public:
    explicit RadiossCardSequence(const std::vector<grammar::radioss::CardSpec>& cards);

    enum class Step { Card, Blank, Past };
    struct Next {
        Step step = Step::Past;
        std::size_t index = 0;  // the card (Step::Card)
    };
    // How the next line, `text`, is read: as card `index`, skipped as a blank line between
    // records, or past the format's cards (no repeated group).
    Next next(std::string_view text) const;

    // After the line read as card `index` was decoded into `values`. The values are read only
    // on a group's first card when the group has a LIST card, and on the cards read once when a
    // card has a condition (needs_values).
    void advance(std::size_t index, const std::vector<RadiossValue>& values);
    bool needs_values(std::size_t index) const {
        return index < first_repeated_ ? conditional_ : index == first_repeated_ && list_ < cards_.size();
    }

    // True when every line from the group on is read as one card (a group of one plain card).
    bool one_repeated_card() const { return group_ == 1 && list_ == cards_.size(); }
    std::size_t first_repeated() const { return first_repeated_; }

private:
    std::size_t list_lines(const std::vector<RadiossValue>& values) const;
    void skip_absent();

    // The numbers of the cards read once so far, for the conditions.
    struct Earlier final : grammar::radioss::EarlierValues {
        std::vector<std::pair<std::string_view, double>> values;
        double operator()(std::string_view field) const override;
    };
    Earlier earlier_;
    bool conditional_ = false;  // a card read once has a condition

    const std::vector<grammar::radioss::CardSpec>& cards_;
    std::size_t first_repeated_;
    std::size_t group_;
    std::size_t list_;  // the group's LIST card, or cards_.size()
    std::size_t next_ = 0, in_group_ = 0;
    std::size_t list_left_ = 0;  // lines left of the current record's LIST card
};

}  // namespace sphdeck::model
