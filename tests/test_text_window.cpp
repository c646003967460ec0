// Reading a mapped deck through a reused buffer (text/text_window.hpp, issue 40): the window hands out the
// file's bytes exactly, and the passes that read through it (the line split, the bulk blocks' decoding, the
// formatter's quick test) find on a mapped file what they find on the same text held in memory: the same
// lines, the same findings, the same numbers. Files of a few MB (mapped from 1 MiB on), with lines that cross
// every window edge, longer than the window, CRLF ends and a last line without a newline.
#include <doctest/doctest.h>

#include <fmt/format.h>
#include <random>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "edit/format_deck.hpp"
#include "engine/check.hpp"
#include "grammar/line_chunks.hpp"
#include "text/source_text.hpp"
#include "text/text_window.hpp"
#include "test_support.hpp"

namespace test_text_window_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// Sets the OpenMP threads for one scope.
class Threads {
public:
    explicit Threads(int n) {
#ifdef _OPENMP
        saved_ = omp_get_max_threads();
        omp_set_num_threads(n);
#else
        (void)n;
#endif
    }
    ~Threads() {
#ifdef _OPENMP
        omp_set_num_threads(saved_);
#endif
    }
    Threads(const Threads&) = delete;
    Threads& operator=(const Threads&) = delete;

private:
    int saved_ = 1;
};

std::string node_line(std::size_t i) {
    return fmt::format("{:>8}{:>16.8e}{:>16.8e}{:>16.8e}{:>8}{:>8}", i + 1, 0.001 * static_cast<double>(i), -0.5, 2.0,
                       0, 0);
}

// A *NODE and *ELEMENT_SPH deck of about 5 MB (read in chunks: grammar::chunked_reading_min_bytes): mostly
// laid-out lines, with free-format ones, a letter O for a zero, comments, ids left in
// their fields, a line longer than the window, CRLF ends from `crlf_from` on, no newline after *END.
std::string big_deck(std::size_t nodes, std::size_t crlf_from) {
    std::mt19937 random(40);
    std::string text = "*KEYWORD\n*PART\nwater\n         1         1         1\n*SECTION_SPH\n         1\n*NODE\n";
    text.reserve(nodes * 160);
    for (std::size_t i = 0; i < nodes; ++i) {
        const std::string eol = i >= crlf_from ? "\r\n" : "\n";
        const unsigned pick = random() % 1000;
        if (pick == 0)
            text += fmt::format("{},{},{},{}", i + 1, 0.5, 0.25, 1.0) + eol;  // free format
        else if (pick == 1)
            text += fmt::format("{:>8}{:>16}{:>16.8e}{:>16.8e}", i + 1, "1.O", -0.5, 2.0) + eol;  // a letter O
        else if (pick == 2)
            text += "$ a comment" + eol + node_line(i) + eol;
        else if (pick == 3)  // the id left in its field: laid out again
            text += fmt::format("{:<8}{:>16.8e}{:>16.8e}{:>16.8e}", i + 1, 0.5, -0.5, 2.0) + eol;
        else
            text += node_line(i) + eol;
        if (i == nodes / 3) text += "$" + std::string(300000, 'c') + eol;  // longer than the window
    }
    text += "*ELEMENT_SPH\n";
    for (std::size_t i = 0; i < nodes; ++i) text += fmt::format("{:>8}{:>8}{:>16.8e}\n", i + 1, 1, 1.0e-3);
    return text + "*END";
}

}  // namespace

TEST_CASE("text window: the bytes of a mapped file and of owned text, wherever they are asked from") {
    std::mt19937 random(41);
    std::string bytes(std::size_t{3} << 20, ' ');
    for (char& c : bytes) c = static_cast<char>('a' + random() % 26);
    const test::TempDir folder;
    const text::SourceText mapped = text::SourceText::read(folder.write("bytes.txt", bytes));
    REQUIRE(mapped.mapped());  // 3 MB: mapped
    const text::SourceText owned(bytes);
    for (const text::SourceText* source : {&mapped, &owned}) {
        text::TextWindow window(*source, 4096);
        std::size_t last = 0;
        for (int k = 0; k < 4000; ++k) {
            // Short steps forward within what the window holds (the passes' use, answered without reading)
            // half the time, jumps anywhere and to the end otherwise.
            const std::size_t begin = k % 2 == 0    ? std::min(bytes.size(), last + random() % 300)
                                      : k % 97 == 1 ? bytes.size() - random() % 10
                                                    : random() % bytes.size();
            last = begin;
            const std::size_t least = random() % 3 == 0 ? random() % 20000 : random() % 200;
            const std::string_view got = window.from(begin, least, random() % 2 ? 10 : ~std::size_t{0});
            INFO("from ", begin, " at least ", least);
            REQUIRE(got.size() >= std::min(least, bytes.size() - begin));
            CHECK(got == std::string_view(bytes).substr(begin, got.size()));
            CHECK(window.at_end(got) == (begin + got.size() == bytes.size()));
        }
    }
}

TEST_CASE("text window: a mapped file splits into the lines its text in memory does") {
    const std::string text = big_deck(45000, 30000);
    const test::TempDir folder;
    const text::SourceText mapped = text::SourceText::read(folder.write("split.k", text));
    REQUIRE(mapped.mapped());
    const text::SourceText owned(text);
    for (const std::size_t chunk : {std::size_t{4099}, std::size_t{65536}, std::size_t{1} << 20, text.size()})
        for (const int threads : {1, 2}) {
            const Threads team(threads);
            for (const grammar::LineSyntax syntax : {grammar::LineSyntax::Dyna, grammar::LineSyntax::Radioss}) {
                INFO("chunks of ", chunk, " bytes on ", threads, " threads");
                const grammar::SplitLines a = grammar::split_lines(mapped, 0, syntax, chunk);
                const grammar::SplitLines b = grammar::split_lines(owned, 0, syntax, chunk);
                REQUIRE(a.chunks.size() == b.chunks.size());
                CHECK(a.lines == b.lines);
                CHECK(a.comment_holds_marker == b.comment_holds_marker);
                for (std::size_t c = 0; c < a.chunks.size(); ++c) {
                    CHECK(a.chunks[c].starts == b.chunks[c].starts);
                    CHECK(a.chunks[c].special == b.chunks[c].special);
                }
            }
        }
}

TEST_CASE("text window: a mapped deck checks and formats as its text in memory does") {
    const std::string text = big_deck(45000, 30000);
    const test::TempDir folder;
    const std::string path = folder.write("check.k", text);
    for (const int threads : {1, 2}) {
        const Threads team(threads);
        const engine::CheckResult a = engine::check_file(path);
        const engine::CheckResult b = engine::check_buffer(text, path);
        REQUIRE(a.deck.sources.file(0).text.mapped());
        CHECK(a.diagnostics.size() >= 30);  // the letters O, found
        CHECK(test::finding_lines(a.diagnostics) == test::finding_lines(b.diagnostics));
        CHECK(a.model.nodes.x == b.model.nodes.x);
        CHECK(a.model.nodes.y == b.model.nodes.y);
        CHECK(a.model.particles.mass == b.model.particles.mass);
        CHECK(a.model.particles.size() == 45000);
        const edit::FormatResult fa = edit::format_deck(a.deck, a.diagnostics, {0}, {});
        const edit::FormatResult fb = edit::format_deck(b.deck, b.diagnostics, {0}, {});
        CHECK(fa.changes == fb.changes);
        CHECK(fa.kept == fb.kept);
        REQUIRE(fa.edits.size() == fb.edits.size());
        CHECK(fa.edits.size() >= 30);  // the ids left in their fields
        for (std::size_t i = 0; i < fa.edits.size(); ++i) CHECK(fa.edits[i].replacement == fb.edits[i].replacement);
    }
}

}  // namespace test_text_window_cpp
