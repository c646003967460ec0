// Each file read once per run (issue 33 item 2): decks that include the same file share its text and,
// for a self-contained file, its reading (grammar/file_cache.hpp); their findings stay those of each
// deck checked alone, in parallel too (`sphdeck check --jobs N`).
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/check.hpp"
#include "engine/include_context.hpp"
#include "grammar/file_cache.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_file_cache_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// A mesh include that names a parameter (&mass) and carries reading findings of its own: a keyword in
// lower case (DK021), an indented keyword line (DK020), text after *END (DK017).
const std::string kMesh =
    "$ shared mesh\n"
    "*node\n"
    "       1             0.0             0.0             0.0\n"
    "       2           0.001             0.0             0.0\n"
    "       3           0.002             0.0             0.0\n"
    "  *ELEMENT_SPH\n"
    "       1       1&mass\n"
    "       2       1&mass\n"
    "       3       1   abc\n"
    "*END\n"
    "stray text\n";

const std::string kHeader =
    "*KEYWORD\n"
    "*SECTION_SPH\n"
    "         1       1.2       0.2       2.0\n"
    "*PART\n"
    "water\n"
    "         1         1         1\n"
    "*MAT_NULL\n"
    "         1    1000.0\n";

std::string deck(const std::string& parameters, const std::string& includes,
                 const std::string& keyword = "*KEYWORD\n") {
    return keyword + parameters + kHeader.substr(std::string("*KEYWORD\n").size()) + includes + "*END\n";
}

// The decks of one folder: the same mesh under two values of its parameter, without it (DK012), in the
// long format (another reading), twice in one deck, and through an include that is not self-contained.
std::vector<std::string> write_decks(const test::TempDir& dir) {
    dir.write("model/mesh/mesh.k", kMesh);
    dir.write("model/mesh/copy.k", kMesh);  // the same bytes under another path: one reading
    dir.write("model/mesh/nested.k", "*PARAMETER\nR mass        2.0e-6\n*INCLUDE\nmesh.k\n");
    return {
        dir.write("model/a.k", deck("*PARAMETER\nR mass        1.0e-6\n", "*INCLUDE\nmesh/mesh.k\n")),
        dir.write("model/b.k", deck("*PARAMETER\nR mass          -1.0\n", "*INCLUDE\nmesh/mesh.k\n")),
        dir.write("model/c.k", deck("", "*INCLUDE\nmesh/mesh.k\n")),
        dir.write("model/d.k",
                  deck("*PARAMETER\nR mass        1.0e-6\n", "*INCLUDE\nmesh/mesh.k\n", "*KEYWORD LONG=Y\n")),
        dir.write("model/e.k", deck("*PARAMETER\nR mass        1.0e-6\n", "*INCLUDE\nmesh/mesh.k\nmesh/copy.k\n")),
        dir.write("model/f.k", deck("", "*INCLUDE\nmesh/nested.k\n")),
    };
}

// Everything a check says about a deck, as text: blocks, card lines, findings with their notes and fixes.
std::string describe(const engine::CheckResult& r) {
    std::ostringstream out;
    const auto span = [](const grammar::Span& s) {
        return fmt::format("{}:{}:{}-{}", s.file, s.line, s.column, s.end_column);
    };
    for (const grammar::Block& b : r.deck.blocks)
        out << b.keyword << ' ' << static_cast<int>(b.format) << ' ' << b.first_line << '+' << b.line_count << " scope "
            << b.scope << " epoch " << b.parameter_epoch << ' ' << span(b.span) << '\n';
    for (const grammar::CardLine& l : r.deck.lines) out << l.file << ':' << l.line << '@' << l.offset << ' ';
    out << '\n'
        << r.deck.stats.files << ' ' << r.deck.stats.bytes << ' ' << r.deck.stats.lines << ' ' << r.deck.stats.keywords
        << ' ' << r.deck.stats.cards << '\n';
    for (const diag::Diagnostic& d : r.diagnostics) {
        out << d.code << ' ' << static_cast<int>(d.severity) << ' ' << span(d.span) << ' ' << d.message << '\n';
        for (const diag::Note& n : d.notes) out << "  note " << span(n.span) << ' ' << n.message << '\n';
        for (const diag::Fix& f : d.fixes)
            for (const diag::TextEdit& e : f.edits) out << "  fix " << span(e.span) << ' ' << e.replacement << '\n';
    }
    out << r.summary.particles << " particles\n";
    return out.str();
}

}  // namespace

TEST_CASE("file cache: decks that share includes give the findings of each deck checked alone") {
    test::TempDir dir;
    const std::vector<std::string> decks = write_decks(dir);
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    // The parameter's value is the deck's: the same mesh is a finding in b (negative mass) and c (undefined).
    CHECK(alone[0] != alone[1]);
    CHECK(alone[2].find("DK012") != std::string::npos);
    CHECK(alone[0].find("DK012") == std::string::npos);

    grammar::FileCache cache;
    engine::CheckOptions options;
    options.reader.cache = &cache;
    for (int round = 0; round < 2; ++round)  // the second round reads nothing from disk
        for (std::size_t i = 0; i < decks.size(); ++i) {
            CAPTURE(decks[i]);
            CHECK(describe(engine::check_file(decks[i], options)) == alone[i]);
        }
    const grammar::FileCache::Counters counters = cache.counters();
    CHECK(counters.files_read == 3);               // mesh.k, copy.k, nested.k
    CHECK(counters.readings_made == 2);            // mesh.k in the standard and in the long format
    CHECK(counters.readings_shared >= 2 * 6 - 2);  // every other reading of mesh.k or its copy
}

TEST_CASE("file cache: decks checked on several threads at once read a shared file once") {
    test::TempDir dir;
    const std::vector<std::string> decks = write_decks(dir);
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    grammar::FileCache cache;
    std::vector<std::string> together(decks.size() * 4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < together.size(); ++t)
        threads.emplace_back([&, t] {
            engine::CheckOptions options;
            options.reader.cache = &cache;
            together[t] = describe(engine::check_file(decks[t % decks.size()], options));
        });
    for (std::thread& t : threads) t.join();
    for (std::size_t t = 0; t < together.size(); ++t) CHECK(together[t] == alone[t % decks.size()]);
    CHECK(cache.counters().readings_made == 2);
}

TEST_CASE("file cache: a file changed on disk is read again") {
    test::TempDir dir;
    const std::string mesh = dir.write("mesh.k", kMesh);
    const std::string main = dir.write("main.k", deck("*PARAMETER\nR mass        1.0e-6\n", "*INCLUDE\nmesh.k\n"));
    grammar::FileCache cache;
    engine::CheckOptions options;
    options.reader.cache = &cache;
    const std::string before = describe(engine::check_file(main, options));
    dir.write("mesh.k", kMesh + "*NODE\n       9\n");  // another size: another version
    CHECK(describe(engine::check_file(main, options)) == describe(engine::check_file(main)));
    CHECK(describe(engine::check_file(main, options)) != before);
    CHECK(cache.counters().files_read == 2);
}

TEST_CASE("check --jobs: a folder of decks sharing includes reports as each deck checked alone, in order") {
    test::TempDir dir;
    const std::vector<std::string> decks = write_decks(dir);
    const test::Run one = test::run_sphdeck(dir, "check --format concise --jobs 1 model");
    const test::Run four = test::run_sphdeck(dir, "check --format concise --jobs 4 model");
    CHECK(one.exit_code == 1);
    CHECK(four.exit_code == one.exit_code);
    CHECK(four.out == one.out);
    // Alone, deck by deck, in the folder's order: the same finding lines (the multi-deck run adds a
    // summary line per deck).
    std::string alone;
    for (const char* name : {"a", "b", "c", "d", "e", "f"})
        alone += test::run_sphdeck(dir, fmt::format("check --format concise --alone model/{}.k", name)).out;
    std::string findings;
    std::istringstream lines(one.out);
    for (std::string line; std::getline(lines, line);)
        if (line.find(" error(s), ") == std::string::npos) findings += line + '\n';
    CHECK(findings == alone);
    CHECK(alone.find("model/mesh/mesh.k:") != std::string::npos);
}

TEST_CASE("file cache: an include checked in the context of its decks reads it once for all of them") {
    test::TempDir dir;
    write_decks(dir);
    const std::string mesh = (dir.path() / "model/mesh/mesh.k").string();
    engine::CheckOptions plain;
    const engine::IncludeContext alone = engine::check_in_context(mesh, engine::Documents{}, plain);
    grammar::FileCache cache;
    engine::CheckOptions options;
    options.reader.cache = &cache;
    const engine::IncludeContext shared = engine::check_in_context(mesh, engine::Documents{}, options);
    REQUIRE(shared.decks.size() == alone.decks.size());
    CHECK(shared.decks.size() >= 4);
    for (std::size_t k = 0; k < alone.decks.size(); ++k) {
        CHECK(describe(shared.decks[k]) == describe(alone.decks[k]));
        CHECK(shared.findings[k].size() == alone.findings[k].size());
    }
    CHECK(cache.counters().readings_made == 2);  // standard and long format, whatever number of decks
}
}  // namespace test_file_cache_cpp
