// `sphdeck check` over folders and standard input, --exclude, --statistics, --exit-zero and
// --output-file (issue 33 items 1 and 3).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_check_inputs_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kMain = "*KEYWORD\n*INCLUDE\ninclude/parts.k\n*SECTION_SOLID\n         1\n*END\n";
// No *KEYWORD; names material 3, which nothing defines: one REF004 in main.k's context.
const std::string kParts = "*PART\nplate\n         1         1         3\n";
const std::string kBroken = "*KEYWORD\n*CONTROL_TERMINATION\n       abc\n*END\n";  // DK003

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("check inputs: a folder is searched for decks; an include is checked in its includer only") {
    test::TempDir dir;
    dir.write("model/main.k", kMain);
    dir.write("model/include/parts.k", kParts);
    dir.write("model/old/broken.k", kBroken);
    dir.write("model/notes.txt", kBroken);  // not a deck file
    dir.write("model/.hidden/broken.k", kBroken);
    const test::Run run = test::run_sphdeck(dir, "check --format concise model");
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("model/include/parts.k:3:30: error: part 1 names material 3") != std::string::npos);
    CHECK(run.out.find("REF010") == std::string::npos);  // parts.k is not checked again on its own
    CHECK(run.out.find("model/old/broken.k:3:8: error") != std::string::npos);
    CHECK(run.out.find("notes.txt") == std::string::npos);
    CHECK(run.out.find(".hidden") == std::string::npos);
    CHECK(run.out.find("model/main.k: 1 error(s), 0 warning(s), 0 info(s)") != std::string::npos);
    const test::Run excluded = test::run_sphdeck(dir, "check --format concise --exclude '*/old/*' model");
    CHECK(excluded.out.find("broken.k") == std::string::npos);
    CHECK(test::run_sphdeck(dir, "check no-such-folder").exit_code == 2);
}

TEST_CASE("check inputs: standard input, named by --stdin-filename, resolves includes from there") {
    test::TempDir dir;
    dir.write("model/main.k", kMain);
    dir.write("model/include/parts.k", kParts);
    const test::Run run =
        test::run_sphdeck(dir, "check --format concise --stdin-filename model/main.k - < model/main.k");
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("model/include/parts.k:3:30: error: part 1 names material 3") != std::string::npos);
    const test::Run unnamed = test::run_sphdeck(dir, "check --format concise - < model/main.k");
    CHECK(unnamed.out.find("<stdin>:3:1: error") != std::string::npos);  // the include is not found: DK010
}

TEST_CASE("check inputs: a deck of several megabytes through a pipe reads as the same file does") {
    // Standard input is read in blocks of 1 MiB from a pipe, in one block from a redirected file: the
    // deck spans several blocks, and its last line holds a mistake, so every byte must arrive in order.
    test::TempDir dir;
    std::string deck = "*KEYWORD\n*NODE\n";
    for (int id = 1; id <= 60000; ++id) deck += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", id, id * 0.01, 0.0, 0.0);
    deck += "*CONTROL_TERMINATION\n       abc\n*END\n";  // DK003 on the deck's second last line
    dir.write("big.k", deck);
    REQUIRE(deck.size() > 3u << 20);
    const test::Run file = test::run_sphdeck(dir, "check --format concise big.k");
    const test::Run piped = test::run_sphdeck(dir, "check --format concise --stdin-filename big.k - < big.k");
    const test::Run through_cat =
        test::run_sphdeck(dir, "check --format concise --stdin-filename big.k -", "cat big.k | ");
    CHECK(file.exit_code == 1);
    CHECK(file.out.find("big.k:60004:8: error") != std::string::npos);
    CHECK(piped.out == file.out);
    CHECK(through_cat.out == file.out);
}

TEST_CASE("check inputs: --statistics, --exit-zero and --output-file") {
    test::TempDir dir;
    dir.write("a.k", kBroken);
    dir.write("b.k", kBroken);
    const test::Run stats = test::run_sphdeck(dir, "check --format concise --statistics a.k b.k");
    CHECK(stats.exit_code == 1);
    CHECK(stats.out.find("       2  DK003   error    bad-real") != std::string::npos);
    CHECK(stats.out.find("       1  a.k (1 error(s), 0 warning(s), 0 info(s))") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "check --exit-zero a.k").exit_code == 0);
    const test::Run to_file = test::run_sphdeck(dir, "check --format json --output-file report.json a.k");
    CHECK(to_file.exit_code == 1);
    CHECK(to_file.out.empty());
    CHECK(slurp(dir.path() / "report.json").find("\"DK003\"") != std::string::npos);
}
}  // namespace test_check_inputs_cpp
