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

// Why an include of `path` may not be read given what the deck has read so far (`files`
// include files, `bytes` in all), or nullopt. Both readers ask before reading.
std::optional<std::string> include_budget_problem(const std::filesystem::path& path, std::size_t files,
                                                  std::size_t bytes, std::size_t max_files, std::size_t max_bytes);

// Every directory tried, for the "not found" note.
std::vector<std::filesystem::path> include_candidates(const std::string& name, const IncludeSearch& search);

}  // namespace sphdeck::grammar::dyna
