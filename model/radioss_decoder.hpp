// Decodes a Radioss RawDeck (grammar/radioss/) into the format-neutral Model, with the
// Radioss-only facts in Model::radioss (model/radioss_facts.hpp says what lands where).
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/deck_check.hpp"
#include "model/model.hpp"

namespace sphdeck::model {

// Reads every block through the card tables of grammar/radioss/cards.hpp, in the deck's format
// version (Invers of /BEGIN). Card-level problems (DK002-DK009, DK016, DK018, RAD025) and
// unknown keywords (DK001) go to `out`.
Model build_radioss_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out,
                          DeckSummary* summary = nullptr);

// One block as the walker read it, for `sphdeck dump`: what the header names, and the fields of
// its cards read once (records of repeated cards, nodes or particles, are only counted).
struct RadiossField {
    std::string_view name;  // from the card table (static storage)
    bool number = false;    // an Int or Real cell; otherwise text
    bool integer = false;   // an Int cell
    bool explicit_value = false, valid = false;
    double value = 0.0;
    std::string text;
    grammar::Span span;
};
struct RadiossRecord {
    std::string header;        // as written, upper case: "/PROP/SPH/7"
    std::string_view keyword;  // the table's name: "/PROP/SPH"
    std::string title;
    grammar::Span span;
    int format = 0;                    // the card format read (its first version)
    std::vector<RadiossField> fields;  // cards read once, in order
    std::size_t repeated_lines = 0;
};
struct RadiossReading {
    std::vector<RadiossRecord> records;          // decoded blocks, in deck order
    std::map<std::string, std::size_t> unknown;  // keyword name without ids → blocks
};
// Reads the deck again as build_radioss_model does, keeping what each block said.
RadiossReading read_radioss_records(const grammar::RawDeck& deck);

// The deck version a Radioss RawDeck is read in: Invers on its /BEGIN, or the latest.
int radioss_version(const grammar::RawDeck& deck);

// The id cells of the starter's /NODE lines defining each of `ids`, in reading order (a scan of
// the /NODE blocks, for rare reports such as duplicated ids).
std::map<long long, std::vector<grammar::Span>> radioss_node_lines(const grammar::RawDeck& deck,
                                                                   const std::set<long long>& ids);

}  // namespace sphdeck::model
