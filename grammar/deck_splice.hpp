// The editor's re-check (issue 45): a deck read again after an edit of its text, by re-reading only
// the lines the edit touched and splicing them into the last reading, instead of reading millions of
// untouched lines again. Taken only where the splice reads exactly what a full read would: a deck of
// one LS-DYNA file without parameters, and an edit that changed data and comment lines inside one
// block the reader does not act on (not *INCLUDE, *PARAMETER, *KEYWORD, *COMMENT, after *END) and
// made or removed no keyword line. Any other edit is read in full (grammar::read_deck).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "grammar/file_overlay.hpp"
#include "grammar/raw_deck.hpp"
#include "text/source_text.hpp"

namespace sphdeck::grammar {

// Where the texts of the two readings differ: bytes [begin, old_end) of the old text became
// [begin, new_end) of the new one, whole lines; the bytes around are the same.
struct SplicedLines {
    FileId file = 0;
    std::size_t begin = 0, old_end = 0, new_end = 0;
    // The card lines (RawDeck::lines) that went: [first_card, old_card_end) of the old reading,
    // [first_card, new_card_end) of the new one; the lines before are the same, those after moved.
    std::uint32_t first_card = 0, old_card_end = 0, new_card_end = 0;
    // The physical lines (1-based): [first_line, old_line_end) of the old text became [first_line,
    // new_line_end) of the new one; the lines after moved by new_line_end - old_line_end.
    std::uint32_t first_line = 0, old_line_end = 0, new_line_end = 0;
    std::size_t block = 0;  // the block (RawDeck::blocks) the edit fell in, the same index in both readings
    // The old text's bytes [begin, old_end), copied: the last reading may view its buffer patched since
    // (grammar/earlier_text.hpp), and the re-check compares the edit's old lines with the new ones.
    std::string replaced;
};

struct SplicedDeck {
    RawDeck deck;
    SplicedLines changed;
};

// `previous` read again with its main file's text now `text`, or nullopt when the edit needs a
// full read (see above). `previous` is not changed. `revision`: what the editor knows changed
// (grammar/file_overlay.hpp); used when it names the text `previous` read, instead of comparing the
// two texts byte by byte (a pass over both, tens of ms on a 100 MB deck), and needed when the editor
// patched that text's buffer in place (`text` views the same buffer then).
std::optional<SplicedDeck> splice_edit(const RawDeck& previous, SourceText text,
                                       const TextRevision* revision = nullptr);

}  // namespace sphdeck::grammar
