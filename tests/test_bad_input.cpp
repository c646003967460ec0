// Input that is not a deck (issue 13): an empty, binary or all-NUL file, a directory, text
// without a keyword. Every subcommand that reads a deck exits 2 with a plain message; an
// *INCLUDE or #include of such a thing is a located DK010 that says what it is.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_bad_input_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kGoodDeck = "*KEYWORD\n*CONTROL_TERMINATION\n$#  endtim\n       1.0\n*END\n";

// The subcommands that read a deck, each with the arguments it needs besides the deck.
const std::vector<std::string> kReaders = {"check", "dump", "smooth", "run --quiet --out out", "sol2sph"};

void require_refused(const test::TempDir& dir, const std::string& deck, const std::string& expected,
                     const std::string& expected_by_check = "") {
    for (const std::string& command : kReaders) {
        CAPTURE(command);
        test::Run r = test::run_sphdeck(dir, command + " '" + deck + "'");
        CHECK(r.exit_code == 2);
        CHECK(r.err.find(command == "check" && !expected_by_check.empty() ? expected_by_check : expected) !=
              std::string::npos);
        CHECK(r.err.find("bad_alloc") == std::string::npos);
        CHECK(r.err.find("not found") == std::string::npos);
        CHECK(r.err.find("cannot open") == std::string::npos);
    }
}

}  // namespace

TEST_CASE("bad input: an empty file is not a keyword deck") {
    test::TempDir dir;
    dir.write("empty.k", "");
    require_refused(dir, "empty.k", "'empty.k' is not a keyword deck: the file is empty");
}

TEST_CASE("bad input: a binary file and an all-NUL file are not keyword decks") {
    test::TempDir dir;
    std::string binary =
        "\x7f"
        "ELF\x02\x01\x01";
    binary += std::string(3, '\0') + "\xff\xfe*KEYWORD\n\x01\x02";
    dir.write("binary.k", binary);
    dir.write("zeros.k", std::string(100000, '\0'));
    require_refused(dir, "binary.k", "'binary.k' is not a keyword deck: it holds binary data (a NUL byte at offset 7)");
    require_refused(dir, "zeros.k", "'zeros.k' is not a keyword deck: it holds binary data (a NUL byte at offset 0)");
}

TEST_CASE("bad input: UTF-16 text is named as such") {
    test::TempDir dir;
    dir.write("utf16.k", std::string("\xff\xfe*\0K\0", 6));
    require_refused(dir, "utf16.k", "'utf16.k' is not a keyword deck: it is UTF-16 text");
}

TEST_CASE("bad input: text without a single keyword line is not a keyword deck") {
    test::TempDir dir;
    dir.write("notes.k", "these are my notes\n$ and a comment\n\n");
    dir.write("blank.rad", "#RADIOSS STARTER\n\n# only comments\n");
    require_refused(dir, "notes.k", "'notes.k' is not a keyword deck: no keyword line (*NODE, *PART...) in it");
    test::Run r = test::run_sphdeck(dir, "check blank.rad");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("'blank.rad' is not a keyword deck: no header line (/BEGIN, /NODE...) in it") !=
          std::string::npos);
}

TEST_CASE("bad input: a directory given as the deck") {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "model.k");
    // check searches a folder for decks (issue 33): one without any is refused as such.
    require_refused(dir, "model.k", "'model.k' is a directory, not a deck file",
                    "'model.k' is a directory with no deck files in it");
}

TEST_CASE("bad input: a missing deck still says it cannot be opened") {
    test::TempDir dir;
    test::Run r = test::run_sphdeck(dir, "check missing.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("cannot open 'missing.k'") != std::string::npos);
}

TEST_CASE("bad input: a directory or a binary file as an *INCLUDE target is DK010 at the include line") {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "parts");
    dir.write("mesh.bin", std::string("\0\0\0\x01", 4));
    dir.write("main.k", "*KEYWORD\n*INCLUDE\nparts\n*INCLUDE\nmesh.bin\n*END\n");
    test::Run r = test::run_sphdeck(dir, "check --format concise main.k");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("main.k:3:1: error: include file 'parts' cannot be read: '") != std::string::npos);
    CHECK(r.out.find("parts' is a directory, not a deck file [DK010]") != std::string::npos);
    CHECK(r.out.find("main.k:5:1: error: include file 'mesh.bin' cannot be read: '") != std::string::npos);
    CHECK(r.out.find("mesh.bin' is not a keyword deck: it holds binary data (a NUL byte at offset 0) [DK010]") !=
          std::string::npos);
    CHECK(r.out.find("not found") == std::string::npos);
}

TEST_CASE("bad input: an empty *INCLUDE file is fine") {
    test::TempDir dir;
    dir.write("empty.inc", "");
    dir.write("main.k", "*KEYWORD\n*INCLUDE\nempty.inc\n*CONTROL_TERMINATION\n       1.0\n*END\n");
    test::Run r = test::run_sphdeck(dir, "check --format concise main.k");
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("DK010") == std::string::npos);
}

TEST_CASE("bad input: a directory as an OpenRadioss #include target is DK010, not 'not found'") {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "nodes.inc");
    dir.write("m_0000.rad",
              "#RADIOSS STARTER\n/BEGIN\nrun\n      2026         0\n"
              "                  kg                  mm                  ms\n"
              "                  kg                  mm                  ms\n#include nodes.inc\n/END\n");
    test::Run r = test::run_sphdeck(dir, "check --format concise m_0000.rad");
    CHECK(r.out.find("include file 'nodes.inc' cannot be read: '") != std::string::npos);
    CHECK(r.out.find("nodes.inc' is a directory, not a deck file [DK010]") != std::string::npos);
    CHECK(r.out.find("not found") == std::string::npos);
}

TEST_CASE("bad input: a good deck is still read by every subcommand") {
    test::TempDir dir;
    dir.write("good.k", kGoodDeck);
    CHECK(test::run_sphdeck(dir, "check good.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "dump good.k").exit_code == 0);
}

TEST_CASE("bad input: when check reads no deck, its error is the last line, not a summary of nothing") {
    test::TempDir dir;
    dir.write("empty.k", "");
    dir.write("good.k", kGoodDeck);
    test::Run alone = test::run_sphdeck(dir, "check --format json empty.k");
    CHECK(alone.exit_code == 2);
    CHECK(alone.err == "sphdeck: error: 'empty.k' is not a keyword deck: the file is empty\n");
    test::Run with_good = test::run_sphdeck(dir, "check --format json empty.k good.k");
    CHECK(with_good.exit_code == 2);
    CHECK(with_good.err.find("checked 1 file(s)") != std::string::npos);  // the good deck was read
}

TEST_CASE("bad input: a Radioss deck of #include lines only is a deck; its missing include is DK010") {
    test::TempDir dir;
    dir.write("m_0000.rad", "#RADIOSS STARTER\n#include model.inc\n");
    test::Run r = test::run_sphdeck(dir, "check --format concise m_0000.rad");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("include file 'model.inc' not found [DK010]") != std::string::npos);
    CHECK(r.err.find("not a keyword deck") == std::string::npos);
}
}  // namespace test_bad_input_cpp
