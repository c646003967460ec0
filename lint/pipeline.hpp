// Transitional forwarding header: the check pipeline moved to engine/check.hpp (issue 15). It stays
// so that tests and branches written against lint::check_file / lint::check_buffer keep compiling;
// new code includes engine/check.hpp. tests/test_layering.cpp allows this one file of lint/ to name
// engine/; delete it once nothing includes it.
#pragma once

#include "engine/check.hpp"

namespace sphdeck::lint {

using engine::CheckOptions;
using engine::CheckResult;
using engine::check_buffer;
using engine::check_file;

}  // namespace sphdeck::lint
