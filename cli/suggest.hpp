// "did you mean" for names typed on the command line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sphdeck::cli {

// "; did you mean 'check'?" when a candidate is within 2 edits, else "".
std::string did_you_mean(std::string_view typed, const std::vector<std::string_view>& candidates);

}  // namespace sphdeck::cli
