// The LS-DYNA keyword reader: files (or an in-memory buffer) in, a RawDeck out.
#pragma once

#include <string>
#include <vector>

#include "grammar/file_cache.hpp"
#include "grammar/file_overlay.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar::dyna {

struct ReaderOptions {
    std::vector<std::string> include_paths;  // extra directories searched after the deck's own
    unsigned max_include_depth = 200;        // deeper nesting is reported, not followed
    const FileOverlay* overlay = nullptr;    // texts in memory read instead of the files (engine/)
    FileCache* cache = nullptr;              // one run's shared reading of files on disk (engine/, cli/)
    // Bounds on what one deck reads, so that memory stays bounded whatever the includes say (a
    // file included twice at each of 30 levels is read 2^30 times): include files read, and
    // bytes of all files together. Past either, an include is reported, not read.
    std::size_t max_include_files = 100000;
    std::size_t max_total_bytes = std::size_t{16} << 30;  // 16 GiB: 1e8 lines of 160 columns
};

// Reads a deck and everything it includes. Throws std::runtime_error only when the main
// file cannot be read; every problem inside the deck becomes a diagnostic.
RawDeck read_file(const std::string& path, const ReaderOptions& options = {});

// Reads a deck held in memory (unsaved editor text, fuzzing). Relative includes are searched
// from `base_directory`.
RawDeck read_buffer(std::string text, const std::string& display_name, const std::string& base_directory = ".",
                    const ReaderOptions& options = {});

}  // namespace sphdeck::grammar::dyna
