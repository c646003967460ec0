// Which files a deck pulled in: its includes (nested), and for a Radioss starter the engine deck
// read beside it. An editor re-checks every open deck whose graph names an edited file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "text/source_map.hpp"

namespace sphdeck::engine {

struct IncludedFile {
    std::filesystem::path path;         // in the form documents are keyed by (Documents::key)
    std::string display_name;           // as diagnostics name it
    std::filesystem::path included_by;  // the including file; empty for a second main file (engine deck)
    std::uint32_t include_line = 0;     // the line of the include in `included_by`
};

struct IncludeGraph {
    std::filesystem::path main;       // the deck itself, keyed like the files
    std::vector<IncludedFile> files;  // every file read after the main one, in reading order

    // Whether the deck read `path` (its main file or any include): an edit to it changes the findings.
    bool depends_on(const std::filesystem::path& path) const;
};

// The graph of a read deck: file 0 of `sources` is the main deck.
IncludeGraph include_graph(const grammar::SourceMap& sources);

}  // namespace sphdeck::engine
