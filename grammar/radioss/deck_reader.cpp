// What each kind of line does to the deck (radioss-format.md §2): headers open blocks, data lines
// join the open block, #include reads a file in place, #enddata ends a file, /END the deck.
#include "grammar/radioss/deck_reader.hpp"

#include "grammar/radioss/keyword_lookup.hpp"

#include "grammar/dyna/include_not_found.hpp"
#include "grammar/dyna/include_resolver.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/parameters.hpp"
#include "grammar/fields.hpp"
#include "grammar/dyna/include_text.hpp"

namespace sphdeck::grammar::radioss {
namespace {

std::string_view strip_cr(const char* begin, const char* end) {
    std::string_view s(begin, static_cast<std::size_t>(end - begin));
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    return s;
}

std::string_view trim(std::string_view s) { return grammar::trim_blanks(s); }

bool blank(std::string_view s) { return trim(s).empty(); }

}  // namespace

DeckReader::DeckReader(RawDeck& deck, const ReaderOptions& options, std::filesystem::path main_directory)
    : deck_(deck), options_(options), main_directory_(std::move(main_directory)) {}

const std::filesystem::path& DeckReader::canonical_of(FileId file) {
    if (canonical_.size() <= file) canonical_.resize(file + 1);
    if (canonical_[file].empty()) canonical_[file] = canonical_path(deck_.sources.file(file).path);
    return canonical_[file];
}

void DeckReader::report(const char* code, diag::Severity severity, std::string message, Span span) {
    deck_.diagnostics.push_back(diag::Diagnostic{code, severity, std::move(message), span, {}});
}

Span DeckReader::line_span(const char* begin, const char* end) const {
    const OpenFile& f = stack_.back();
    const auto length = static_cast<std::uint32_t>(std::max<std::size_t>(strip_cr(begin, end).size(), 1));
    return Span{f.id, f.line, 1, length + 1};
}

// Lines after /END (anywhere) or after #enddata (in this file) are ignored; the first non-blank
// one is reported once per file (DK017).
bool DeckReader::skipped(const char* begin, const char* end) {
    OpenFile& f = current();
    if (!ended_ && !f.done) return false;
    if (!f.reported_after && !blank(strip_cr(begin, end))) {
        f.reported_after = true;
        report("DK017", diag::Severity::Info,
               std::string("content after ") + (f.done ? "#enddata" : "/END") + " is ignored", line_span(begin, end));
    }
    return true;
}

void DeckReader::on_empty(const char* begin) {
    ++current().line;
    if (ended_ || current().done || !block_ || in_preamble()) return;
    // A blank line inside a block is a card (blank cards take every default); trailing blank
    // lines of a block are dropped when it closes.
    OpenFile& f = current();
    deck_.lines.push_back(CardLine{f.id, f.line, static_cast<std::uint32_t>(begin - f.base)});
    ++deck_.blocks[*block_].line_count;
    ++deck_.stats.cards;
}

void DeckReader::on_comment(const char*, const char*) { ++current().line; }

void DeckReader::on_enddata(const char* begin, const char* end) {
    ++current().line;
    if (skipped(begin, end)) return;
    current().done = true;
}

void DeckReader::on_header(const char* begin, const char* end) {
    OpenFile& f = current();
    ++f.line;
    if (ended_ && header_path == begin) {
        const std::string header = to_upper(trim(strip_cr(header_path, end)));
        dropped_.note_radioss(header, lookup_keyword(header).known);
    }
    if (skipped(begin, end)) return;
    close_block();
    f.headed = true;
    const auto indent = static_cast<std::size_t>(header_path - begin);
    std::string_view path = trim(strip_cr(header_path, end));

    Block block;
    block.keyword = to_upper(path);
    block.arguments = std::string(path);
    block.span = Span{f.id, f.line, static_cast<std::uint32_t>(indent + 1),
                      static_cast<std::uint32_t>(indent + 1 + path.size())};
    block.first_line = static_cast<std::uint32_t>(deck_.lines.size());
    block.scope = f.id;
    block.parameter_epoch = deck_.parameters.epoch();
    ++deck_.stats.keywords;
    if (indent > 0)
        report("DK020", diag::Severity::Warning,
               "header line does not start in column 1; OpenRadioss reads it as data unless headers may be indented",
               block.span);
    if (indent > 0)  // safe: sphdeck reads the line as this header; in column 1 the starter does too
        deck_.diagnostics.back().fixes.push_back(
            {"start the header line in column 1",
             true,
             {{Span{f.id, f.line, 1, static_cast<std::uint32_t>(indent + 1)}, ""}}});
    deck_.blocks.push_back(std::move(block));
    if (deck_.blocks.back().keyword == "/END") {
        ended_ = true;
        dropped_.set_end(deck_.blocks.back().span);
        return;
    }
    block_ = deck_.blocks.size() - 1;
}

void DeckReader::on_data(const char* begin, const char* end) {
    OpenFile& f = current();
    ++f.line;
    if (skipped(begin, end)) return;
    std::string_view text = strip_cr(begin, end);
    // The preamble of an included file (a licence header, say) is read by no keyword, and the
    // starter says nothing about it.
    if (in_preamble()) return;
    if (!block_) {
        if (!f.reported_stray && !blank(text)) {
            f.reported_stray = true;
            report("DK027", diag::Severity::Warning, "data line outside any header block is ignored",
                   line_span(begin, end));
        }
        return;
    }
    deck_.lines.push_back(CardLine{f.id, f.line, static_cast<std::uint32_t>(begin - f.base)});
    ++deck_.blocks[*block_].line_count;
    ++deck_.stats.cards;
}

// Trailing blank card lines of a block are not cards ("blank lines at the end of a block are
// ignored", radioss-format.md §2).
void DeckReader::close_block() {
    if (!block_) return;
    Block& b = deck_.blocks[*block_];
    while (b.line_count > 0) {
        const CardLine& last = deck_.lines[b.first_line + b.line_count - 1];
        if (!blank(deck_.text(last))) break;
        // Only the block's own trailing lines can be removed: they are the last lines read.
        if (b.first_line + b.line_count != deck_.lines.size()) break;
        deck_.lines.pop_back();
        --b.line_count;
        --deck_.stats.cards;
    }
    block_.reset();
}

void DeckReader::on_include(const char* begin, const char* end, std::string_view written) {
    OpenFile& f = current();
    ++f.line;
    if (skipped(begin, end)) return;
    std::string_view name = trim(written);
    if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front())
        name = name.substr(1, name.size() - 2);
    const auto column =
        static_cast<std::uint32_t>(std::string_view(begin, static_cast<std::size_t>(end - begin)).find(name) + 1);
    const Span where{f.id, f.line, column, column + static_cast<std::uint32_t>(std::max<std::size_t>(name.size(), 1))};
    const std::string file_name(name);
    if (file_name.empty()) {
        report("DK010", diag::Severity::Error, "#include without a file name", line_span(begin, end));
        return;
    }
    if (stack_.size() > options_.max_include_depth) {
        report("DK011", diag::Severity::Error,
               "include nesting deeper than " + std::to_string(options_.max_include_depth) + " files; '" + file_name +
                   "' is not read",
               where);
        return;
    }
    const SourceFile& parent = deck_.sources.file(f.id);
    std::vector<std::filesystem::path> paths(options_.include_paths.begin(), options_.include_paths.end());
    dyna::IncludeSearch search{std::filesystem::path(parent.path).parent_path(), main_directory_, paths,
                               options_.overlay, std::vector<std::string>(paths.size(), "-I or include-paths")};
    auto resolved = dyna::resolve_include(file_name, search);
    if (!resolved) {
        deck_.diagnostics.push_back(dyna::include_not_found(file_name, where, search, false, true));
        return;
    }
    const std::filesystem::path canonical = canonical_path(resolved->path);  // the same file by any path
    for (const OpenFile& open : stack_) {
        if (canonical_of(open.id) == canonical) {
            report("DK011", diag::Severity::Error,
                   "include cycle: '" + file_name + "' is already being read (" +
                       deck_.sources.file(open.id).display_name + ")",
                   where);
            return;
        }
    }
    if (auto problem = dyna::include_budget_problem(resolved->path, deck_.sources.size() - 1, deck_.stats.bytes,
                                                    options_.max_include_files, options_.max_total_bytes)) {
        report("DK011", diag::Severity::Error, "include file '" + file_name + "' is not read: " + *problem, where);
        return;
    }
    SourceFile child;
    child.path = resolved->path.string();
    child.display_name = normal_path(resolved->path).string();
    child.parent = f.id;
    child.include_line = f.line;
    child.depth = parent.depth + 1;
    try {
        child.text = dyna::read_include_text(child.path, options_.overlay, options_.cache);
    } catch (const std::exception& e) {
        report("DK010", diag::Severity::Error, "include file '" + file_name + "' cannot be read: " + e.what(), where);
        return;
    }
    // The open block goes on after the #include unless the child opened blocks of its own: its
    // last block ends with the child, and this file's lines after the #include, before the next
    // header, are then reported as outside any block (DK027; sphdeck keeps a block's lines together).
    const std::size_t blocks = deck_.blocks.size();
    read(deck_.sources.add(std::move(child)));
    if (deck_.blocks.size() != blocks) close_block();
}

// The warning then stands for the information on the first line after /END in its file.
void DeckReader::report_dropped_blocks() { dropped_.report(deck_.diagnostics, 0, "/END", false); }

}  // namespace sphdeck::grammar::radioss
