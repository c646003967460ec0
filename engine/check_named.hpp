// A file named to be checked, as `sphdeck check FILE` and the Python module's check(path) take it: an
// include file is checked as part of the decks around it that include it (engine/include_context.hpp),
// each of their checks then holding only the file's findings; a file no deck includes, on its own.
#pragma once

#include <string>
#include <vector>

#include "engine/check.hpp"

namespace sphdeck::engine {

struct NamedCheck {
    std::vector<CheckResult> checked;      // one check, or one per deck around the file
    std::vector<std::string> included_by;  // the decks around the file, as their findings name them; empty when alone
};

// `in_context` false checks the file on its own (`check --alone`, a deck found in a folder).
// Throws std::runtime_error when the file cannot be read, as check_file does.
NamedCheck check_named_file(const std::string& path, const CheckOptions& options, bool in_context = true);

}  // namespace sphdeck::engine
