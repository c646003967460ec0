// The bulk blocks' ids kept as runs while the threads decode them (model/id_run.hpp, issue 40): a block
// whose ids run first + step * k over all its lines becomes a sequence column without an entry written, and
// every other shape (a jump, a line that gives no id, an NEND range, a second block, ids too wide for 4
// bytes) reads the same ids as before, on 1, 2 and 3 threads.
#include <doctest/doctest.h>

#include <fmt/format.h>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "engine/check.hpp"
#include "model/id_run.hpp"

namespace test_id_runs_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

constexpr std::size_t lines = 20000;  // above IdColumn::compact_min_entries: the runs are kept

// A deck of *NODE lines with ids `node_ids` and one particle a node (*ELEMENT_SPH: id, part, mass), the
// particles' parts `parts`; `odd` replaces the *ELEMENT_SPH line of that index when not empty.
std::string deck(const std::vector<long long>& node_ids, const std::vector<long long>& parts, std::size_t odd_at = 0,
                 const std::string& odd = "") {
    std::string text = "*KEYWORD\n*NODE\n";
    for (std::size_t i = 0; i < node_ids.size(); ++i)
        text +=
            fmt::format("{:>8}{:>16.8e}{:>16.8e}{:>16.8e}\n", node_ids[i], 0.001 * static_cast<double>(i), 0.0, 0.0);
    text += "*ELEMENT_SPH\n";
    for (std::size_t i = 0; i < node_ids.size(); ++i)
        text += !odd.empty() && i == odd_at ? odd + "\n"
                                            : fmt::format("{:>8}{:>8}{:>16.8e}\n", node_ids[i], parts[i], 1e-3);
    return text + "*END\n";
}

std::vector<long long> values(const model::IdColumn& column) { return {column.begin(), column.end()}; }

// Decodes `text` on 1, 2 and 3 threads: the ids each time, and whether each column is a sequence.
struct Read {
    std::vector<long long> nodes, particle_nodes, parts;
    bool nodes_sequence = false, parts_sequence = false;
};
std::vector<Read> read_on_threads(const std::string& text) {
    std::vector<Read> out;
    for (const int threads : {1, 2, 3}) {
#ifdef _OPENMP
        const int saved = omp_get_max_threads();
        omp_set_num_threads(threads);
#endif
        const engine::CheckResult r = engine::check_buffer(text, "runs.k");
#ifdef _OPENMP
        omp_set_num_threads(saved);
#endif
        out.push_back({values(r.model.nodes.id), values(r.model.particles.node), values(r.model.particles.part),
                       r.model.nodes.id.sequence(), r.model.particles.part.sequence()});
    }
    return out;
}

std::vector<long long> ids_from(long long first, long long step) {
    std::vector<long long> ids(lines);
    for (std::size_t i = 0; i < lines; ++i) ids[i] = first + step * static_cast<long long>(i);
    return ids;
}

}  // namespace

TEST_CASE("id runs: a run is taken id by id and ends at the first id that does not continue it") {
    model::IdRun run;
    CHECK(run.extend(5, 10));
    CHECK(run.extend(6, 12));  // the step is the second id's
    CHECK(run.extend(7, 14));
    CHECK_FALSE(run.extend(8, 15));  // not 16
    CHECK_FALSE(run.extend(9, 16));  // a line between gave no id
    CHECK(run.count == 3);
    CHECK(run.at(2) == 14);
    CHECK(run.end() == 8);
    model::IdRun wide;
    CHECK_FALSE(wide.extend(0, 4'000'000'000LL));  // not kept in 4 bytes
}

TEST_CASE("id runs: ids 1..n and one part become sequences, with the same ids") {
    const std::vector<long long> ids = ids_from(1, 1);
    for (const Read& r : read_on_threads(deck(ids, std::vector<long long>(lines, 7)))) {
        CHECK(r.nodes == ids);
        CHECK(r.particle_nodes == ids);
        CHECK(r.parts == std::vector<long long>(lines, 7));
        CHECK(r.nodes_sequence);
        CHECK(r.parts_sequence);
    }
    for (const Read& r : read_on_threads(deck(ids_from(90000, -3), ids_from(5, 2)))) {  // other steps
        CHECK(r.nodes == ids_from(90000, -3));
        CHECK(r.parts == ids_from(5, 2));
        CHECK(r.nodes_sequence);
    }
}

TEST_CASE("id runs: any other shape reads the ids it did") {
    std::vector<long long> jump = ids_from(1, 1);
    for (std::size_t i = lines / 3; i < lines; ++i) jump[i] += 1000;  // inside the first thread's lines, or on its edge
    for (const Read& r : read_on_threads(deck(jump, std::vector<long long>(lines, 1)))) {
        CHECK(r.nodes == jump);
        CHECK(r.particle_nodes == jump);
        CHECK_FALSE(r.nodes_sequence);
        CHECK(r.parts_sequence);
    }
    std::vector<long long> parts(lines, 1);
    parts.back() = 2;  // the last line's part only
    for (const Read& r : read_on_threads(deck(ids_from(1, 1), parts))) {
        CHECK(r.parts == parts);
        CHECK_FALSE(r.parts_sequence);
    }
    // A particle line without a node id (skipped, DK008) and one with an NEND range: the lines after them move.
    const std::vector<long long> ids = ids_from(1, 1);
    const std::vector<std::pair<std::string, std::size_t>> odd_lines = {
        {"               1 1.00000000e-03", lines - 1},
        {fmt::format("{:>8}{:>8}{:>16.8e}{:>8}", 101, 1, 1e-3, 103), lines + 2}};
    for (const auto& odd_line : odd_lines) {
        const std::string& odd = odd_line.first;  // not a structured binding: CAPTURE takes it into a lambda
        const std::size_t expected_count = odd_line.second;
        for (const Read& r : read_on_threads(deck(ids, std::vector<long long>(lines, 1), 100, odd))) {
            CAPTURE(odd);
            REQUIRE(r.particle_nodes.size() == expected_count);
            CHECK(r.particle_nodes[99] == 100);
            CHECK(r.particle_nodes.back() == static_cast<long long>(lines));
            CHECK(r.nodes == ids);
        }
    }
}

TEST_CASE("id runs: a second *NODE block after one kept as a sequence") {
    const std::vector<long long> ids = ids_from(1, 1);
    std::string text = deck(ids, std::vector<long long>(lines, 1));
    std::string second = "*NODE\n";
    for (std::size_t i = 0; i < lines; ++i)
        second += fmt::format("{:>8}{:>16.8e}{:>16.8e}{:>16.8e}\n", 50001 + i, 1.0, 0.0, 0.0);
    text.insert(text.find("*ELEMENT_SPH"), second);
    std::vector<long long> all = ids;
    for (std::size_t i = 0; i < lines; ++i) all.push_back(50001 + static_cast<long long>(i));
    for (const Read& r : read_on_threads(text)) {
        CHECK(r.nodes == all);
        CHECK(r.particle_nodes == ids);
    }
}

}  // namespace test_id_runs_cpp
