// The whole check of one deck: read, decode, and (as rules land) lint. What `sphdeck check`,
// the deck-driven tests and the benchmarks call.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/dyna/reader.hpp"
#include "grammar/raw_deck.hpp"
#include "model/deck_check.hpp"

namespace sphdeck::lint {

struct CheckOptions {
    grammar::dyna::ReaderOptions reader;
};

struct CheckResult {
    grammar::RawDeck deck;
    std::vector<diag::Diagnostic> diagnostics;  // sorted by location
    model::DeckSummary summary;
};

// Throws std::runtime_error when the main file cannot be read.
CheckResult check_file(const std::string& path, const CheckOptions& options = {});
CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options = {});

}  // namespace sphdeck::lint
