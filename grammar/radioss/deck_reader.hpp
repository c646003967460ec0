// Internal: the state the Radioss line grammar's actions feed while a deck and its includes
// are read. One DeckReader per main file (the starter, then the engine deck).
#pragma once

#include "grammar/dropped_after_end.hpp"
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "grammar/radioss/reader.hpp"

namespace sphdeck::grammar::radioss {

class DeckReader {
public:
    DeckReader(RawDeck& deck, const ReaderOptions& options, std::filesystem::path main_directory);

    // Reads one file's text (already in the SourceMap) with the line grammar.
    void read(FileId file);

    // Called by the grammar's actions, once per physical line.
    void on_empty(const char* begin);
    void on_comment(const char* begin, const char* end);
    void on_header(const char* begin, const char* end);
    void on_data(const char* begin, const char* end);
    void on_include(const char* begin, const char* end, std::string_view name);
    void on_enddata(const char* begin, const char* end);

    const char* header_path = nullptr;  // scratch: where the '/' of a header line is

private:
    struct OpenFile {
        FileId id = 0;
        const char* base = nullptr;
        std::uint32_t line = 0;
        bool done = false;  // after #enddata
        bool reported_after = false;
        bool reported_stray = false;
        bool headed = false;  // a header line was read in this file
    };

    // A big file read in chunks on all threads (grammar/line_chunks.hpp, chunked_lines.cpp): the lines the
    // grammar must read go through it one by one (grammar_line, reader.cpp), runs of data lines in one step.
    // Whether a comment line holds the suppressions' marker (text::SourceFile::comment_holds_marker).
    bool read_chunked(const SourceText& text, std::size_t chunk_bytes);
    void grammar_line(const char* begin, const char* text_end);
    void data_lines(const std::uint32_t* starts, std::size_t count, const char* text_end);

    OpenFile& current() { return stack_.back(); }
    // Lines of an included file before its first header: no keyword reads them.
    bool in_preamble() const { return stack_.size() > 1 && !stack_.back().headed; }
    bool skipped(const char* begin, const char* end);
    void close_block();
    void report(const char* code, diag::Severity severity, std::string message, Span span);
    Span line_span(const char* begin, const char* end) const;

    RawDeck& deck_;
    const ReaderOptions& options_;
    std::filesystem::path main_directory_;
    std::deque<OpenFile> stack_;
    // Per FileId, for cycle detection: asked of the system only when an include is found (canonical_of),
    // since a deck read from a buffer with no include would pay several system calls for nothing.
    std::vector<std::filesystem::path> canonical_;
    const std::filesystem::path& canonical_of(FileId file);
    // The open block. A block's cards come from its own file: the starter skips an #include
    // line while it reads one keyword, and finds the included file's blocks by their headers
    // (reader/source/cfgio/MODEL_IO/meci_read_model_base.cpp: includes are not followed in
    // READ_STATUS_SINGLE_KEYWORD), so an included file's lines before its first header belong
    // to no block (QA LOI13: its /GRNOD/NODE keeps 45 nodes though qadiags.inc follows it).
    std::optional<std::size_t> block_;
    bool ended_ = false;       // after /END: the rest of the deck is ignored
    DroppedAfterEnd dropped_;  // the blocks that are (DK017)
public:
    // After the deck's last file: the warning for blocks after /END (grammar/dropped_after_end.hpp).
    void report_dropped_blocks();
};

}  // namespace sphdeck::grammar::radioss
