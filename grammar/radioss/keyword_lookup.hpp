// Which Radioss keyword reads a header: the hand-written tables (grammar/radioss/cards_*.cpp)
// and the layouts generated from the starter's CFG files, and whether the name is a keyword at
// all (a hand-written family table such as /MAT or /PROP reads any law, but /MAT/LAW999 is no
// keyword). The engine's own check of a header (engine/source/input/redkey0.F) is here too.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::grammar::radioss {

struct KeywordLookup {
    // The table that reads the block: a hand-written one where it reads the block into the model
    // (decoded) or no generated layout matches as well, else the generated one; nullptr: none.
    const KeywordSpec* spec = nullptr;
    std::size_t prefix_segments = 0;  // header segments the table's name matched
    // The table whose cards the lines are checked against: `spec`, or a generated layout where
    // `spec` is a hand-written family table that keeps every line as text (/PROP for
    // /PROP/SHELL): the model reads the header through `spec`, the cards are checked by this.
    const KeywordSpec* cards = nullptr;
    // The name is a starter or engine keyword: a generated name, or a hand-written name that is
    // not only a family's catch-all.
    bool known = false;
};

// `header`: upper case, "/INTER/TYPE7/5".
KeywordLookup lookup_keyword(std::string_view header);

// The generated layout whose name matches the most leading segments of `header`, or nullptr.
const KeywordSpec* find_generated(std::string_view header, std::size_t* prefix_segments = nullptr);

// The engine's reader (REDKEY0): the first five characters of the first segment are one of its
// keywords (/RUN, /ANIM, /TFILE, /DT, /PARITH ...); it stops on any other.
bool is_engine_key(std::string_view header);
// An engine key whose first segment no starter keyword has (/ANIM, /RUN, /TFILE; not /INTER or
// /TH, which both decks have): a header the starter does not know is then an engine one. Not a first
// segment no engine keyword has in full whose five characters begin a starter keyword's (/FUNCTT: a typo
// of /FUNCT, which the engine's five-character key would also take).
bool is_engine_only_key(std::string_view header);

// The segments the generated names put after `family` ("/GRSH3N" -> BOX, PART, SHELL...), sorted;
// empty when no generated name continues it.
std::vector<std::string> options_below(std::string_view family);

// The known keyword name closest to `name` ("/SHEL" -> "/SHELL"), or nullopt.
std::optional<std::string> suggest_keyword(std::string_view name);

}  // namespace sphdeck::grammar::radioss
