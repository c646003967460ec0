#include "model/radioss_card_sequence.hpp"

#include <algorithm>
#include <cmath>

#include "grammar/fields.hpp"
#include "grammar/radioss/generated_layouts.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

RadiossCardSequence::RadiossCardSequence(const std::vector<rad::CardSpec>& cards)
    : cards_(cards), first_repeated_(cards.size()), list_(cards.size()) {
    for (std::size_t k = 0; k < cards.size(); ++k)
        if (cards[k].repeat == rad::Repeat::Repeated) {
            first_repeated_ = k;
            break;
        }
    group_ = cards.size() - first_repeated_;
    for (std::size_t k = first_repeated_ + 1; k < cards.size(); ++k)
        if (!cards[k].count.empty()) {
            list_ = k;
            break;
        }
    for (std::size_t k = 0; k < first_repeated_; ++k)
        conditional_ = conditional_ || cards[k].present_if || !cards[k].when.empty();
    skip_absent();
}

double RadiossCardSequence::Earlier::operator()(std::string_view field) const {
    for (const auto& [name, value] : values)
        if (name == field) return value;
    return 0.0;
}

void RadiossCardSequence::skip_absent() {
    const auto absent = [&](const rad::CardSpec& c) {
        if (c.present_if) return !c.present_if(earlier_);
        return !c.when.empty() && !rad::generated::condition_holds(c.when, earlier_);
    };
    while (next_ < first_repeated_ && absent(cards_[next_])) ++next_;
}

RadiossCardSequence::Next RadiossCardSequence::next(std::string_view text) const {
    if (next_ < first_repeated_) return {Step::Card, next_};
    if (group_ == 0) return {Step::Past, 0};
    const std::size_t index = first_repeated_ + in_group_;
    // Blank lines between records (nodes, particles, elements, ids) are no records; a blank row
    // of reals (a /MAT card) is a card of defaults and keeps its place.
    const auto& fields = cards_[index].fields;
    if (!fields.empty() && fields.front().cell == rad::Cell::Int && grammar::is_blank(text)) return {Step::Blank, 0};
    return {Step::Card, index};
}

void RadiossCardSequence::advance(std::size_t index, const std::vector<RadiossValue>& values) {
    if (index < first_repeated_) {
        if (conditional_)
            for (const RadiossValue& v : values)
                if (v.spec && v.valid && (v.spec->cell == rad::Cell::Int || v.spec->cell == rad::Cell::Real))
                    earlier_.values.emplace_back(v.spec->name, v.number);
        ++next_;
        skip_absent();
        return;
    }
    if (in_group_ == 0) list_left_ = needs_values(index) ? list_lines(values) : 0;
    if (index == list_ && list_left_ > 0 && --list_left_ > 0) return;  // more lines of the LIST
    in_group_ = (in_group_ + 1) % group_;
    // A LIST card with no line to read (count 0 or blank) is passed over.
    if (first_repeated_ + in_group_ == list_ && list_left_ == 0) in_group_ = (in_group_ + 1) % group_;
}

// Lines of the group's LIST card: its count field's value (on the group's first card, just
// decoded) over the values a line holds, rounded up; 0 when the count is absent or not positive.
std::size_t RadiossCardSequence::list_lines(const std::vector<RadiossValue>& values) const {
    const rad::CardSpec& list = cards_[list_];
    const std::size_t field = cards_[first_repeated_].index(list.count);
    if (field >= values.size() || !values[field].valid || !(values[field].number > 0)) return 0;
    // A count past the block's lines only reads the lines there are: no allocation follows it.
    const double per_line = static_cast<double>(list.fields.size());
    return static_cast<std::size_t>(std::ceil(std::min(values[field].number, 1e12) / per_line));
}

}  // namespace sphdeck::model
