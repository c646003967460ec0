// DK016's fix: the tabs of a fixed-format line replaced by the blanks an editor shows in their place,
// when that layout is certain: with tab stops every 8 columns each value lies whole inside a field of
// its own, right-aligned to its end (or left-aligned to its start), and tab stops every 4 columns show
// no other such layout. The solver counts a tab as one
// column; the author placed the values by what the editor showed, which is what the blanks keep.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "grammar/fields.hpp"

namespace sphdeck::grammar {

// `text` with each tab expanded to the next multiple of `stop` columns.
std::string expand_tabs(std::string_view text, std::size_t stop);

// The line with its tabs expanded (stops every 8), or nullopt when that is not certain (see above).
std::optional<std::string> expand_tabs_if_certain(std::string_view text, std::span<const FixedField> positions);

}  // namespace sphdeck::grammar
