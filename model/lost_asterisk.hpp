// A keyword line that lost its '*' (`PART` typed for `*PART`, `SECTION_SPH` after a careless delete): LS-DYNA
// reads it, and every line after it up to the next keyword, as more cards of the block above, so the block
// it meant to open is never read. The symptoms land elsewhere (DK009 "N more lines ignored" on the block
// above, a DK002 where the word meets a number field, the part or section it defined missing); the cause is
// the line itself, which reads as a keyword name the tables know once a '*' is put back (DK033).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// The keyword `text` names once a '*' is put in front ("*PART"), when the line is a keyword name alone from
// column 1: a known keyword (with known options) other than the frame's (*END, *KEYWORD, *TITLE, *COMMENT).
std::optional<std::string> keyword_without_asterisk(std::string_view text);

struct LostAsteriskLine {
    grammar::FileId file = grammar::no_file;
    std::uint32_t line = 0;
    std::string written;        // "PART"
    std::string keyword;        // "*PART"
    bool read_as_text = false;  // read into a text field (a heading, a title): no finding of its own
};

// The line as a candidate, when it is one (keyword_without_asterisk).
std::optional<LostAsteriskLine> lost_asterisk_line(grammar::FileId file, std::uint32_t line, std::string_view text,
                                                   bool read_as_text);

// Candidates among the lines of `block` from `from` on that no card reads (an unknown keyword, a generated
// layout that ends): a title line (the block's first, under a _TITLE keyword) is never one.
void note_lost_in_unread(const grammar::RawDeck& deck, const grammar::Block& block, grammar::CardLinePtr from,
                         std::vector<LostAsteriskLine>& out);

// Candidates among the text of a *COMMENT block (its lines, up to the next keyword line, are no cards: read
// from the file): a keyword name followed by a line of numbers only (its card), which the comment swallowed.
void note_lost_in_comment(const grammar::RawDeck& deck, const grammar::Block& block,
                          std::vector<LostAsteriskLine>& out);

// DK033 for each line, folding the block's reading findings (DK002-DK009) on it and on the lines after it,
// which belong to the block it meant to open. A plain word read as text is reported only when a line after
// it misreads (a part heading "NODE" is a heading); a compound name (SECTION_SOLID) always. `from`: the block's
// findings are out[from, end).
void diagnose_lost_asterisks(const grammar::RawDeck& deck, const grammar::Block& block,
                             std::span<const LostAsteriskLine> lines, std::vector<diag::Diagnostic>& out,
                             std::size_t from);

}  // namespace sphdeck::model
