// One input and exit-code convention across the subcommands, and the parser's messages in sphdeck's
// words (issue 44 items 2-4 and 6): --exclude by folder name, list options given twice or joined, a code
// never taken for a deck, `format` over folders and standard input, `format --diff` exit 1, stdout and
// stderr in order on one pipe.
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_cli_conventions_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kTidy = "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*END\n";
const std::string kUntidy = "*keyword\n*CONTROL_TERMINATION\n1.0\n*END\n";         // DK021, and 1.0 not right-aligned
const std::string kBroken = "*KEYWORD\n*CONTROL_TERMINATION\n       abc\n*END\n";  // DK003

std::string read_file(const test::TempDir& dir, const std::string& name) {
    std::ifstream in(dir.path() / name, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// stdout and stderr of `sphdeck ARGS` into one pipe, as `sphdeck ... 2>&1 | less` shows them.
std::string merged_output(const test::TempDir& dir, const std::string& args) {
    const std::string command = "cd '" + dir.path().string() + "' && '" + SPHDECK_BINARY + "' " + args + " 2>&1 | cat";
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[4096];
        for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
        ::pclose(pipe);
    }
    return out;
}

}  // namespace

TEST_CASE("cli conventions: --exclude takes a folder name as .gitignore does, below the given folder") {
    test::TempDir dir;
    dir.write("model/main.k", kTidy);
    dir.write("model/water_tank/broken.k", kBroken);
    dir.write("model/tmp_scratch.k", kBroken);
    const test::Run by_name = test::run_sphdeck(dir, "check --format concise --exclude water_tank model");
    CHECK(by_name.out.find("water_tank") == std::string::npos);
    CHECK(by_name.out.find("tmp_scratch.k:3:8: error") != std::string::npos);
    const test::Run two = test::run_sphdeck(dir, "check --format concise --exclude water_tank --exclude 'tmp_*' model");
    CHECK(two.exit_code == 0);
    // The given folder's own name is not matched: `--exclude model model` still checks model/.
    CHECK(test::run_sphdeck(dir, "check --format concise --exclude model model").exit_code == 1);
    const test::Run by_path = test::run_sphdeck(dir, "check --format concise --exclude 'model/water_tank' model");
    CHECK(by_path.out.find("water_tank") == std::string::npos);
}

TEST_CASE("cli conventions: list options joined or repeated; a rule code is never read as a deck") {
    test::TempDir dir;
    dir.write("deck.k", kBroken);
    CHECK(test::run_sphdeck(dir, "check --ignore DK003,SPH030 deck.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "check --ignore SPH030 --ignore DK003 deck.k").exit_code == 0);
    const test::Run swallowed = test::run_sphdeck(dir, "check --ignore SPH030 DK003 deck.k");
    CHECK(swallowed.exit_code == 2);
    CHECK(swallowed.err.find("sphdeck check: error: 'DK003' is no file but looks like a rule code") !=
          std::string::npos);
    CHECK(swallowed.err.find("--ignore A --ignore B") != std::string::npos);
}

TEST_CASE("cli conventions: the option parser's errors in sphdeck's words") {
    test::TempDir dir;
    const test::Run none = test::run_sphdeck(dir, "");
    CHECK(none.exit_code == 2);
    CHECK(none.err == "sphdeck: no command given; try 'sphdeck --help'\n");
    const test::Run no_deck = test::run_sphdeck(dir, "check");
    CHECK(no_deck.exit_code == 2);
    CHECK(no_deck.err == "sphdeck check: no deck given; try 'sphdeck check --help'\n");
    CHECK(test::run_sphdeck(dir, "smooth").err == "sphdeck smooth: no deck given; try 'sphdeck smooth --help'\n");
    const test::Run choice = test::run_sphdeck(dir, "check --format xml deck.k");
    CHECK(
        choice.err ==
        "sphdeck check: --format: 'xml' is not one of full, concise, json, sarif, github; try 'sphdeck check --help'\n");
    const test::Run number = test::run_sphdeck(dir, "run --threads abc deck.k");
    CHECK(number.exit_code == 2);
    CHECK(number.err.rfind("sphdeck run: --threads: 'abc' is not", 0) == 0);
    CHECK(number.err.find("1797") == std::string::npos);  // no 300-digit bound
    CHECK(test::run_sphdeck(dir, "check --help").exit_code == 0);
}

TEST_CASE("cli conventions: format takes folders and standard input; --diff and --check exit 1 on a change") {
    test::TempDir dir;
    dir.write("model/tidy.k", kTidy);
    dir.write("model/sub/untidy.k", kUntidy);
    const test::Run diff = test::run_sphdeck(dir, "format --diff model");
    CHECK(diff.exit_code == 1);
    CHECK(diff.out.find("+++ b/model/sub/untidy.k") != std::string::npos);
    CHECK(diff.err.find("would reformat 1 of 2 files") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "format --check model").exit_code == 1);
    CHECK(test::run_sphdeck(dir, "format --diff model/tidy.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "format --check --exclude sub model").exit_code == 0);

    const test::Run piped = test::run_sphdeck(dir, "format - --stdin-filename model/sub/untidy.k < model/sub/untidy.k");
    CHECK(piped.exit_code == 0);
    CHECK(piped.out == "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*END\n");
    CHECK(read_file(dir, "model/sub/untidy.k") == kUntidy);  // standard input: nothing written
    CHECK(test::run_sphdeck(dir, "format - < model/tidy.k").out == kTidy);
    CHECK(test::run_sphdeck(dir, "format --check - < model/sub/untidy.k").exit_code == 1);

    const test::Run missing = test::run_sphdeck(dir, "format no-such.k");
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.rfind("sphdeck format: error: ", 0) == 0);

    test::run_sphdeck(dir, "format model");  // in place, through the folder
    CHECK(read_file(dir, "model/sub/untidy.k") == "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*END\n");
}

TEST_CASE("cli conventions: output and messages in order when both streams go to one pipe") {
    test::TempDir dir;
    dir.write("deck.k", kUntidy);
    const std::string text = merged_output(dir, "format --diff deck.k");
    const auto diff_at = text.find("--- a/deck.k");
    const auto summary_at = text.find("would reformat 1 of 1 file");
    REQUIRE(diff_at != std::string::npos);
    REQUIRE(summary_at != std::string::npos);
    CHECK(diff_at < summary_at);
}

TEST_CASE("cli conventions: dump, smooth and diff read a deck from standard input (-) as check does") {
    test::TempDir dir;
    dir.write("deck.k", kTidy);
    dir.write("other.k", "*KEYWORD\n*CONTROL_TERMINATION\n       2.0\n*END\n");
    const test::Run dumped = test::run_sphdeck(dir, "dump - --stdin-filename named.k < deck.k");
    CHECK(dumped.exit_code == 0);
    CHECK(dumped.out.find("\"file\": \"named.k\"") != std::string::npos);
    CHECK(dumped.out.find("\"ENDTIM\": {\n          \"value\": 1.0,") != std::string::npos);
    const test::Run same = test::run_sphdeck(dir, "diff deck.k - < deck.k");
    CHECK(same.exit_code == 0);
    const test::Run differs = test::run_sphdeck(dir, "diff - other.k --stdin-filename piped.k < deck.k");
    CHECK(differs.exit_code == 1);
    CHECK(differs.out.find("ENDTIM: 1.0 -> 2.0") != std::string::npos);
    CHECK(differs.out.find("piped.k:2") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "diff - - < deck.k").exit_code == 2);
    const test::Run smoothed = test::run_sphdeck(dir, "smooth - --stdin-filename piped.k < deck.k");
    CHECK(smoothed.exit_code == 2);  // no particles: the message names the deck as --stdin-filename says
    CHECK(smoothed.err.find("sphdeck: error: piped.k: no SPH particles") != std::string::npos);
}
}  // namespace test_cli_conventions_cpp
