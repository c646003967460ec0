// What the reference solver needs from the blocks of an OpenRadioss deck that the reader keeps as
// they are (no card layout, so neither the Model nor RadiossFacts holds them): the engine deck's
// /RUN end time, the /INIVEL cards, and every block the solver must refuse or may ignore (/GRAV,
// /BCS, /INTER...), read from the raw deck (radioss_run_input.cpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// /INIVEL/<kind>/<id>: a title line, then Vx Vy Vz in 20-column fields and the node group and skew
// in 10-column fields (the starter's hm_read_inivel.F, format 2017 and later).
struct RadiossInitialVelocity {
    std::string kind;  // "TRA", "ROT", "T+G", "GRID", "AXIS", "FVM"... (upper case)
    std::array<double, 3> v{};
    long long group = 0, skew = 0;
    bool read = false;  // the card was found and its numbers are valid
    grammar::Span span;
};

struct RadiossKeptBlock {
    std::string keyword;  // upper case, the whole header: "/GRAV/1"
    grammar::Span span;
    bool engine = false;  // in the engine deck (or before /END/ENGINE of a one-file deck)
};

struct RadiossRunInput {
    std::optional<double> end_time;  // Tstop of the engine deck's /RUN/<name>/<n>
    grammar::Span run_span;
    std::vector<RadiossInitialVelocity> initial_velocities;
    std::vector<RadiossKeptBlock> blocks;  // every block, starter and engine
};

RadiossRunInput read_radioss_run_input(const grammar::RawDeck& deck);

}  // namespace sphdeck::model
