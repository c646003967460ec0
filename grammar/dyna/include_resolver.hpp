// Where an *INCLUDE file name points (lsdyna-format.md §13). LS-DYNA's exact order is not
// documented; we follow the reference's recommendation and say which directory matched.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "grammar/file_overlay.hpp"

namespace sphdeck::grammar::dyna {

struct IncludeSearch {
    std::filesystem::path including_directory;  // folder of the file with the *INCLUDE
    std::filesystem::path main_directory;       // folder of the main deck
    std::vector<std::filesystem::path> include_paths;  // *INCLUDE_PATH(_RELATIVE) entries, then --include-path
    const FileOverlay* overlay = nullptr;  // in-memory texts that count as files
};

struct ResolvedInclude {
    std::filesystem::path path;
    std::string matched_by;  // "absolute path", "including file's folder", ...
};

// Order: absolute name as is; the including file's folder; the main file's folder;
// each include path in order of definition. A regular file wins; when there is none, the first
// other entry of that name (a directory), so that the caller reports what it is.
std::optional<ResolvedInclude> resolve_include(const std::string& name, const IncludeSearch& search);

// Every directory tried, for the "not found" note.
std::vector<std::filesystem::path> include_candidates(const std::string& name, const IncludeSearch& search);

}  // namespace sphdeck::grammar::dyna
