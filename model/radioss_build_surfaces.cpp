// The surfaces of a Radioss deck: every /SURF kind (PART, SEG, BOX, MAT, PROP, SURF, PLANE,
// ELLIPS...) names its id in the header, /SURF/<kind>[/<option>]/<id> (hm_read_surf.F reads it as
// the option id), so the ids come from the headers; the cards are not read.
#include "grammar/radioss/cards.hpp"
#include "grammar/value.hpp"
#include "model/radioss_builder.hpp"

namespace sphdeck::model {

void RadiossBuilder::collect_surfaces() {
    for (const grammar::Block& block : deck_.blocks) {
        const auto segments = grammar::radioss::path_segments(block.keyword);
        // A /SET is a surface of its id too when an option asks for one (starter fill_igr.F).
        if (segments.empty() || (segments[0] != "SURF" && segments[0] != "SET")) continue;
        bool found = false;
        for (std::size_t k = 1; k < segments.size() && !found; ++k) {
            const auto id = grammar::parse_integer(segments[k]);
            if (id.status != grammar::NumberStatus::Ok) continue;
            facts_.surfaces.push_back({id.value, block.span});
            found = true;
        }
        // An id we cannot read (a parameter, a typo): the starter may still know the surface.
        if (!found) facts_.surfaces_known = false;
    }
}

}  // namespace sphdeck::model
