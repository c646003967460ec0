// engine/include_context: an include file checked as part of the decks that include it (issue 26
// item 2), the fragment's note when none does (REF010), and DK018 across files.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "engine/include_context.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_include_context_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
namespace fs = std::filesystem;

namespace {

const std::string kTank = std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/water_tank";

const std::string kMain =
    "*KEYWORD\n"
    "*INCLUDE\n"
    "include/parts.k\n"
    "*SECTION_SOLID\n"
    "         1\n"
    "*MAT_ELASTIC\n"
    "         1    7800.0   2.1e+11       0.3\n"
    "*END\n";

// No *KEYWORD: a fragment. Part 2 names section 5, which nothing defines (a real mistake).
const std::string kParts =
    "*PART\n"
    "plate\n"
    "         1         1         1\n"
    "rib\n"
    "         2         5         1\n";

std::string file_of(const engine::CheckResult& r, const diag::Diagnostic& d) {
    return fs::path(r.deck.sources.file(d.span.file).path).filename().string();
}

}  // namespace

TEST_CASE("include context: an include of a shipped multi-file deck is checked as part of its deck") {
    const auto context = engine::check_in_context(kTank + "/include/particles.k", engine::Documents{}, {});
    REQUIRE(context.decks.size() == 1);
    CHECK(fs::path(context.decks[0].deck.sources.file(0).path).filename() == "water_tank.k");
    CHECK(context.findings[0].empty());  // alone it names part 1 and lies in z = 0 with no *CONTROL_SPH
    const engine::CheckResult alone = engine::check_file(kTank + "/include/particles.k");
    CHECK(count_code(alone.diagnostics, "REF010") == 1);
}

TEST_CASE("include context: the file's own findings are reported, at the file's lines, once") {
    test::TempDir dir;
    dir.write("sphdeck.toml", "");  // the project root: the search stops here
    dir.write("main.k", kMain);
    dir.write("second_case.k", kMain);  // two load cases read the same parts
    const std::string parts = dir.write("include/parts.k", kParts);
    const auto context = engine::check_in_context(parts, engine::Documents{}, {});
    REQUIRE(context.decks.size() == 2);
    REQUIRE(context.findings[0].size() == 1);
    CHECK(context.findings[0][0].code == "REF003");
    CHECK(context.findings[0][0].span.line == 5);
    CHECK(file_of(context.decks[0], context.findings[0][0]) == "parts.k");
    CHECK(context.findings[1].empty());  // the second deck's copy of the same finding
}

TEST_CASE("include context: a deck that reaches the file through another include, and an unsaved buffer") {
    test::TempDir dir;
    dir.write(".git/HEAD", "");  // a version-control root
    dir.write("main.k", "*KEYWORD\n*INCLUDE\nmodel.k\n*SECTION_SOLID\n         1\n*END\n");
    dir.write("model.k", "*KEYWORD\n*INCLUDE\ninclude/parts.k\n*MAT_ELASTIC\n         1    7800.0   2.1e+11\n");
    const std::string parts = dir.write("include/parts.k", kParts);
    engine::Documents documents;
    documents.set(parts, "*PART\nplate\n         1         1         1\n");  // the rib deleted in the editor
    const auto context = engine::check_in_context(parts, documents, {});
    REQUIRE(context.decks.size() == 1);  // model.k is read by main.k: main.k's check covers it
    CHECK(fs::path(context.decks[0].deck.sources.file(0).path).filename() == "main.k");
    CHECK(context.findings[0].empty());
}

TEST_CASE("include context: a file no deck includes gets none; roots of sphdeck.toml are searched") {
    test::TempDir dir;
    dir.write("sphdeck.toml", "");
    const std::string parts = dir.write("include/parts.k", kParts);
    dir.write("elsewhere/main.k", kMain);  // two folders down from the root: not searched
    CHECK(engine::check_in_context(parts, engine::Documents{}, {}).decks.empty());
    engine::CheckOptions options;
    options.config.roots = {(dir.path() / "elsewhere").string()};
    dir.write("elsewhere/include/parts.k", kParts);
    const std::string other_parts = (dir.path() / "elsewhere/include/parts.k").string();
    CHECK(engine::check_in_context(other_parts, engine::Documents{}, options).decks.size() == 1);
    CHECK(engine::check_in_context(parts, engine::Documents{}, options).decks.empty());  // main.k reads the other
}

TEST_CASE("include context: a big deck naming the file across its 1 MiB search slices") {
    // The decks around a file are searched in slices of 1 MiB released behind the search: a name cut by
    // a slice's end is still found (each slice reaches into the next).
    for (const std::size_t cut : {std::size_t{0}, std::size_t{1}, std::size_t{4}, std::size_t{6}, std::size_t{7}}) {
        CAPTURE(cut);
        test::TempDir dir;
        dir.write("sphdeck.toml", "");
        // "*KEYWORD\n" + comment + "\n*INCLUDE\ninclude/parts.k": "parts.k" starts 27 bytes after the
        // comment's start; it starts `cut` bytes before the first slice's end.
        const std::string comment = "$" + std::string((std::size_t{1} << 20) - cut - 27 - 1, '-');
        const std::string main =
            "*KEYWORD\n" + comment + "\n*INCLUDE\ninclude/parts.k\n*SECTION_SOLID\n         1\n*END\n";
        REQUIRE(main.find("parts.k") == (std::size_t{1} << 20) - cut);
        dir.write("big_main.k", main);
        const std::string parts = dir.write("include/parts.k", kParts);
        CHECK(engine::check_in_context(parts, engine::Documents{}, {}).decks.size() == 1);
    }
}

TEST_CASE("include context: sphdeck check names the deck and reports only the file's findings") {
    test::TempDir dir;
    dir.write("sphdeck.toml", "");
    dir.write("main.k", kMain + "*PART\nstray\n         9         8         1\n");
    dir.write("include/parts.k", kParts);
    const test::Run run = test::run_sphdeck(dir, "check --format concise include/parts.k");
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("include/parts.k: checked as included by main.k") != std::string::npos);
    CHECK(run.out.find("parts.k:5:20: error: part 2 names section 5") != std::string::npos);
    CHECK(run.out.find("section 8") == std::string::npos);  // main.k's own mistake is main.k's business
    const test::Run alone = test::run_sphdeck(dir, "check --format concise --alone include/parts.k");
    CHECK(alone.exit_code == 0);  // a fragment alone: one REF010 note
    CHECK(alone.out.find("[REF010]") != std::string::npos);
}

TEST_CASE("DK018: a copy in the same file is an error, a copy in an include a warning naming the copy used") {
    const engine::CheckResult r = engine::check_file(std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/dk/DK018_fires.k");
    REQUIRE(count_code(r.diagnostics, "DK018") == 2);
    for (const diag::Diagnostic& d : r.diagnostics) {
        if (d.code != "DK018") continue;
        if (file_of(r, d) == "DK018_fires.k") {
            CHECK(d.severity == diag::Severity::Error);
        } else {
            CHECK(d.severity == diag::Severity::Warning);
            CHECK(d.message.find("this copy, read last, is the one that takes effect") != std::string::npos);
        }
    }
}
}  // namespace test_include_context_cpp
