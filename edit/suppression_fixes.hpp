// Suppressing a finding, as fixes (diag::Fix, like every other mend, so the editor offers them through the
// same path): a `disable=CODE` directive just before the finding's line, which silences the card (the
// whole block before a keyword line), or CODE added to the file's `disable-file=` directive. The
// directives' syntax is lint/suppressions.hpp's; a directive already there takes the code.
#pragma once

#include <cstdint>
#include <string_view>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::edit {

// `line`: the finding's 1-based line in `file`; `comment`: '$' in LS-DYNA decks, '#' in Radioss ones.
diag::Fix suppress_for_card(const grammar::RawDeck& deck, grammar::FileId file, std::uint32_t line,
                            std::string_view code, char comment);

// The file's `disable-file=` directive among its first lines takes the code, else a directive line at the top
// (after a Radioss file's `#RADIOSS` line, which tells the format).
diag::Fix suppress_in_file(const grammar::SourceMap& sources, grammar::FileId file, std::string_view code,
                           char comment);

}  // namespace sphdeck::edit
