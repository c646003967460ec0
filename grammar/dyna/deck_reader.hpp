// Internal: the state the line grammar's actions feed while a deck and its includes are read.
#pragma once

#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/dropped_after_end.hpp"
#include "grammar/dyna/include_resolver.hpp"
#include "grammar/dyna/reader.hpp"

namespace sphdeck::grammar::dyna {

// The parts of a keyword line, filled by the grammar's actions.
struct KeywordLineParts {
    std::string_view name;
    char suffix = 0;
    std::string_view arguments;
};

class DeckReader {
public:
    DeckReader(RawDeck& deck, const ReaderOptions& options);

    // Reads one file's text (already in the SourceMap) with the line grammar; `cached`: the file as the
    // run's FileCache holds it, whose reading another deck may have made already (shared_reading.cpp).
    void read(FileId file, CardFormat inherited_format, const FileCache::File* cached = nullptr);

    // Called by the grammar's actions, once per physical line.
    void on_comment();
    void on_keyword(const char* line_begin, const char* line_end, const KeywordLineParts& parts);
    void on_data(const char* line_begin, const char* line_end);
    void on_pgp_begin(const char* line_begin, const char* line_end);
    void on_pgp_end(const char* line_begin, const char* line_end);

    KeywordLineParts parts;  // scratch for the keyword-line actions

    void set_main_directory(std::filesystem::path dir) { main_directory_ = std::move(dir); }

private:
    struct OpenFile {
        FileId id = 0;
        CardFormat format = CardFormat::Standard;
        const char* base = nullptr;
        const SourceText* text = nullptr;
        std::size_t released = 0;  // bytes of `text` handed back (SourceText::release)
        std::uint32_t line = 0;
        std::optional<std::size_t> block;  // index of the open block in deck_.blocks
        bool ended = false;                // after *END
        bool reported_after_end = false;
        DroppedAfterEnd dropped;        // keyword blocks after *END (DK017)
        bool in_comment_block = false;  // inside *COMMENT
        bool in_encrypted = false;
        bool reported_stray_data = false;
    };

    static constexpr std::size_t release_step = std::size_t{8} << 20;

    // A big file read in chunks on all threads (grammar/line_chunks.hpp, chunked_lines.cpp): the lines the
    // grammar must read go through it one by one (grammar_line, reader.cpp), runs of data lines in one step.
    // Whether a comment line holds the suppressions' marker (text::SourceFile::comment_holds_marker).
    bool read_chunked(const SourceText& text, std::size_t chunk_bytes);
    void grammar_line(const char* begin, const char* text_end);
    void data_lines(const std::uint32_t* starts, std::size_t count, const char* text_end);

    OpenFile& current() { return stack_.back(); }
    bool indented_data(std::size_t star, const KeywordLineParts& parts);
    void close_block();
    bool after_end(const char* begin, const char* end);
    void report_dropped_blocks(std::size_t first_diagnostic);
    Span span_of(const char* begin, const char* end, std::size_t column_begin, std::size_t column_end) const;
    void report(const char* code, diag::Severity severity, std::string message, Span span);

    // Special keywords, handled when their block closes (block_handlers.cpp).
    void handle_keyword_line_arguments(const Block& block);
    void handle_include(const Block& block, bool transform);
    void handle_include_path(const Block& block, bool relative);
    void open_include(const std::string& name, Span where, char suffix);
    std::vector<std::pair<std::string, Span>> file_names(const Block& block, std::size_t max_lines);

    // A shared reading laid into the deck as `file`, and the reading of `file` just made, to share.
    void lay_in(FileId file, const FileReading& reading);
    FileReading reading_of(FileId file, std::size_t first_block, std::size_t first_line, std::size_t first_diagnostic,
                           std::uint32_t physical_lines) const;

    RawDeck& deck_;
    const ReaderOptions& options_;
    std::deque<OpenFile> stack_;  // deque: an include pushed while a caller holds current()
    // Per FileId, for cycle detection: asked of the system only when an include is found (canonical_of),
    // since a deck read from a buffer with no include would pay several system calls for nothing.
    std::vector<std::filesystem::path> canonical_paths_;
    const std::filesystem::path& canonical_of(FileId file);
    std::filesystem::path main_directory_;
    std::vector<std::filesystem::path> include_paths_;
    std::vector<std::string> include_path_origins_;  // per include path: the option or card that gave it
};

}  // namespace sphdeck::grammar::dyna
