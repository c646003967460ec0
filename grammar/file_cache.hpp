// One run's shared reading of deck files (issue 33): decks that include the same file share its text,
// and, when that file's reading depends on nothing outside it, the blocks and card lines the reader
// made of it. What is shared is the raw read only: values are decoded per deck, under each deck's own
// *PARAMETERs (a block's `&name` means what the deck around it defines), so nothing that depends on
// them is shared. Safe to use from several threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "text/source_text.hpp"

namespace sphdeck::grammar {

// The file id a FileReading is written with; dyna::DeckReader lays it into a deck under the file's own.
inline constexpr FileId reading_file = no_file - 1;

// What a reader made of one file read alone: its blocks, card lines and reading findings, written
// with FileId reading_file, block lines counted from 0, scope and parameter epoch 0.
struct FileReading {
    std::vector<Block> blocks;
    CardLines lines;
    std::vector<diag::Diagnostic> diagnostics;
    std::uint32_t physical_lines = 0;  // ReadStats::lines of the file
    SourceText text;                   // what it was read from: compared when another path has the same hash
};

class FileCache {
public:
    // One version of a file on disk: its text and what its content says about sharing its reading.
    struct File {
        SourceText text;
        std::uint64_t hash = 0;       // of the content
        bool self_contained = false;  // names no *INCLUDE, *PARAMETER, *KEYWORD, *RVE: read alike in any deck
    };

    // The file at `path` as it is now: shared with earlier calls while its size and modification
    // time stay the same. Throws like SourceText::read.
    std::shared_ptr<const File> file(const std::string& path);

    // A reading of `file` in card format `format`: shared when one was made from the same content
    // (hash, size, then the bytes), or a claim to make it. The claim's holder reads the file and
    // calls fulfil(); other threads asking meanwhile wait for it (a self-contained file includes
    // nothing, so its reader never waits on another claim). A claim dropped unfulfilled leaves the
    // file to be read by each deck. Neither is set when the file is not self-contained.
    class Claim;
    struct Lookup {
        std::shared_ptr<const FileReading> reading;
        std::unique_ptr<Claim> claim;
    };
    Lookup reading(const File& file, CardFormat format);

    struct Counters {
        std::size_t files_read = 0, files_shared = 0;        // texts read from disk, or given again
        std::size_t readings_made = 0, readings_shared = 0;  // readings made, or laid into another deck
    };
    Counters counters() const;

private:
    struct Version {
        std::uintmax_t size = 0;
        std::filesystem::file_time_type modified;
        std::shared_ptr<const File> file;
    };
    using ReadingKey = std::tuple<std::uint64_t, std::size_t, CardFormat>;
    mutable std::mutex mutex_;
    std::map<std::filesystem::path, Version> files_;
    std::map<ReadingKey, std::shared_future<std::shared_ptr<const FileReading>>> readings_;
    Counters counters_;
};

class FileCache::Claim {
public:
    Claim() = default;
    Claim(const Claim&) = delete;
    Claim& operator=(const Claim&) = delete;
    ~Claim();
    void fulfil(FileReading reading);

private:
    friend class FileCache;
    std::promise<std::shared_ptr<const FileReading>> promise_;
    bool done_ = false;
};

}  // namespace sphdeck::grammar
