// `sphdeck format`: in place, --check (exit 1 when a file would change), --diff (writes nothing),
// --includes (only the named files otherwise), the summary and --verbose; `dump --cards` reads the same
// values before and after.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_format_command_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kMain =
    "*keyword\n"
    "*INCLUDE\n"
    "part.k\n"
    "*CONTROL_TERMINATION\n"
    "1.0\n"
    "*CONTROL_TIMESTEP\n"
    "   0.0000.9\n"  // a value across the boundary (DK003): left as written
    "*END\n";
const std::string kPart = "*KEYWORD\n*SECTION_SPH\n1         1.2\n*END\n";

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string cards(const test::TempDir& dir) {
    test::Run r = test::run_sphdeck(dir, "dump --cards main.k");
    REQUIRE(r.exit_code == 0);
    // Positions aside: the card list after its first "values".
    const auto at = r.out.find("\"cards\":");
    REQUIRE(at != std::string::npos);
    std::string out;
    for (std::size_t i = r.out.find("\"values\"", at); i != std::string::npos; i = r.out.find("\"values\"", i + 1))
        out += r.out.substr(i, r.out.find("]}", i) - i) + "\n";
    return out;
}

}  // namespace

TEST_CASE("format command: --check and --diff write nothing; in place, then idempotent; --includes") {
    test::TempDir dir;
    const std::string main = dir.write("main.k", kMain), part = dir.write("part.k", kPart);
    const std::string values = cards(dir);

    test::Run r = test::run_sphdeck(dir, "format --check main.k");
    CHECK(r.exit_code == 1);
    CHECK(r.out == "would reformat main.k\n");
    CHECK(r.err.find("would reformat 1 of 1 file (lines: 1 values realigned, 1 keyword case); 1 card line left as "
                     "written") != std::string::npos);
    r = test::run_sphdeck(dir, "format --diff main.k");
    CHECK(r.exit_code == 1);  // as --check and `check --diff`: a file would change
    CHECK(r.out.find("-1.0\n+       1.0\n") != std::string::npos);
    CHECK(slurp(main) == kMain);

    r = test::run_sphdeck(dir, "format -v main.k");
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("main.k:7: left as written: finding DK003") != std::string::npos);
    CHECK(slurp(main) ==
          "*KEYWORD\n*INCLUDE\npart.k\n*CONTROL_TERMINATION\n       1.0\n*CONTROL_TIMESTEP\n   0.0000.9\n*END\n");
    CHECK(slurp(part) == kPart);  // not named, not formatted
    CHECK(test::run_sphdeck(dir, "format --check main.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "format --check --includes main.k").exit_code == 1);

    r = test::run_sphdeck(dir, "format --includes main.k");
    CHECK(r.exit_code == 0);
    CHECK(slurp(part) == "*KEYWORD\n*SECTION_SPH\n         1       1.2\n*END\n");
    CHECK(test::run_sphdeck(dir, "format --check --includes main.k").exit_code == 0);
    CHECK(cards(dir) == values);  // the same values, read from the same cards
}

TEST_CASE("format command: a deck that cannot be read is exit 2") {
    test::TempDir dir;
    test::Run r = test::run_sphdeck(dir, "format missing.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("error:") != std::string::npos);
}
}  // namespace test_format_command_cpp
