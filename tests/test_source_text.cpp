// Source texts held as a mapping of the file (big decks) or as an owned buffer (editors, fuzzers,
// small files): the readers and the checks see the same bytes and give the same findings.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include "engine/check.hpp"
#include "text/source_text.hpp"
#include "test_support.hpp"

namespace test_source_text_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {
// A deck past the mapping threshold (1 MiB) with a few defects in its big blocks.
std::string big_deck(int nodes) {
    std::string text = "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20         3\n*NODE\n";
    for (int i = 1; i <= nodes; ++i)
        text += i == 17 ? "      17     1.0x     0.0     0.0\n"  // DK003
                        : fmt::format("{:8d}{:16.8e}{:16.8e}{:16.8e}\n", i, 1e-3 * i, 2e-3 * (i % 7), -1e-3 * (i % 5));
    text += "*ELEMENT_SPH\n";
    for (int i = 1; i <= nodes; ++i) text += fmt::format("{:8d}{:8d}{:16.8e}\n", i == nodes ? nodes + 5 : i, 1, 1e-6);
    return text + "*END\n";
}
}  // namespace

TEST_CASE("source text: a mapped file reads as its bytes, before and after its pages are released") {
    test::TempDir dir;
    std::string content(std::size_t{9} << 20, 'a');
    content.replace((std::size_t{8} << 20) - 3, 8, "$ SPHDECK");  // straddles the 8 MiB slice of contains()
    const std::string path = dir.write("big.k", content);
    const grammar::SourceText text = grammar::SourceText::read(path);
    CHECK(text.mapped());
    REQUIRE(text.size() == content.size());
    CHECK(text.view() == content);
    CHECK(text.contains("$ SPHDECK"));
    CHECK_FALSE(text.contains("$ NOTHERE"));
    text.release(0, text.size());
    CHECK(text.view() == content);  // released pages come back unchanged
    const grammar::SourceText copy = text;
    CHECK(copy.data() == text.data());  // copies share the mapping

    const grammar::SourceText small = grammar::SourceText::read(dir.write("small.k", "*KEYWORD\n"));
    CHECK_FALSE(small.mapped());  // small files are read whole
    CHECK(small.view() == "*KEYWORD\n");
    CHECK(grammar::SourceText::read(path, 0).mapped());
}

TEST_CASE("source text: a mapped deck gives the findings of the same text in memory") {
    test::TempDir dir;
    const std::string text = big_deck(30000);  // ~2 MB: mapped, and decoded in parallel blocks
    REQUIRE(text.size() > (std::size_t{1} << 20));
    const std::string path = dir.write("big.k", text);
    const engine::CheckResult on_disk = engine::check_file(path);
    const engine::CheckResult in_memory = engine::check_buffer(text, path);
    CHECK(on_disk.deck.sources.file(0).text.mapped());
    CHECK_FALSE(in_memory.deck.sources.file(0).text.mapped());
    CHECK(test::count_code(on_disk.diagnostics, "DK003") > 0);  // the glued "1.0x     0.0" of node 17
    CHECK(test::finding_lines(on_disk.diagnostics) == test::finding_lines(in_memory.diagnostics));
    CHECK(on_disk.model.nodes.x == in_memory.model.nodes.x);
    CHECK(on_disk.model.particles.node == in_memory.model.particles.node);
    CHECK(on_disk.deck.sources.line_text(0, 21) == in_memory.deck.sources.line_text(0, 21));
}
}  // namespace test_source_text_cpp
