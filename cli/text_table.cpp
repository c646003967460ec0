#include "cli/text_table.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace sphdeck::cli {

void print_table(const std::vector<std::vector<std::string>>& rows, WordColumn words, const std::string& indent) {
    std::vector<std::size_t> width;
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (width.size() <= c) width.push_back(0);
            width[c] = std::max(width[c], row[c].size());
        }
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (c > 0) line += "  ";
            const bool left = words == WordColumn::First ? c == 0 : c + 1 == row.size();
            line += left ? fmt::format("{:<{}}", row[c], width[c]) : fmt::format("{:>{}}", row[c], width[c]);
        }
        while (!line.empty() && line.back() == ' ') line.pop_back();
        fmt::print("{}{}\n", indent, line);
    }
}

}  // namespace sphdeck::cli
