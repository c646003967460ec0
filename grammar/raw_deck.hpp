// What a reader hands to the model: blocks of card lines, still text, with their positions.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/card_lines.hpp"
#include "grammar/parameters.hpp"
#include "text/source_map.hpp"

namespace sphdeck::grammar {

// Field widths in effect for a card (lsdyna-format.md §6).
enum class CardFormat : std::uint8_t { Standard, I10, Long };

std::string_view to_string(CardFormat f);

// One keyword (or Radioss header) and the data lines that follow it up to the next keyword.
struct Block {
    std::string keyword;                       // upper case, with the leading '*', without suffix: "*CONTROL_SPH"
    std::string arguments;                     // text after the name on the keyword line (trimmed)
    CardFormat format = CardFormat::Standard;  // effective format of its data cards
    char suffix = 0;                           // '+', '-', '%' or 0 as written on the keyword line
    Span span;                                 // the keyword name on its line
    std::uint32_t first_line = 0;              // index into RawDeck::lines
    std::uint32_t line_count = 0;
    std::uint32_t scope = 0;            // parameter scope (include instance) the block was read in
    std::uint32_t parameter_epoch = 0;  // parameters defined before this block (use-before-definition)
};

// Arguments of the *KEYWORD line (lsdyna-format.md §8). Memory values stay text ("5M" occurs).
struct KeywordArguments {
    bool present = false;
    std::string memory, memory2;
    long long ncpu = 0;
    bool long_format = false;
    bool i10_format = false;
    Span span;
};

struct ReadStats {
    std::size_t files = 0;
    std::size_t bytes = 0;
    std::size_t lines = 0;
    std::size_t keywords = 0;
    std::size_t cards = 0;
};

struct RawDeck {
    // Declared here and defaulted in grammar/raw_deck.cpp: the special members of this large aggregate
    // are compiled once, not in every room that copies, moves or drops one (issue 42).
    RawDeck();
    RawDeck(const RawDeck&);
    RawDeck(RawDeck&&);
    RawDeck& operator=(const RawDeck&);
    RawDeck& operator=(RawDeck&&) noexcept;
    ~RawDeck();

    SourceMap sources;
    std::vector<Block> blocks;
    CardLines lines;  // a bulk block's regular lines kept as runs (grammar/card_lines.hpp)
    ParameterTable parameters;
    KeywordArguments keyword_arguments;
    std::vector<diag::Diagnostic> diagnostics;
    ReadStats stats;

    // The line's text without "\r\n".
    std::string_view text(const CardLine& l) const;
    // Its length in bytes, without "\r\n" (for spans covering the whole line).
    std::uint32_t length(const CardLine& l) const { return static_cast<std::uint32_t>(text(l).size()); }
    CardLinePtr begin_lines(const Block& b) const { return lines.at(b.first_line); }
    CardLinePtr end_lines(const Block& b) const { return CardLinePtr(lines, b.first_line + b.line_count, false); }
};

}  // namespace sphdeck::grammar
