// Aligned plain-text tables for the commands' terminal output.
#pragma once

#include <string>
#include <vector>

namespace sphdeck::cli {

// Which column holds words (left-aligned); every other column holds numbers (right-aligned).
enum class WordColumn { First, Last };

// Prints `rows` padded to aligned columns, two blanks apart, each line after `indent`.
void print_table(const std::vector<std::vector<std::string>>& rows, WordColumn words, const std::string& indent = "");

}  // namespace sphdeck::cli
