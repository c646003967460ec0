// Format rules for *INCLUDE trees (lsdyna-format.md §7, §13).
#include <doctest/doctest.h>

#include "grammar/dyna/reader.hpp"
#include "test_support.hpp"

namespace test_reader_includes_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::dyna::read_file;
using test::count_code;
using test::TempDir;

TEST_CASE("includes: blocks of an included file appear where the *INCLUDE stands") {
    TempDir dir;
    dir.write("part.k", "*NODE\n       2\n");
    auto main = dir.write("main.k", "*NODE\n       1\n*INCLUDE\npart.k\n*NODE\n       3\n");
    auto deck = read_file(main);
    REQUIRE(deck.blocks.size() == 4);
    CHECK(deck.blocks[1].keyword == "*INCLUDE");
    CHECK(deck.blocks[2].keyword == "*NODE");
    CHECK(deck.sources.file(deck.blocks[2].span.file).display_name.find("part.k") != std::string::npos);
    CHECK(deck.sources.file(1).parent == 0);
    CHECK(deck.sources.file(1).include_line == 4);
    CHECK(deck.text(deck.lines[deck.blocks[3].first_line]) == "       3");
    CHECK(deck.stats.files == 2);
    CHECK(deck.diagnostics.empty());
}

TEST_CASE("includes: search order and *INCLUDE_PATH") {
    TempDir dir;
    dir.write("sub/child.k", "*INCLUDE\nsibling.k\n");
    dir.write("sub/sibling.k", "*NODE\n       5\n");
    dir.write("lib/shared.k", "*NODE\n       6\n");
    dir.write("rel/relative.k", "*NODE\n       7\n");
    auto main = dir.write("main.k", "*INCLUDE_PATH\n" + (dir.path() / "lib").string() +
                                        "\n*INCLUDE_PATH_RELATIVE\nrel\n*INCLUDE\nsub/child.k\nshared.k\nrelative.k\n");
    auto deck = read_file(main);
    CHECK(deck.diagnostics.empty());
    CHECK(deck.stats.files == 5);
    CHECK(deck.lines.size() >= 3);
}

TEST_CASE("includes: a long file name continues over lines ending in ' +'") {
    TempDir dir;
    dir.write("a_rather_long_folder_name/and_a_long_file_name.k", "*NODE\n       9\n");
    auto main = dir.write("main.k", "*INCLUDE\na_rather_long_folder_name/ +\nand_a_long_file_name.k\n");
    auto deck = read_file(main);
    CHECK(deck.diagnostics.empty());
    CHECK(deck.stats.files == 2);
}

TEST_CASE("includes: a missing file is DK010 at the file name, with the folders tried") {
    TempDir dir;
    auto main = dir.write("main.k", "*INCLUDE\n  nowhere.k\n");
    auto deck = read_file(main);
    REQUIRE(count_code(deck.diagnostics, "DK010") == 1);
    const auto& d = deck.diagnostics[0];
    CHECK(d.span.line == 2);
    CHECK(d.span.column == 3);
    CHECK(d.span.end_column == 12);
    REQUIRE(d.notes.size() == 3);  // two folders tried, and the references left unchecked
    CHECK(d.notes[2].message.find("not checked while it is missing") != std::string::npos);
}

TEST_CASE("includes: cycles are DK011, direct and indirect") {
    TempDir dir;
    auto self = dir.write("self.k", "*INCLUDE\nself.k\n");
    CHECK(count_code(read_file(self).diagnostics, "DK011") == 1);
    dir.write("b.k", "*INCLUDE\na.k\n");
    auto a = dir.write("a.k", "*INCLUDE\nb.k\n");
    auto deck = read_file(a);
    CHECK(count_code(deck.diagnostics, "DK011") == 1);
    CHECK(deck.stats.files == 2);
}

TEST_CASE("includes: 100-deep nesting is read; deeper than the limit is reported") {
    TempDir dir;
    for (int i = 0; i < 100; ++i)
        dir.write("level" + std::to_string(i) + ".k", "*INCLUDE\nlevel" + std::to_string(i + 1) + ".k\n");
    dir.write("level100.k", "*NODE\n       1\n");
    auto deck = read_file((dir.path() / "level0.k").string());
    CHECK(deck.diagnostics.empty());
    CHECK(deck.stats.files == 101);
    CHECK(deck.lines.size() == 100 + 1);

    grammar::dyna::ReaderOptions shallow;
    shallow.max_include_depth = 10;
    auto limited = read_file((dir.path() / "level0.k").string(), shallow);
    CHECK(count_code(limited.diagnostics, "DK011") == 1);
}

TEST_CASE("includes: files read and bytes read are bounded, so a diamond of includes stays small") {
    // Each level includes the next one twice: 2^31 - 1 files if nothing stopped it.
    TempDir dir;
    for (int i = 0; i < 30; ++i) {
        const std::string next = "d" + std::to_string(i + 1) + ".k";
        dir.write("d" + std::to_string(i) + ".k", "*INCLUDE\n" + next + "\n" + next + "\n");
    }
    dir.write("d30.k", "*NODE\n       1\n");
    grammar::dyna::ReaderOptions few;
    few.max_include_files = 50;
    auto limited = read_file((dir.path() / "d0.k").string(), few);
    CHECK(limited.stats.files == 51);  // the main file and 50 includes
    CHECK(count_code(limited.diagnostics, "DK011") >= 1);
    REQUIRE(!limited.diagnostics.empty());
    CHECK(limited.diagnostics.front().message.find("already read 50 include files") != std::string::npos);
    CHECK(limited.diagnostics.front().span.line >= 2);  // at a file name of an *INCLUDE

    dir.write("big.k", "*NODE\n" + std::string(1000, '$') + "\n");
    const std::string main = dir.write("main.k", "*INCLUDE\nbig.k\n");
    grammar::dyna::ReaderOptions small;
    small.max_total_bytes = 500;
    auto refused = read_file(main, small);
    CHECK(refused.stats.files == 1);
    REQUIRE(count_code(refused.diagnostics, "DK011") == 1);
    CHECK(refused.diagnostics.front().message.find("1007 bytes would take the deck past 500") != std::string::npos);
}

TEST_CASE("includes: the format passes down and a suffix on *INCLUDE changes it") {
    TempDir dir;
    dir.write("long.k", "*NODE\n*KEYWORD long=y\n");
    dir.write("plain.k", "*NODE\n");
    auto main = dir.write("main.k", "*KEYWORD i10=y\n*INCLUDE +\nlong.k\n*INCLUDE\nplain.k\n");
    auto deck = read_file(main);
    REQUIRE(deck.blocks.size() == 6);
    CHECK(deck.blocks[2].format == grammar::CardFormat::Long);  // *NODE of long.k
    CHECK(deck.blocks[5].format == grammar::CardFormat::I10);   // *NODE of plain.k inherits i10
    CHECK(count_code(deck.diagnostics, "DK019") == 1);          // long=y inside an include is ignored
}

TEST_CASE("includes: a file name over 236 characters is DK025") {
    TempDir dir;
    std::string name(240, 'x');
    std::string text = "*INCLUDE\n";
    for (std::size_t i = 0; i < name.size(); i += 60) text += name.substr(i, 60) + " +\n";
    text += "end.k\n";
    auto deck = read_file(dir.write("main.k", text));
    CHECK(count_code(deck.diagnostics, "DK025") == 1);
    CHECK(count_code(deck.diagnostics, "DK010") == 1);
}

TEST_CASE("includes: an unreadable main file throws, an include path that is a folder is not found") {
    CHECK_THROWS(read_file("/nonexistent/deck.k"));
    TempDir dir;
    std::filesystem::create_directories(dir.path() / "folder.k");
    auto deck = read_file(dir.write("main.k", "*INCLUDE\nfolder.k\n"));
    CHECK(count_code(deck.diagnostics, "DK010") == 1);
}
}  // namespace test_reader_includes_cpp
