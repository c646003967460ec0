// What a Radioss card cell holds, in words, for `sphdeck keyword` and editor hovers.
#pragma once

#include <string_view>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::grammar::radioss {

std::string_view cell_kind_name(Cell cell);

}  // namespace sphdeck::grammar::radioss
