#include "model/card_ruler.hpp"

#include "grammar/line_tokens.hpp"

namespace sphdeck::model {

RulerWords ruler_words(std::string_view ruler, const keywords::CardSpec& card) {
    RulerWords words;
    if (ruler.empty() || ruler[0] != '$') return words;
    const std::string_view text = ruler.substr(ruler.size() > 1 && ruler[1] == '#' ? 2 : 1);
    grammar::for_each_token(text, [&](const grammar::LineToken& t) {
        ++words.count;
        words.named += card.field(text.substr(t.begin, t.end - t.begin)) != nullptr;
        return true;
    });
    return words;
}

bool ruler_names(std::string_view ruler, const keywords::CardSpec& card) {
    return ruler_words(ruler, card).names_card();
}

}  // namespace sphdeck::model
