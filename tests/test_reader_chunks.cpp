// The chunked line reader (issue 40, grammar/line_chunks.hpp) reads every deck as the line-by-line
// reader does: the same blocks, card lines, spans, findings, parameters and statistics, whatever the chunk
// size (edges inside blocks, inside long and free lines, between '\r' and '\n', on a last line without a
// newline) and on 1, 2 and 16 threads. Checked on generated decks of awkward lines, cut at every small
// chunk size, and on every deck of decks/ (their includes too) cut at random sizes.
#include <doctest/doctest.h>

#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "grammar/line_chunks.hpp"
#include "grammar/read_deck.hpp"
#include "text/source_map.hpp"

namespace test_reader_chunks_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace fs = std::filesystem;

namespace {

// Under the sanitizers (some ten times slower) every fourth deck of decks/ is cut, the others are not read.
#ifdef SPHDECK_SANITIZED
constexpr std::size_t chunked_deck_stride = 4;
#else
constexpr std::size_t chunked_deck_stride = 1;
#endif

std::string span_text(const grammar::Span& s) {
    return std::to_string(s.file) + ":" + std::to_string(s.line) + ":" + std::to_string(s.column) + "-" +
           std::to_string(s.end_column);
}

std::string diagnostic_text(const diag::Diagnostic& d) {
    std::string out =
        d.code + " " + std::string(diag::to_string(d.severity)) + " " + span_text(d.span) + " " + d.message;
    for (const diag::Note& n : d.notes) out += " | note " + span_text(n.span) + " " + n.message;
    for (const diag::Fix& f : d.fixes) {
        out += " | fix " + f.description + (f.safe ? " safe" : " unsafe");
        for (const diag::TextEdit& e : f.edits) out += " [" + span_text(e.span) + " '" + e.replacement + "']";
    }
    return out;
}

std::string block_text(const grammar::Block& b) {
    return b.keyword + " '" + b.arguments + "' " + std::string(grammar::to_string(b.format)) + " suffix " +
           std::to_string(static_cast<int>(b.suffix)) + " " + span_text(b.span) + " lines " +
           std::to_string(b.first_line) + "+" + std::to_string(b.line_count) + " scope " + std::to_string(b.scope) +
           " epoch " + std::to_string(b.parameter_epoch);
}

// Everything a reading hands on, one line per item: two readings are the same when their texts are.
std::string reading_text(const grammar::RawDeck& deck) {
    std::ostringstream out;
    for (grammar::FileId id = 0; id < deck.sources.size(); ++id) {
        const grammar::SourceFile& f = deck.sources.file(id);
        out << "file " << f.path << " | " << f.display_name << " parent " << f.parent << " line " << f.include_line
            << " depth " << f.depth << " bytes " << f.text.size() << "\n";
    }
    for (const grammar::Block& b : deck.blocks) out << "block " << block_text(b) << "\n";
    for (const grammar::CardLine& l : deck.lines) out << "line " << l.file << ":" << l.line << "@" << l.offset << "\n";
    for (const diag::Diagnostic& d : deck.diagnostics) out << "finding " << diagnostic_text(d) << "\n";
    for (const grammar::Parameter& p : deck.parameters.definitions())
        out << "parameter " << p.name << " " << static_cast<int>(p.type) << " " << p.number << " '" << p.text << "' "
            << p.scope << " " << span_text(p.span) << "\n";
    const grammar::KeywordArguments& k = deck.keyword_arguments;
    out << "*KEYWORD " << k.present << " " << k.memory << " " << k.memory2 << " " << k.ncpu << " " << k.long_format
        << k.i10_format << " " << span_text(k.span) << "\n";
    const grammar::ReadStats& s = deck.stats;
    out << "stats " << s.files << " " << s.bytes << " " << s.lines << " " << s.keywords << " " << s.cards << "\n";
    return out.str();
}

// The first line where two readings differ (empty when they are the same).
std::string first_difference(const std::string& expected, const std::string& found) {
    std::istringstream a(expected), b(found);
    std::string la, lb;
    for (std::size_t n = 1;; ++n) {
        const bool more_a = static_cast<bool>(std::getline(a, la)), more_b = static_cast<bool>(std::getline(b, lb));
        if (!more_a && !more_b) return {};
        if (la != lb || more_a != more_b)
            return "item " + std::to_string(n) + ": expected '" + la + "', found '" + lb + "'";
    }
}

// The reading of `read()` with files cut every `chunk_bytes` bytes, or the message it threw.
template <typename Read>
std::string chunk_reading(Read&& read, std::size_t chunk_bytes, int threads) {
    grammar::set_line_chunk_bytes(chunk_bytes);
#ifdef _OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
    std::string out;
    try {
        out = reading_text(read());
    } catch (const std::exception& e) {
        out = std::string("threw: ") + e.what();
    }
#ifdef _OPENMP
    omp_set_num_threads(before);
#endif
    grammar::set_line_chunk_bytes(0);
    return out;
}

// Lines that each mean something else to the LS-DYNA reader (keywords indented or not, suffixes, comments,
// *COMMENT and *END, PGP blocks, parameters, free and long lines, blank lines...).
const std::vector<std::string> dyna_lines = {"*KEYWORD",
                                             "*KEYWORD LONG=Y",
                                             "*keyword i10=y",
                                             "*NODE",
                                             "*NODE +",
                                             "*NODE%",
                                             "*NODE -1",
                                             "*node-",
                                             "  *PART",
                                             "\t*MAT_NULL",
                                             "*",
                                             "  *",
                                             "  **(1/3)",
                                             "*PARAMETER_EXPRESSION",
                                             "R X     1.0*2",
                                             "*PARAMETER",
                                             "R       a     1.0",
                                             "I       n        3",
                                             "*COMMENT",
                                             "*END",
                                             "*CONTROL_SPH",
                                             "$ comment",
                                             "$# nid x",
                                             "",
                                             "   ",
                                             "\t",
                                             "       1     0.0     1.0",
                                             "1,2.0,3.0",
                                             "-1.0,2.0",
                                             "-----BEGIN PGP MESSAGE-----",
                                             "xyz encrypted",
                                             "-----END PGP MESSAGE-----",
                                             "       2  1.0e+00 &a",
                                             "\t1\t2",
                                             "*ELEMENT_SPH",
                                             "       1       1  1.0e-06",
                                             "*TITLE",
                                             "a title, with a comma",
                                             "*INCLUDE",
                                             "no_such_include.k",
                                             "*SECTION_SPH",
                                             std::string(230, '7'),
                                             "*INCLUDE_PATH",
                                             "*DEFINE_CURVE_TITLE",
                                             "-"};

// The same for OpenRadioss (headers, comments, #include and #enddata, /END, blank lines...).
const std::vector<std::string> radioss_lines = {"#RADIOSS STARTER",
                                                "/BEGIN",
                                                "deck title",
                                                "      2024         0",
                                                "kg mm ms",
                                                "/NODE",
                                                "         1       0.0       0.0       0.0",
                                                "  /PART/1",
                                                "/PART/1",
                                                "part title",
                                                "# comment",
                                                "$ comment",
                                                "#include no_such.inc",
                                                "#enddata",
                                                "/END",
                                                "",
                                                "  ",
                                                "/",
                                                "//x",
                                                " /1/2",
                                                "#INCLUDE x",
                                                "/SPH/1",
                                                "/MAT/LAW6/2",
                                                "1,2,3",
                                                "\t/TH/PART/3",
                                                std::string(200, '1'),
                                                "/end"};

// A deck of `count` lines drawn from `lines`, with "\r\n" or "\n" ends, a byte order mark sometimes, and
// sometimes no newline after the last line.
std::string random_deck(std::mt19937& random, const std::vector<std::string>& lines, std::size_t count,
                        const std::string& first) {
    std::string text = random() % 8 == 0 ? "\xEF\xBB\xBF" : "";
    text += first + "\n";
    const bool crlf = random() % 2 == 0;
    for (std::size_t i = 0; i < count; ++i) {
        text += lines[random() % lines.size()];
        if (i + 1 < count || random() % 3 != 0) text += crlf || random() % 5 == 0 ? "\r\n" : "\n";
    }
    return text;
}

void check_generated_decks(grammar::DeckFormat format, const std::vector<std::string>& lines, const char* name,
                           const std::string& first, std::uint32_t seed) {
    std::mt19937 random(seed);
    const int thread_counts[] = {1, 2, 16};
    for (int deck = 0; deck < 12; ++deck) {
        const std::string text = random_deck(random, lines, 24 + random() % 24, first);
        const auto read = [&] { return grammar::read_deck_buffer(text, name, ".", {}, format); };
        const std::string expected = chunk_reading(read, grammar::read_line_by_line, 1);
        // Every small size puts an edge on every byte of the first lines; a few larger ones cut lines whole.
        std::vector<std::size_t> sizes;
        for (std::size_t s = 1; s <= 8; ++s) sizes.push_back(s);
        for (int k = 0; k < 4; ++k) sizes.push_back(1 + random() % text.size());
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            const int threads = thread_counts[k % 3];
            const std::string found = chunk_reading(read, sizes[k], threads);
            INFO("deck ", deck, " cut every ", sizes[k], " bytes on ", threads, " threads:\n", text);
            CHECK(first_difference(expected, found) == "");
        }
    }
}

}  // namespace

TEST_CASE("reader chunks: the lines of a file are cut at line starts, each line once") {
    const std::string text = "ab\n\ncd\r\nlong line\nlast";
    const grammar::SourceText source(text);
    for (std::size_t size = 1; size <= text.size() + 1; ++size) {
        const grammar::SplitLines split = grammar::split_lines(source, 0, grammar::LineSyntax::Dyna, size);
        std::vector<std::uint32_t> starts;
        for (const grammar::LineChunk& chunk : split.chunks)
            starts.insert(starts.end(), chunk.starts.begin(), chunk.starts.end());
        CHECK(starts == std::vector<std::uint32_t>{0, 3, 4, 8, 18});
        CHECK(split.lines == 5);
    }
}

TEST_CASE("reader chunks: only lines that can be nothing but data skip the grammar") {
    const std::string text = "$c\n  *K\n-----END PGP\n 1 2\n\n-1,2\n/H\n #x\n";
    const grammar::SourceText source(text);
    const auto special = [&](grammar::LineSyntax syntax) {
        const grammar::SplitLines split = grammar::split_lines(source, 0, syntax, text.size());
        REQUIRE(split.chunks.size() == 1);
        return split.chunks[0].special;
    };
    CHECK(special(grammar::LineSyntax::Dyna) == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(special(grammar::LineSyntax::Radioss) == std::vector<std::uint32_t>{0, 6});
}

TEST_CASE("reader chunks: a keyword or header after any run of blanks is seen, and only then") {
    // Runs of 0 to 20 blanks (spaces and tabs mixed), then a keyword's '*' or a header's '/', a number, or
    // nothing: only the first two are lines for the grammar.
    std::string text;
    std::vector<std::uint32_t> dyna, radioss;
    std::uint32_t line = 0;
    for (int blanks = 0; blanks <= 20; ++blanks) {
        std::string run;
        for (int k = 0; k < blanks; ++k) run += (k * 7 + blanks) % 5 == 0 ? '\t' : ' ';
        for (const char* rest : {"*K", "/H", "1 2", "", "x*", "\t*"}) {
            text += run + rest + "\n";
            const std::string after = rest;
            if (after == "*K" || after == "\t*") dyna.push_back(line);
            if (after == "/H") radioss.push_back(line);
            ++line;
        }
    }
    const grammar::SourceText source(text);
    const auto special = [&](grammar::LineSyntax syntax) {
        const grammar::SplitLines split = grammar::split_lines(source, 0, syntax, text.size());
        REQUIRE(split.chunks.size() == 1);
        return split.chunks[0].special;
    };
    CHECK(special(grammar::LineSyntax::Dyna) == dyna);
    CHECK(special(grammar::LineSyntax::Radioss) == radioss);
}

TEST_CASE("reader chunks: a comment line holding the suppressions' marker is seen at every chunk size") {
    // The suppressions read a directive from a line that starts with '$' or '#' and holds the marker
    // (lint/suppressions.cpp), the lines cut at '\n' from byte 0 on: the split must say yes whenever such a
    // line exists. Random texts of the pieces that matter, every chunk size, from byte 0 and after a BOM.
    const std::vector<std::string> pieces = {"$",    "#",  "sphdeck", "sphdec",        "k", " ", "\n",
                                             "\r\n", "*K", "1",       "$ sphdeck: all"};
    std::mt19937 random(40);
    const auto holds = [](const std::string& text, std::size_t first) {
        for (std::size_t at = first; at < text.size();) {
            std::size_t end = text.find('\n', at);
            if (end == std::string::npos) end = text.size();
            const std::string_view line(text.data() + at, end - at);
            if ((line.starts_with('$') || line.starts_with('#')) && line.find(text::directive_marker) != line.npos)
                return true;
            at = end + 1;
        }
        return false;
    };
    int with = 0, without = 0;
    for (int round = 0; round < 400; ++round) {
        std::string text = round % 5 == 0 ? "\xEF\xBB\xBF" : "";
        const std::size_t first = text.size();
        const int count = 1 + static_cast<int>(random() % 14);
        for (int i = 0; i < count; ++i) text += pieces[random() % pieces.size()];
        const bool expected = holds(text, first);
        (expected ? with : without) += 1;
        const grammar::SourceText source(text);
        for (const grammar::LineSyntax syntax : {grammar::LineSyntax::Dyna, grammar::LineSyntax::Radioss})
            for (std::size_t size = 1; size <= text.size() + 1; ++size) {
                INFO("text '", text, "' cut every ", size, " bytes");
                CHECK(grammar::split_lines(source, first, syntax, size).comment_holds_marker == expected);
            }
    }
    CHECK(with > 40);  // both answers are tried
    CHECK(without > 40);
}

TEST_CASE("reader chunks: small files are read line by line unless asked") {
    grammar::set_line_chunk_bytes(0);
    CHECK(grammar::line_chunk_bytes(1000) == 0);
    CHECK(grammar::line_chunk_bytes(grammar::chunked_reading_min_bytes) == grammar::default_line_chunk_bytes);
    grammar::set_line_chunk_bytes(7);
    CHECK(grammar::line_chunk_bytes(1000) == 7);
    grammar::set_line_chunk_bytes(grammar::read_line_by_line);
    CHECK(grammar::line_chunk_bytes(grammar::chunked_reading_min_bytes) == 0);
    grammar::set_line_chunk_bytes(0);
}

TEST_CASE("reader chunks: generated LS-DYNA decks read the same at every chunk size and thread count") {
    check_generated_decks(grammar::DeckFormat::LsDyna, dyna_lines, "chunks.k", "*KEYWORD", 40);
}

TEST_CASE("reader chunks: generated OpenRadioss decks read the same at every chunk size and thread count") {
    check_generated_decks(grammar::DeckFormat::Radioss, radioss_lines, "chunks_0000.rad", "#RADIOSS STARTER", 41);
}

TEST_CASE("reader chunks: every deck of decks/ reads the same cut at random sizes on 1, 2 and 16 threads") {
    std::mt19937 random(400);
    const int thread_counts[] = {1, 2, 16};
    std::size_t decks = 0, seen = 0;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SPHDECK_SOURCE_DIR) / "decks")) {
        const std::string name = entry.path().filename().string();
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() ||
            !(extension == ".k" || extension == ".key" || extension == ".dyn" || name.ends_with("_0000.rad")))
            continue;
        if (seen++ % chunked_deck_stride != 0) continue;
        const std::string path = entry.path().string();
        const auto read = [&] { return grammar::read_deck(path); };
        const std::string expected = chunk_reading(read, grammar::read_line_by_line, 1);
        const std::size_t size = static_cast<std::size_t>(entry.file_size());
        const std::size_t chunk =
            std::max<std::size_t>(1, size / 4096) + random() % std::max<std::size_t>(64, size / 16);
        const int threads = thread_counts[decks % 3];
        INFO(path, " cut every ", chunk, " bytes on ", threads, " threads");
        CHECK(first_difference(expected, chunk_reading(read, chunk, threads)) == "");
        ++decks;
    }
    CHECK(decks * chunked_deck_stride > 250);
}
}  // namespace test_reader_chunks_cpp
