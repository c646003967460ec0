// Decks of one run that include one mesh share its decoded *NODE and *ELEMENT_SPH blocks and its
// geometry preview (issue 40 item 4: model/shared_bulk.hpp, engine/shared_preview.hpp); each deck's
// findings stay exactly those it makes checked alone. A block that names a deck's *PARAMETER or is
// read in another card format is decoded by each deck.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/check.hpp"
#include "engine/shared_preview.hpp"
#include "grammar/file_cache.hpp"
#include "lint/bulk_facts.hpp"
#include "test_support.hpp"

namespace test_shared_decks_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

constexpr int kSide = 16, kLayers = 32;  // 8192 particles: a block big enough for the bulk path

// A lattice of particles in part 1, the last layer in part 2; `mass`: the MASS field as written.
// `flawed`: what the rules over every particle find in the mesh alone: a massless particle, a
// volume, a particle id given twice, a particle far from its part (SPH112, REF006, SPH115).
std::string mesh(const std::string& mass, bool flawed = false) {
    std::string nodes = "*NODE\n", particles = "*ELEMENT_SPH\n";
    int id = 0;
    for (int k = 0; k < kLayers; ++k)
        for (int j = 0; j < kSide; ++j)
            for (int i = 0; i < kSide; ++i) {
                ++id;
                const double far = flawed && id == 100 ? 1.0 : 0.0;
                nodes += fmt::format("{:8d}{:16.6e}{:16.6e}{:16.6e}\n", id, 0.001 * i + far, 0.001 * j, 0.001 * k);
                const std::string written = !flawed ? mass : id == 7 ? "0.0" : id == 9 ? "-1.0e-9" : mass;
                particles +=
                    fmt::format("{:8d}{:8d}{:>16}\n", flawed && id == 50 ? 49 : id, k + 1 == kLayers ? 2 : 1, written);
            }
    return nodes + particles;
}

// A load case: its controls, parts 1 and 2 (`second_part` false leaves part 2 undefined), the includes.
std::string load_case(const std::string& endtim, const std::string& cslh, const std::string& includes,
                      bool second_part = true, const std::string& parameters = "") {
    std::string text = "*KEYWORD\n" + parameters + "*CONTROL_TERMINATION\n" + fmt::format("{:>10}\n", endtim) +
                       "*SECTION_SPH\n" + fmt::format("         1{:>10}       0.2       2.0\n", cslh) +
                       "*PART\nwater\n         1         1         1\n";
    if (second_part) text += "*PART\nwall\n         2         1         1\n";
    return text + "*MAT_NULL\n         1    1000.0\n*INCLUDE\n" + includes + "*END\n";
}

// Everything a check says about a deck: its findings with their places, notes and fixes, its counts.
std::string describe(const engine::CheckResult& r) {
    std::ostringstream out;
    const auto span = [](const grammar::Span& s) {
        return fmt::format("{}:{}:{}-{}", s.file, s.line, s.column, s.end_column);
    };
    for (const diag::Diagnostic& d : r.diagnostics) {
        out << d.code << ' ' << static_cast<int>(d.severity) << ' ' << span(d.span) << ' ' << d.message << '\n';
        for (const diag::Note& n : d.notes) out << "  note " << span(n.span) << ' ' << n.message << '\n';
        for (const diag::Fix& f : d.fixes)
            for (const diag::TextEdit& e : f.edits) out << "  fix " << span(e.span) << ' ' << e.replacement << '\n';
    }
    out << r.summary.particles << " particles, " << r.model.nodes.id.size() << " nodes\n";
    for (std::size_t i = 0; i < r.model.particles.size(); i += 997)
        out << r.model.particles.node[i] << ' ' << r.model.particles.part[i] << ' ' << r.model.particles.mass[i] << ' '
            << r.model.particles.line[i] << '\n';
    return out.str();
}

}  // namespace

// The decks checked in one run that shares `share`, as the command line checks several: each prints what
// it printed alone (`alone`).
void check_in_one_run(const std::vector<std::string>& decks, const std::vector<std::string>& alone,
                      engine::RunShare& share) {
    grammar::FileCache cache;
    engine::CheckOptions options;
    options.reader.cache = &cache;
    options.share = &share;
    for (std::size_t i = 0; i < decks.size(); ++i) {
        CAPTURE(decks[i]);
        CHECK(describe(engine::check_file(decks[i], options)) == alone[i]);
    }
}

TEST_CASE("shared decks: load cases over one mesh give the findings of each checked alone") {
    test::TempDir dir;
    dir.write("mesh.k", mesh("1.0e-6"));
    dir.write("copy.k", mesh("1.0e-6"));  // the same bytes under another name: shared as well
    dir.write("mass.k", mesh("&mass"));   // a parameter in the block: each deck decodes it
    const std::vector<std::string> decks = {
        dir.write("a.k", load_case("0.001", "1.2", "mesh.k\n")),
        dir.write("b.k", load_case("0.002", "1.2", "copy.k\n")),         // another end time: the same preview
        dir.write("c.k", load_case("0.003", "3.0", "mesh.k\n", false)),  // part 2 undefined, another CSLH
        dir.write("e.k", load_case("0.005", "1.2", "mass.k\n", true, "*PARAMETER\nR mass        2.0e-6\n")),
    };
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    CHECK(alone[2] != alone[0]);
    CHECK(alone[2].find("REF") != std::string::npos);  // the particles of the undefined part 2

    engine::RunShare share;
    check_in_one_run(decks, alone, share);
    const model::SharedBulkBlocks::Counters counters = share.bulk.counters();
    CHECK(counters.kept == 2);            // mesh.k's *NODE and *ELEMENT_SPH; mass.k's particles name &mass
    CHECK(counters.shared == 5);          // b and c take both, e its nodes
    CHECK(share.previews.shared() == 1);  // b; c reads other parts and another smoothing length
}

TEST_CASE("shared decks: what the rules find over every particle of a shared mesh is each deck's own") {
    test::TempDir dir;
    dir.write("mesh.k", mesh("1.0e-6"));
    dir.write("flawed.k", mesh("1.0e-6", true));  // another mesh in the same run: facts of its own
    dir.write("part2.k", "*PART\nwall\n         2         1         1\n");
    const std::vector<std::string> decks = {
        dir.write("a.k", load_case("0.001", "1.2", "flawed.k\n")),
        dir.write("b.k", load_case("0.002", "1.2", "mesh.k\n")),
        dir.write("c.k", load_case("0.003", "1.2", "flawed.k\n", false)),  // part 2 undefined: REF002 here only
        // The mesh as the third file: every finding in it at other places than a's.
        dir.write("d.k", load_case("0.004", "1.2", "part2.k\nflawed.k\n", false)),
        dir.write("e.k", load_case("0.005", "3.0", "flawed.k\n")),  // another preview, the same particles
    };
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    for (const char* code : {"SPH112", "REF006", "SPH115"}) {
        CAPTURE(code);
        CHECK(alone[0].find(code) != std::string::npos);
        CHECK(alone[1].find(code) == std::string::npos);
    }
    CHECK(alone[2].find("REF002") != std::string::npos);
    CHECK(alone[0].find("REF002") == std::string::npos);
    CHECK(alone[3].find("REF002") == std::string::npos);

    // The particles' facts are made by the first deck over each mesh; the next pass over its particles
    // again only for a preview of their own (SPH115's stray particles, kept under it): c's and e's.
    engine::RunShare share;
    check_in_one_run({decks[0], decks[1]}, {alone[0], alone[1]}, share);
    const std::size_t facts = share.lookups.facts_computed();
    CHECK(facts > 4);
    check_in_one_run(std::vector<std::string>(decks.begin() + 2, decks.end()),
                     std::vector<std::string>(alone.begin() + 2, alone.end()), share);
    CHECK(share.lookups.facts_computed() == facts + 2);
    CHECK(share.bulk.counters().shared == 6);  // c, d and e take both blocks of the flawed mesh
}

TEST_CASE("shared decks: decks checked at once on several threads give the findings of each checked alone") {
    test::TempDir dir;
    dir.write("mesh.k", mesh("1.0e-6", true));
    std::vector<std::string> decks;
    for (int i = 0; i < 4; ++i)  // 0 and 1 alike; 2 without part 2; 3 with another smoothing length
        decks.push_back(dir.write(fmt::format("case_{}.k", i),
                                  load_case(fmt::format("0.00{}", i + 1), i == 3 ? "3.0" : "1.2", "mesh.k\n", i != 2)));
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    engine::RunShare share;
    grammar::FileCache cache;
    engine::CheckOptions options;
    options.reader.cache = &cache;
    options.share = &share;
    std::vector<std::string> together(decks.size());
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < decks.size(); ++i)
        threads.emplace_back([&, i] { together[i] = describe(engine::check_file(decks[i], options)); });
    for (std::thread& t : threads) t.join();
    for (std::size_t i = 0; i < decks.size(); ++i) {
        CAPTURE(decks[i]);
        CHECK(together[i] == alone[i]);
    }
    // Three previews, each made once, even when two decks ask for one at the same time.
    CHECK(share.previews.shared() == 1);
}

TEST_CASE("shared decks: a fact is computed once per object it is kept under") {
    lint::BulkFacts facts;
    int calls = 0;
    struct Count {
        int value;
    };
    const auto count = [&] { return Count{++calls}; };
    CHECK(facts.get<Count>(count)->value == 1);
    CHECK(facts.get<Count>(count)->value == 1);  // kept
    const auto one = std::make_shared<int>(1), two = std::make_shared<int>(2);
    CHECK(facts.get<Count>(count, one)->value == 2);  // under another object: its own
    CHECK(facts.get<Count>(count, two)->value == 3);
    CHECK(facts.get<Count>(count, one)->value == 2);
    CHECK(facts.computed() == 3);
}

TEST_CASE("shared decks: a block read in another card format is not taken from the shared one") {
    test::TempDir dir;
    dir.write("mesh.k", mesh("1.0e-6"));
    const std::vector<std::string> decks = {
        dir.write("a.k", load_case("0.001", "1.2", "mesh.k\n")),
        dir.write("b.k", "*KEYWORD LONG=Y\n*INCLUDE\nmesh.k\n*END\n"),  // the mesh read 20 wide: other values
    };
    std::vector<std::string> alone;
    for (const std::string& path : decks) alone.push_back(describe(engine::check_file(path)));
    engine::RunShare share;
    check_in_one_run(decks, alone, share);
    CHECK(share.bulk.counters().shared == 0);
}

}  // namespace test_shared_decks_cpp
