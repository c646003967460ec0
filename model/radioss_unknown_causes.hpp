// DK001 on an OpenRadioss header of a shape whose cause is known, said at the header: a family of
// options written without its option (/GRSH3N/1: the header is /GRSH3N/<type>/<id> and a title
// follows), and an LS-DYNA style /INCLUDE (OpenRadioss includes a file with a `#include` line).
#pragma once

#include <optional>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

// The finding for `block`'s unknown header when its shape says the cause; nullopt otherwise (the
// caller reports the name unknown, with its did-you-mean).
std::optional<diag::Diagnostic> unknown_header_cause(const grammar::RawDeck& deck, const grammar::Block& block);

}  // namespace sphdeck::model
