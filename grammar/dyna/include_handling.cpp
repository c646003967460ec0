// *KEYWORD arguments and the *INCLUDE family, acted on when their block closes.
#include <cstring>
#include <stdexcept>

#include "grammar/dyna/deck_reader.hpp"
#include "grammar/dyna/include_not_found.hpp"
#include "grammar/dyna/keyword_arguments.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/dyna/include_text.hpp"

namespace sphdeck::grammar::dyna {

namespace {
constexpr std::size_t max_include_name = 236;  // *INCLUDE Remark 2, via dynareadout and pydyna

std::string_view trim(std::string_view s, std::size_t* leading = nullptr) {
    std::size_t b = 0, e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
    if (leading) *leading = b;
    return s.substr(b, e - b);
}
}  // namespace

const std::filesystem::path& DeckReader::canonical_of(FileId file) {
    if (canonical_paths_.size() <= file) canonical_paths_.resize(file + 1);
    if (canonical_paths_[file].empty()) canonical_paths_[file] = canonical_path(deck_.sources.file(file).path);
    return canonical_paths_[file];
}

void DeckReader::handle_keyword_line_arguments(const Block& block) {
    KeywordArguments args = parse_keyword_arguments(block.arguments);
    args.span = block.span;
    OpenFile& f = current();
    if (stack_.size() == 1) {
        if (args.long_format)
            f.format = CardFormat::Long;
        else if (args.i10_format)
            f.format = CardFormat::I10;
        if (!deck_.keyword_arguments.present) deck_.keyword_arguments = args;
    } else if (args.long_format || args.i10_format) {
        report("DK019", diag::Severity::Warning,
               "long=/i10= on *KEYWORD inside an included file is ignored by LS-DYNA; put a suffix on the "
               "*INCLUDE line instead",
               block.span);
    }
}

// File names of an include block: each name may continue over lines ending in " +".
std::vector<std::pair<std::string, Span>> DeckReader::file_names(const Block& block, std::size_t max_names) {
    std::vector<std::pair<std::string, Span>> names;
    std::string name;
    Span span;
    bool continuing = false;
    for (CardLinePtr l = deck_.begin_lines(block); l != deck_.end_lines(block); ++l) {
        std::size_t lead = 0;
        std::string_view text = trim(deck_.text(*l), &lead);
        if (!continuing) {
            if (names.size() >= max_names) break;
            if (text.empty()) continue;
            name.clear();
            span = Span{l->file, l->line, static_cast<std::uint32_t>(lead + 1),
                        static_cast<std::uint32_t>(lead + text.size() + 1)};
        }
        continuing = text.size() >= 2 && text.back() == '+' && (text[text.size() - 2] == ' ');
        if (continuing) text = trim(text.substr(0, text.size() - 1));
        name += text;
        if (!continuing) names.emplace_back(name, span);
    }
    if (continuing) names.emplace_back(name, span);
    return names;
}

void DeckReader::handle_include(const Block& block, bool transform) {
    // *INCLUDE_TRANSFORM has one file name followed by offset and scale cards.
    for (auto& [name, span] : file_names(block, transform ? 1 : SIZE_MAX)) open_include(name, span, block.suffix);
}

void DeckReader::handle_include_path(const Block& block, bool relative) {
    for (auto& [name, span] : file_names(block, SIZE_MAX)) {
        std::filesystem::path dir(name);
        include_paths_.push_back(relative || dir.is_relative() ? main_directory_ / dir : dir);
        include_path_origins_.push_back(block.keyword + " at line " + std::to_string(span.line) + " of " +
                                        deck_.sources.file(span.file).display_name);
    }
}

void DeckReader::open_include(const std::string& name, Span where, char suffix) {
    if (name.size() > max_include_name) {
        report("DK025", diag::Severity::Error,
               "include file name has " + std::to_string(name.size()) + " characters; LS-DYNA reads at most 236",
               where);
    }
    const OpenFile& parent = current();
    const SourceFile& parent_source = deck_.sources.file(parent.id);
    if (stack_.size() > options_.max_include_depth) {
        report("DK011", diag::Severity::Error,
               "include nesting deeper than " + std::to_string(options_.max_include_depth) + " files; '" + name +
                   "' is not read",
               where);
        return;
    }
    IncludeSearch search{std::filesystem::path(parent_source.path).parent_path(), main_directory_, include_paths_,
                         options_.overlay, include_path_origins_};
    auto resolved = resolve_include(name, search);
    if (!resolved) {
        const bool continued = where.end_column - where.column != name.size();  // over several lines (" +")
        deck_.diagnostics.push_back(include_not_found(name, where, search, continued, false));
        return;
    }
    const std::filesystem::path canonical = canonical_path(resolved->path);  // the same file by any path
    for (const OpenFile& open : stack_) {
        if (canonical_of(open.id) == canonical) {
            report("DK011", diag::Severity::Error,
                   "include cycle: '" + name + "' is already being read (" + deck_.sources.file(open.id).display_name +
                       ")",
                   where);
            return;
        }
    }
    if (auto problem = include_budget_problem(resolved->path, deck_.sources.size() - 1, deck_.stats.bytes,
                                              options_.max_include_files, options_.max_total_bytes)) {
        report("DK011", diag::Severity::Error, "include file '" + name + "' is not read: " + *problem, where);
        return;
    }
    SourceFile child;
    child.path = resolved->path.string();
    child.display_name = normal_path(resolved->path).string();
    child.parent = parent.id;
    child.include_line = where.line;
    child.depth = parent_source.depth + 1;
    std::shared_ptr<const FileCache::File> cached;  // the run's copy, whose reading other decks share
    try {
        child.text = read_include_text(child.path, options_.overlay, options_.cache, &cached);
    } catch (const std::exception& e) {
        report("DK010", diag::Severity::Error, std::string("include file '") + name + "' cannot be read: " + e.what(),
               where);
        return;
    }
    CardFormat format = parent.format;
    if (suffix == '+')
        format = CardFormat::Long;
    else if (suffix == '%')
        format = CardFormat::I10;
    else if (suffix == '-')
        format = CardFormat::Standard;
    FileId id = deck_.sources.add(std::move(child));
    read(id, format, cached.get());
}

}  // namespace sphdeck::grammar::dyna
