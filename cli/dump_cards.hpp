// `sphdeck dump --cards`: every card line the reading decodes, with the text and number of each field
// (LS-DYNA: hand-written and generated layouts alike, through model::check_deck; OpenRadioss: the starter
// blocks' cards as the decoder walks them). What the corpus check compares before and after `format`:
// the model dump alone leaves out the keywords the model does not read.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "grammar/raw_deck.hpp"

namespace sphdeck::cli {

// [{"keyword", "card", "file", "line", "values": [[NAME, TEXT, EXPLICIT, VALID, NUMBER]...]}...]; "file"
// indexes card_files_json's list (one name per file instance, as the text formats name them).
// Written as JSON text directly: a deck of 100,000 card lines gives some million values.
std::string cards_json(const grammar::RawDeck& deck);
nlohmann::ordered_json card_files_json(const grammar::RawDeck& deck);

}  // namespace sphdeck::cli
