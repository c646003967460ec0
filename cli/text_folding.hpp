// What the text formats (full, concise) print of a deck's findings. The machine formats carry every
// finding; text folds long runs so a person can read it: past 5 findings of one code on the lines of
// one block, one line counts the rest of that block, and past --max-per-code findings of one code in
// the deck, one line counts the rest. Summaries always count every finding.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::cli {

// One line of the text output: a finding to render, or a folding line already written out.
struct TextItem {
    const diag::Diagnostic* finding = nullptr;  // null: `line` instead
    std::string line;
};

inline constexpr std::size_t kShownPerBlock = 5;

// The findings of one deck as the text formats show them; max_per_code 0 shows every finding, unfolded.
std::vector<TextItem> fold_for_text(const std::vector<diag::Diagnostic>& findings, const grammar::RawDeck& deck,
                                    std::size_t max_per_code);

}  // namespace sphdeck::cli
