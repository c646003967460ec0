// The Radioss reader's driver: grammar actions, main files, the engine deck, RAD001.
#include "grammar/radioss/reader.hpp"

#include <cstring>

#include "grammar/radioss/deck_reader.hpp"
#include "grammar/radioss/line_grammar.hpp"
#include "grammar/deck_files.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/line_chunks.hpp"
#include "grammar/dyna/include_text.hpp"

namespace sphdeck::grammar::radioss {
namespace {

namespace pegtl = tao::pegtl;
namespace fs = std::filesystem;

template <typename Rule>
struct action : pegtl::nothing<Rule> {};

template <>
struct action<rules::empty_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_empty(in.begin());
    }
};
template <>
struct action<rules::comment_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_comment(in.begin(), in.end());
    }
};
template <>
struct action<rules::header_path> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.header_path = in.begin();
    }
};
template <>
struct action<rules::header_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_header(in.begin(), in.end());
    }
};
template <>
struct action<rules::include_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        std::string_view line(in.begin(), in.size());
        std::size_t at = line.find_first_of(" \t");  // after "#include"
        r.on_include(in.begin(), in.end(), line.substr(at == std::string_view::npos ? line.size() : at));
    }
};
template <>
struct action<rules::enddata_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_enddata(in.begin(), in.end());
    }
};
template <>
struct action<rules::data_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_data(in.begin(), in.end());
    }
};

bool ends_with(std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// RAD001: a starter deck whose first line is not a comment. The starter asks for no header: its
// reader takes a line with '#' or '$' in column 1 as a comment (reader/source/cfgio/MODEL_IO/
// meci_syntax_infos.cpp), and no code of reader/ or starter/ emits message 100201 ("mandatory first
// card #RADIOSS STARTER missing"), which msg_hw_radioss_reader.txt still defines. So `# RADIOSS`
// (QA onefile_rad/CRA2AV4_0000.rad, accepted) or any comment may come first; a deck that starts
// with data or a keyword lacks the conventional #RADIOSS STARTER line that every writer puts there.
void check_first_line(RawDeck& deck, FileId main) {
    const SourceFile& f = deck.sources.file(main);
    std::string_view text = f.text;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::string_view first = text.substr(0, text.find('\n'));
    while (!first.empty() && (first.back() == '\r' || first.back() == ' ' || first.back() == '\t'))
        first.remove_suffix(1);
    if (!first.empty() && (first.front() == '#' || first.front() == '$')) return;
    const auto width = static_cast<std::uint32_t>(std::max<std::size_t>(first.size(), 1));
    std::string found = first.empty() ? std::string("an empty line")
                                      : "'" + std::string(first.substr(0, std::min<std::size_t>(first.size(), 40))) +
                                            (first.size() > 40 ? "...'" : "'");
    deck.diagnostics.push_back(
        {"RAD001",
         diag::Severity::Error,
         "first line is " + found + "; a starter deck begins with the comment line #RADIOSS STARTER",
         Span{main, 1, 1, width + 1},
         {}});
}

void read_one(RawDeck& deck, SourceFile file, const fs::path& directory, const ReaderOptions& options) {
    const bool engine = is_engine_file_name(file.display_name);
    const std::size_t first_block = deck.blocks.size();
    FileId id = deck.sources.add(std::move(file));
    DeckReader reader(deck, options, directory);
    reader.read(id);
    // A one-file deck puts the engine input first, ends it with /END/ENGINE and follows with the
    // starter input (QA onefile_rad, accepted by the starter); it has no #RADIOSS STARTER line.
    bool one_file = false;
    for (std::size_t b = first_block; b < deck.blocks.size(); ++b)
        one_file = one_file || deck.blocks[b].keyword == "/END/ENGINE";
    // Only a file named as a starter deck (<run>_0000.rad, the name the starter reads) must begin
    // with #RADIOSS STARTER: another name is an include or a fragment (an editor opens those alone).
    const bool starter_name = ends_with(deck.sources.file(id).display_name, radioss_starter_suffix);
    if (!engine && !one_file && starter_name) check_first_line(deck, id);
}

// The engine deck next to a starter, read as a second main file (it has no include chain).
void read_engine(RawDeck& deck, const std::string& starter_name, const fs::path& directory,
                 const ReaderOptions& options) {
    auto name = engine_file_name(fs::path(starter_name).filename().string());
    if (!name) return;
    fs::path path = directory / *name;
    if (!is_regular_file(path, options.overlay)) return;
    SourceFile engine;
    engine.path = path.string();
    engine.display_name = (fs::path(starter_name).parent_path() / *name).string();
    try {
        engine.text = dyna::read_include_text(engine.path, options.overlay, options.cache);
    } catch (const std::exception& e) {
        deck.diagnostics.push_back({"DK010",
                                    diag::Severity::Error,
                                    "engine deck '" + engine.display_name + "' cannot be read: " + e.what(),
                                    Span{},
                                    {}});
        return;
    }
    read_one(deck, std::move(engine), directory, options);
}

RawDeck read_main(SourceFile main, const fs::path& directory, const ReaderOptions& options) {
    RawDeck deck;
    // A file read in chunks counts its lines on the threads (DeckReader::read_chunked reserves then).
    const bool chunked = line_chunk_bytes(main.text.size()) > 0;
    if (!chunked) {
        std::size_t newlines = 0;
        for (const char* p = main.text.data();
             (p = static_cast<const char*>(
                  std::memchr(p, '\n', static_cast<std::size_t>(main.text.data() + main.text.size() - p))));
             ++p)
            ++newlines;
        deck.lines.reserve(newlines + 1);
    }
    const std::string name = main.display_name;
    read_one(deck, std::move(main), directory, options);
    read_engine(deck, name, directory, options);
    return deck;
}

}  // namespace

std::optional<std::string> engine_file_name(std::string_view name) {
    if (!ends_with(name, ".rad") || is_engine_file_name(name)) return std::nullopt;
    std::string_view stem = name.substr(0, name.size() - 4);
    if (ends_with(stem, "_0000")) stem.remove_suffix(5);
    return std::string(stem) + "_0001.rad";
}

bool is_engine_file_name(std::string_view name) {
    if (!ends_with(name, ".rad") || name.size() < 9) return false;
    std::string_view digits = name.substr(name.size() - 8, 4);
    if (name[name.size() - 9] != '_') return false;
    for (char c : digits)
        if (c < '0' || c > '9') return false;
    return digits != "0000";
}

void DeckReader::read(FileId file) {
    const SourceFile& source = deck_.sources.file(file);
    deck_.parameters.add_file(file, source.parent);
    ++deck_.stats.files;
    deck_.stats.bytes += source.text.size();

    OpenFile open;
    open.id = file;
    open.base = source.text.data();
    stack_.push_back(open);
    if (const std::size_t chunk_bytes = line_chunk_bytes(source.text.size())) {
        deck_.sources.file(file).comment_holds_marker = read_chunked(source.text, chunk_bytes);
    } else {
        pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(
            source.text.data(), source.text.data() + source.text.size(), source.path.c_str());
        pegtl::parse<rules::file, action>(in, *this);
    }
    deck_.stats.lines += current().line;
    stack_.pop_back();
    if (stack_.empty()) close_block(), report_dropped_blocks();
}

// One line read with the line grammar, as the file loop reads it there (`begin` starts a line).
void DeckReader::grammar_line(const char* begin, const char* text_end) {
    pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(begin, text_end, "");
    pegtl::parse<rules::line, action>(in, *this);
}

RawDeck read_file(const std::string& path, const ReaderOptions& options) {
    SourceFile main;
    main.path = path;
    main.display_name = path;
    main.text = dyna::read_include_text(path, options.overlay, options.cache);
    return read_main(std::move(main), fs::path(path).parent_path(), options);
}

RawDeck read_buffer(std::string text, const std::string& display_name, const std::string& base_directory,
                    const ReaderOptions& options) {
    SourceFile main;
    main.path = display_name;
    main.display_name = display_name;
    main.text = std::move(text);
    return read_main(std::move(main), base_directory, options);
}

}  // namespace sphdeck::grammar::radioss
