// Source files of a deck and positions inside them.
// Every value the readers produce points back here, through includes, so diagnostics can
// name file:line:column and print the include chain.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/source_text.hpp"

namespace sphdeck::text {

using FileId = std::uint32_t;
inline constexpr FileId no_file = 0xFFFFFFFFu;

// A range of columns on one line. Columns are 1-based; end_column is one past the last.
struct Span {
    FileId file = no_file;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::uint32_t end_column = 0;

    bool valid() const { return file != no_file; }
};

// The word that opens an inline suppression in a comment ("$ sphdeck: ...", lint/suppressions.cpp).
inline constexpr std::string_view directive_marker = "sphdeck";

// One opened file: an include instance. The same path included twice is two instances,
// because each has its own include chain and parameter scope.
struct SourceFile {
    std::string path;                // as opened (resolved)
    std::string display_name;        // as the user or the include line wrote it
    SourceText text;                 // whole content, never modified after reading (owned or mapped)
    FileId parent = no_file;         // the file whose *INCLUDE opened this one
    std::uint32_t include_line = 0;  // line of that *INCLUDE keyword in the parent
    unsigned depth = 0;              // 0 for a main file

    mutable std::vector<std::uint32_t> line_starts;  // built lazily and partly, for excerpts only
    // Whether a line of `text` that starts with '$' or '#' holds directive_marker, where the reader looked
    // at every line (a big file read in chunks, grammar/line_chunks.hpp); unknown otherwise. With it the
    // suppressions need no second pass over a big text.
    std::optional<bool> comment_holds_marker;
};

class SourceMap {
public:
    FileId add(SourceFile file);
    const SourceFile& file(FileId id) const { return files_.at(id); }
    SourceFile& file(FileId id) { return files_.at(id); }
    std::size_t size() const { return files_.size(); }

    // The text of a 1-based line, without its end-of-line characters; empty past the end.
    std::string_view line_text(FileId id, std::uint32_t line) const;
    // Number of lines of a file (a final line without newline counts).
    std::uint32_t line_count(FileId id) const;
    // Files from the main file down to `id` (the include chain), main first.
    std::vector<FileId> include_chain(FileId id) const;

private:
    void index_lines(const SourceFile& f, std::uint32_t up_to_line) const;
    std::deque<SourceFile> files_;  // deque: references stay valid while includes are added
};

}  // namespace sphdeck::text

// grammar/ and the rooms above it named these grammar::X before text/ was split out of grammar/ (issue 39);
// the names stay so that their code reads on unchanged.
namespace sphdeck::grammar {
using text::FileId;
using text::no_file;
using text::SourceFile;
using text::SourceMap;
using text::Span;
}  // namespace sphdeck::grammar
