#include "grammar/dyna/reader.hpp"

#include "grammar/dyna/parameter_cards.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "grammar/dyna/deck_reader.hpp"
#include "grammar/dyna/include_text.hpp"
#include "grammar/dyna/line_grammar.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/line_chunks.hpp"
#include "text/text_file.hpp"

namespace sphdeck::grammar::dyna {
namespace {

namespace pegtl = tao::pegtl;

template <typename Rule>
struct line_action : pegtl::nothing<Rule> {};

template <>
struct line_action<rules::keyword_name> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.parts.name = in.string_view();
    }
};
template <>
struct line_action<rules::suffix_char> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.parts.suffix = *in.begin();
    }
};
template <>
struct line_action<rules::keyword_arguments> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.parts.arguments = in.string_view();
    }
};
template <>
struct line_action<rules::comment_line> {
    template <typename Input>
    static void apply(const Input&, DeckReader& r) {
        r.on_comment();
    }
};
template <>
struct line_action<rules::keyword_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        // Copy first: an *INCLUDE closed by this keyword line parses another file with `r`.
        KeywordLineParts parts = r.parts;
        r.parts = {};
        r.on_keyword(in.begin(), in.end(), parts);
    }
};
template <>
struct line_action<rules::pgp_begin_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_pgp_begin(in.begin(), in.end());
    }
};
template <>
struct line_action<rules::pgp_end_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_pgp_end(in.begin(), in.end());
    }
};
template <>
struct line_action<rules::empty_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_data(in.begin(), in.begin());
    }
};
template <>
struct line_action<rules::data_line> {
    template <typename Input>
    static void apply(const Input& in, DeckReader& r) {
        r.on_data(in.begin(), in.end());
    }
};

RawDeck read_main(SourceFile main, const std::filesystem::path& directory, const ReaderOptions& options) {
    RawDeck deck;
    // One CardLine per line at most: reserving once keeps the big-deck path free of regrowth.
    // memchr, not std::count: glibc's vectorised memchr costs a tenth of the instructions per byte.
    // Counted in slices, each released behind the count: a mapped deck scanned whole would be
    // resident whole, which was the peak of memory of a check without geometry.
    // A file read in chunks counts its lines on the threads (DeckReader::read_chunked reserves then).
    std::size_t newlines = 0;
    constexpr std::size_t slice = std::size_t{1} << 20;
    const bool chunked = line_chunk_bytes(main.text.size()) > 0;
    const std::size_t size = chunked ? 0 : main.text.size();
    for (std::size_t at = 0; at < size; at += slice) {
        const char* const end = main.text.data() + std::min(size, at + slice);
        for (const char* p = main.text.data() + at;
             (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)))); ++p)
            ++newlines;
        main.text.release(at, at + slice);
    }
    if (!chunked) deck.lines.reserve(newlines + 1);
    FileId id = deck.sources.add(std::move(main));
    DeckReader reader(deck, options);
    reader.set_main_directory(directory);
    reader.read(id, CardFormat::Standard);
    group_redefinitions(deck);
    return deck;
}

}  // namespace

void DeckReader::read(FileId file, CardFormat inherited_format, const FileCache::File* cached) {
    const SourceFile& source = deck_.sources.file(file);
    deck_.parameters.add_file(file, source.parent);
    ++deck_.stats.files;
    deck_.stats.bytes += source.text.size();
    FileCache::Lookup shared;
    if (cached && options_.cache) shared = options_.cache->reading(*cached, inherited_format);
    if (shared.reading) return lay_in(file, *shared.reading);
    const std::size_t first_block = deck_.blocks.size(), first_line = deck_.lines.size(),
                      first_diagnostic = deck_.diagnostics.size();

    OpenFile open;
    open.id = file;
    open.format = inherited_format;
    open.base = source.text.data();
    open.text = &source.text;
    stack_.push_back(open);
    if (const std::size_t chunk_bytes = line_chunk_bytes(source.text.size())) {
        deck_.sources.file(file).comment_holds_marker = read_chunked(source.text, chunk_bytes);
    } else {
        pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(
            source.text.data(), source.text.data() + source.text.size(), source.path.c_str());
        pegtl::parse<rules::file, line_action>(in, *this);
    }
    close_block();
    report_dropped_blocks(first_diagnostic);
    const std::uint32_t physical_lines = current().line;
    deck_.stats.lines += physical_lines;
    stack_.pop_back();
    if (shared.claim) shared.claim->fulfil(reading_of(file, first_block, first_line, first_diagnostic, physical_lines));
    source.text.release(0, source.text.size());  // read again, block by block, when decoded
}

// One line read with the line grammar, as the file loop reads it there (`begin` starts a line).
void DeckReader::grammar_line(const char* begin, const char* text_end) {
    pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(begin, text_end, "");
    pegtl::parse<rules::line, line_action>(in, *this);
}

RawDeck read_file(const std::string& path, const ReaderOptions& options) {
    SourceFile main;
    main.path = path;
    main.display_name = path;
    main.text = read_source_text(path, options.overlay);
    return read_main(std::move(main), std::filesystem::path(path).parent_path(), options);
}

RawDeck read_buffer(std::string text, const std::string& display_name, const std::string& base_directory,
                    const ReaderOptions& options) {
    SourceFile main;
    main.path = display_name;
    main.display_name = display_name;
    main.text = std::move(text);
    return read_main(std::move(main), base_directory, options);
}

SourceText read_include_text(const std::string& path, const FileOverlay* overlay, FileCache* cache,
                             std::shared_ptr<const FileCache::File>* cached) {
    SourceText text;
    if (cache && !(overlay && overlay->find(path))) {
        std::shared_ptr<const FileCache::File> file = cache->file(path);
        text = file->text;
        if (cached) *cached = std::move(file);
    } else {
        text = read_source_text(path, overlay);
    }
    // An empty include is fine; a binary one (a d3plot named by mistake) is not parsed as cards.
    if (auto why = text::binary_or_empty(text.substr(0, 64 * 1024)); why && !text.empty())
        throw std::runtime_error("'" + path + "' is not a keyword deck: " + *why);
    return text;
}

}  // namespace sphdeck::grammar::dyna
