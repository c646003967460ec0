// The whole check of one deck: read, decode, and (as rules land) lint. What `sphdeck check`,
// the deck-driven tests and the benchmarks call.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/dyna/reader.hpp"
#include "grammar/raw_deck.hpp"
#include "grammar/read_deck.hpp"
#include "lint/config.hpp"
#include "lint/rule_context.hpp"
#include "model/deck_check.hpp"
#include "model/model.hpp"

namespace sphdeck::lint {

struct CheckOptions {
    grammar::dyna::ReaderOptions reader;
    RuleOptions rules;
    Config config;  // sphdeck.toml merged with the command line; cli/ copies the solver into `rules`
};

struct CheckResult {
    grammar::RawDeck deck;
    std::vector<diag::Diagnostic> diagnostics;  // sorted by location
    model::DeckSummary summary;
    model::Model model;
};

// Throws std::runtime_error when the main file cannot be read.
CheckResult check_file(const std::string& path, const CheckOptions& options = {});
// `format`: the reader to use (LS-DYNA unless told; nullopt detects it from the text and name).
// Relative includes are searched from `base_directory`.
CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options = {},
                         std::optional<grammar::DeckFormat> format = grammar::DeckFormat::LsDyna,
                         const std::string& base_directory = ".");

}  // namespace sphdeck::lint
