// One cause, not eight symptoms, across lines: a line shifted off its fields (DK029) or a block written in
// other widths (DK030) makes findings on other lines too (REF003 on a *PART whose section the shifted
// *SECTION_SPH line no longer defines, SPH113 after a misread IDIM, REF007 on what a shifted /PART no
// longer names). Which ones is decided by the deck itself, not guessed: the deck is checked again with the
// cause's safe fix applied, and a finding that is gone there follows from the cause and becomes a note of
// it. A finding that stays is not the shift's doing and stays. The findings on the cause's own lines are
// folded before (lint/fold_causes.hpp).
#pragma once

#include <functional>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/file_overlay.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::engine {

// The findings of the deck read again with `mended` laid over its files (and over the caller's documents).
using RecheckMended = std::function<std::vector<diag::Diagnostic>(const grammar::FileOverlay& mended)>;

// At most this many causes are re-checked (one check each), and only on decks of at most this many lines.
inline constexpr std::size_t max_mended_causes = 4;
inline constexpr std::size_t max_mended_deck_lines = 2'000'000;

// Folds into each DK029 (error) and DK030 with a safe fix the findings of other lines that its fix removes.
// `documents`: the overlay the deck was read with (may be null), kept under the mended files.
void fold_mended_consequences(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics,
                              const grammar::FileOverlay* documents, const RecheckMended& recheck);

}  // namespace sphdeck::engine
