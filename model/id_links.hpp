// References followed through the generated layouts: the ids that fields of generated keywords
// name (pydyna's links, FieldSpec::refers_to, plus a few the links miss or a type field decides),
// collected while the cards are decoded, one per kind and id, for the REF rules. Which keywords define
// which kinds is grammar/keywords/id_kinds.hpp's, shared with the editor.
#pragma once

#include <cstddef>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/raw_deck.hpp"
#include "text/source_map.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

struct IdReference {
    std::string_view kind;     // "PART", "SET_PART", "DEFINE_CURVE"... (static storage)
    long long id = 0;          // > 0: 0 names nothing and negative ids often mean something else
    grammar::Span span;        // the first field naming it
    std::string_view keyword;  // that field's keyword (schema name) and field name
    std::string_view field;
    std::string_view why;   // what decided the kind when a type field did: "SURFATYP 3"; else empty
    std::size_t count = 1;  // fields of the deck naming this kind and id
};

// The kind a field names in a keyword (empty: not followed). `type` is the value of the field's
// type field where one decides the kind (SURFATYP for SURFA); `why` is set to what decided it.
std::string_view followed_kind(std::string_view keyword, const keywords::FieldSpec& field,
                               const std::vector<FieldValue>& card, std::string_view& why);

class IdLinkCollector {
public:
    // One decoded card of a generated keyword.
    void on_card(const keywords::KeywordMatch& match, const std::vector<FieldValue>& values);
    std::vector<IdReference> take() { return std::move(references_); }

private:
    std::vector<IdReference> references_;
    std::map<std::pair<std::string_view, long long>, std::size_t> seen_;  // (kind, id) → index
};

}  // namespace sphdeck::model
