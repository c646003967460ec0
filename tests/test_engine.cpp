// engine/: a deck checked from documents held in memory gives the findings it gives from disk, an
// include held in memory is read instead of the file, and the include graph names what a deck read.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "engine/check.hpp"
#include "text/text_file.hpp"
#include "test_support.hpp"

namespace test_engine_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

namespace {

namespace fs = std::filesystem;

const std::string kDeck = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/ref/REF002_fires.k";
const std::string kInclude = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/ref/include/ref_lattice.inc";

// What a finding says and where, with the file named by its base name: the same deck read from two
// folders gives equal lists.
using Finding = std::tuple<std::string, std::string, std::string, std::uint32_t, std::uint32_t>;
std::vector<Finding> findings(const engine::CheckResult& r) {
    std::vector<Finding> out;
    for (const diag::Diagnostic& d : r.diagnostics) {
        const std::string file =
            d.span.valid() ? fs::path(r.deck.sources.file(d.span.file).path).filename().string() : "";
        out.emplace_back(d.code, d.message, file, d.span.line, d.span.column);
    }
    return out;
}

}  // namespace

TEST_CASE("engine: a deck given as an in-memory document gives the findings it gives from disk") {
    const engine::CheckResult disk = engine::check_file(kDeck);
    REQUIRE(count_code(disk.diagnostics, "REF002") == 3);

    engine::Documents documents;
    documents.set(kDeck, text::read_text_file(kDeck));
    CHECK(findings(engine::check_deck(kDeck, documents)) == findings(disk));
    CHECK(findings(engine::check_deck(kDeck, engine::Documents{})) == findings(disk));
}

TEST_CASE("engine: check_read_file of a deck read already gives check_file's findings and includes") {
    // sphdeck format reads a deck, then checks that reading (not the file again) when a line changes.
    const std::string source = std::string(SPHDECK_SOURCE_DIR) + "/decks/";
    for (const std::string& deck : {kDeck, source + "tests/dk/DK003_fires_realign.k",  // with fixes
                                    source + "sol2sph/bumper_0000.rad"}) {
        CAPTURE(deck);
        const engine::CheckResult disk = engine::check_file(deck);
        engine::CheckOptions options;
        const engine::CheckResult read =
            engine::check_read_file(deck, grammar::read_deck(deck, options.reader), options);
        CHECK(findings(read) == findings(disk));
        CHECK(read.diagnostics.size() == disk.diagnostics.size());
        CHECK(read.includes.files.size() == disk.includes.files.size());
        CHECK(read.deck.sources.size() == disk.deck.sources.size());
    }
    CHECK(count_code(engine::check_read_file(kDeck, grammar::read_deck(kDeck, {}), {}).diagnostics, "REF002") == 3);
}

TEST_CASE("engine: an include held in memory is read instead of the file, as if it were saved") {
    // The include as an editor holds it: node 1 defined a second time (REF006).
    const std::string edited = text::read_text_file(kInclude) + "*NODE\n       1\n";
    test::TempDir saved;
    saved.write("include/ref_lattice.inc", edited);
    const engine::CheckResult on_disk = engine::check_file(saved.write("REF002_fires.k", text::read_text_file(kDeck)));
    REQUIRE(count_code(on_disk.diagnostics, "REF006") == 1);

    engine::Documents documents;
    documents.set(kInclude, edited);
    const engine::CheckResult in_memory = engine::check_deck(kDeck, documents);
    CHECK(findings(in_memory) == findings(on_disk));
    CHECK(count_code(engine::check_file(kDeck).diagnostics, "REF006") == 0);  // the file itself is untouched
}

TEST_CASE("engine: an include that exists only in memory is found") {
    test::TempDir dir;
    const std::string main = dir.write("main.k", "*KEYWORD\n*INCLUDE\nmesh.k\n*END\n");
    CHECK(count_code(engine::check_file(main).diagnostics, "DK010") == 1);
    engine::Documents documents;
    documents.set(dir.path() / "mesh.k", "*NODE\n       1\n");
    const engine::CheckResult r = engine::check_deck(main, documents);
    CHECK(count_code(r.diagnostics, "DK010") == 0);
    REQUIRE(r.includes.files.size() == 1);
    CHECK(r.includes.files[0].path == engine::Documents::key(dir.path() / "mesh.k"));
}

TEST_CASE("engine: the include graph lists the files a deck pulled in") {
    const engine::CheckResult r = engine::check_file(kDeck);
    CHECK(r.includes.main == engine::Documents::key(kDeck));
    REQUIRE(r.includes.files.size() == 1);
    const engine::IncludedFile& f = r.includes.files[0];
    CHECK(f.path == engine::Documents::key(kInclude));
    CHECK(f.included_by == engine::Documents::key(kDeck));
    CHECK(f.include_line == 21);  // the line naming the file
    CHECK(r.includes.depends_on(kInclude));
    CHECK(r.includes.depends_on(kDeck));
    CHECK_FALSE(r.includes.depends_on(std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/ref/REF002_silent.k"));
}

TEST_CASE("engine: a Radioss engine deck read beside its starter is in the graph, from memory too") {
    test::TempDir dir;
    const std::string starter = dir.write("run_0000.rad", "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n/END\n");
    engine::Documents documents;
    documents.set(dir.path() / "run_0001.rad", "#RADIOSS ENGINE\n/RUN/run/1\n1.0\n/END/ENGINE\n");
    const engine::CheckResult r = engine::check_deck(starter, documents);
    REQUIRE(r.includes.files.size() == 1);
    CHECK(r.includes.files[0].path == engine::Documents::key(dir.path() / "run_0001.rad"));
    CHECK(r.includes.files[0].included_by.empty());
    CHECK(engine::check_file(starter).includes.files.empty());
}
}  // namespace test_engine_cpp
