// `make demo` (decks/demo/run_demo.sh): the mistakes deck shows its diagnostics with carets, the
// clean deck its smoothing-length table, and the script exits 0. The exact codes and lines of the
// mistakes deck are checked by the deck runner (test_decks.cpp reads its `$ expect:` comments).
#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_demo_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

TEST_CASE("demo: run_demo.sh shows the mistakes with carets, then the preview table, and exits 0") {
    test::TempDir dir;
    const std::string script = std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/run_demo.sh";
    const std::string command =
        "NO_COLOR=1 bash '" + script + "' '" + SPHDECK_BINARY + "' > '" + (dir.path() / "out.txt").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(dir.path() / "out.txt");
    const std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    INFO(out);
    CHECK(status == 0);
    for (const char* code : {"SPH010", "SPH030", "SPH100", "REF003"}) {
        CAPTURE(code);
        CHECK(out.find(std::string("[") + code + "]") != std::string::npos);
    }
    CHECK(out.find("--> decks/demo/sph_mistakes_2d.k:") != std::string::npos);  // paths as the user typed them
    CHECK(out.find("^^^") != std::string::npos);                                // carets under the fields
    CHECK(out.find("decks/demo/dam_break_2d.k") != std::string::npos);
    CHECK(out.find("3200") != std::string::npos);  // the preview counts the dam break's particles
}
}  // namespace test_demo_cpp
