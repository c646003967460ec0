// The documents a check reads: path -> text held in memory (an editor's buffers, a test's decks),
// laid over the file system for the deck and its includes. A path the set does not hold is read
// from disk. The readers consult it through grammar::dyna::ReaderOptions::overlay.
#pragma once

#include "grammar/file_overlay.hpp"

namespace sphdeck::engine {

using Documents = grammar::FileOverlay;

}  // namespace sphdeck::engine
