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
    std::filesystem::path including_directory;         // folder of the file with the *INCLUDE
    std::filesystem::path main_directory;              // folder of the main deck
    std::vector<std::filesystem::path> include_paths;  // --include-path (-I) entries, then *INCLUDE_PATH(_RELATIVE)
    const FileOverlay* overlay = nullptr;              // in-memory texts that count as files
    // Where each include path came from ("-I or include-paths", "*INCLUDE_PATH at line 4"), for the
    // not-found report; may be shorter than include_paths (the rest: "include path").
    std::vector<std::string> include_path_origins = {};
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

// Every path tried, once each in search order, with the search rules that led to it ("including
// file's folder", "main deck's folder", an include path's origin), for the "not found" report.
struct IncludeTry {
    std::filesystem::path path;
    std::vector<std::string> rules;
};
std::vector<IncludeTry> include_tries(const std::string& name, const IncludeSearch& search);

}  // namespace sphdeck::grammar::dyna
