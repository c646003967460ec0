// Each particle's node as the rules and the geometry read it (model/particle_nodes.hpp, issue 40): kept as
// first + step * i when both id columns are sequences that line up, as i when the particles name the nodes in
// their order, else as a table; either way each particle's entry is the node index's own answer
// (model::IdIndex::find), or no_node. Checked against that answer, particle by particle, on
// sequences of several steps and directions, on particles past the nodes' end, between them, on a column
// that is no sequence, and on a deck read whole.
#include <doctest/doctest.h>

#include <fmt/format.h>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "model/particle_nodes.hpp"

namespace test_particle_nodes_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

model::IdColumn sequence(long long first, long long step, std::size_t n) {
    model::IdColumn column;
    column.assign_sequence(first, step, n);
    return column;
}

// The table the rules had before: the index's answer for every particle.
std::vector<std::uint32_t> expected(const model::Model& m, const model::IdIndex& nodes) {
    std::vector<std::uint32_t> out(m.particles.node.size(), model::ParticleNodes::no_node);
    for (std::size_t i = 0; i < out.size(); ++i)
        if (const auto k = nodes.find(m.particles.node[i])) out[i] = static_cast<std::uint32_t>(*k);
    return out;
}

struct Outcome {
    bool arithmetic = false;
    bool same = false;
};
Outcome compare(const model::IdColumn& node_ids, const model::IdColumn& particle_nodes) {
    model::Model m;
    m.nodes.id = node_ids;
    m.particles.node = particle_nodes;
    const model::IdIndex index(m.nodes.id);
    const model::ParticleNodes got(m, &index);
    const model::ParticleNodes own(m);  // its own index, where it needs one
    const std::vector<std::uint32_t> want = expected(m, index);
    bool same = got.size() == want.size() && own.size() == want.size();
    for (std::size_t i = 0; same && i < want.size(); ++i) same = got[i] == want[i] && own[i] == want[i];
    return {got.arithmetic(), same};
}

}  // namespace

TEST_CASE("particle nodes: sequences that line up are kept as first + step * i, with the index's answers") {
    struct Case {
        long long node_first, node_step;
        std::size_t nodes;
        long long particle_first, particle_step;
        std::size_t particles;
        bool arithmetic;
    };
    const Case cases[] = {
        {1, 1, 1000, 1, 1, 1000, true},        // particle i on node i
        {1, 1, 1000, 101, 1, 500, true},       // on nodes 101..600
        {10, 2, 1000, 14, 4, 300, true},       // every other node, step 2 in the nodes' steps
        {1000, -1, 1000, 990, -3, 200, true},  // descending ids
        {1, 1, 1000, 5, 0, 50, true},          // every particle on node 5
        {1, 1, 1000, 1, 1, 1001, false},       // the last particle's node is missing
        {10, 2, 1000, 11, 2, 100, false},      // between the nodes: none found
        {10, 2, 1000, 10, 3, 100, false},      // a step the nodes' does not divide: every other found
        {1, 1, 100, 50, 1, 0, false},          // no particle
    };
    for (const Case& c : cases) {
        CAPTURE(c.node_first);
        CAPTURE(c.node_step);
        CAPTURE(c.particle_first);
        CAPTURE(c.particle_step);
        CAPTURE(c.particles);
        const Outcome o = compare(sequence(c.node_first, c.node_step, c.nodes),
                                  sequence(c.particle_first, c.particle_step, c.particles));
        CHECK(o.arithmetic == c.arithmetic);
        CHECK(o.same);
    }
}

TEST_CASE("particle nodes: columns that are no sequence are a table, with the index's answers") {
    model::IdColumn jumping;  // 1..500, then 1001..1500
    for (long long id = 1; id <= 500; ++id) jumping.push_back(id);
    for (long long id = 1001; id <= 1500; ++id) jumping.push_back(id);
    Outcome o = compare(jumping, sequence(1, 1, 600));  // 501..600 missing
    CHECK_FALSE(o.arithmetic);
    CHECK(o.same);
    model::IdColumn scattered;
    for (const long long id : {7, 3, 3, 9, 12, 1}) scattered.push_back(id);
    o = compare(sequence(1, 1, 12), scattered);
    CHECK_FALSE(o.arithmetic);
    CHECK(o.same);
    o = compare(scattered, sequence(1, 1, 12));  // a node column with a repeated id
    CHECK_FALSE(o.arithmetic);
    CHECK(o.same);
}

TEST_CASE("particle nodes: particles naming the nodes in their order, in columns too short for sequences") {
    model::IdColumn ids, named;
    for (long long id = 1; id <= 100; ++id) ids.push_back(3 * id * id), named.push_back(3 * id * id);  // rising
    ids.push_back(7);  // one node more, named by no particle
    model::Model m;
    m.nodes.id = ids, m.particles.node = named;
    REQUIRE_FALSE(m.nodes.id.sequence());
    const model::ParticleNodes nodes(m);
    CHECK(nodes.identity());
    bool same = nodes.size() == 100;
    for (std::size_t i = 0; same && i < 100; ++i) same = nodes[i] == i;
    CHECK(same);
    // A repeated id: the index finds the first copy, so particle 1 is not on node 1.
    model::IdColumn repeated = named;
    repeated.set(1, 3);
    m.nodes.id = repeated, m.particles.node = repeated;
    const model::ParticleNodes again(m);
    CHECK_FALSE(again.identity());
    CHECK(again[1] == 0);
    CHECK(compare(repeated, repeated).same);
}

TEST_CASE("particle nodes: a generated deck read whole is arithmetic, and its findings are the table's") {
    // 20,000 nodes and particles (above IdColumn::compact_min_entries: the decoding keeps both as sequences).
    std::string text =
        "*KEYWORD\n*CONTROL_SPH\n" + fmt::format("{:>10}{:>10}{:>10}{:>10}\n", 1, 0, "1e+20", 2) + "*NODE\n";
    constexpr int n = 20000;
    for (int i = 0; i < n; ++i) text += fmt::format("{:>8}{:>16.8e}{:>16.8e}{:>16.8e}\n", i + 1, 0.001 * i, 0.0, 1.0);
    text += "*ELEMENT_SPH\n";
    for (int i = 0; i < n; ++i) text += fmt::format("{:>8}{:>8}{:>16.8e}\n", i + 1, 1, 1e-6);
    text += "*END\n";
    const engine::CheckResult r = engine::check_buffer(text, "generated.k");
    REQUIRE(r.model.nodes.id.sequence());
    REQUIRE(r.model.particles.node.sequence());
    const model::IdIndex index(r.model.nodes.id);
    const model::ParticleNodes nodes(r.model, &index);
    CHECK(nodes.arithmetic());
    const std::vector<std::uint32_t> want = expected(r.model, index);
    REQUIRE(nodes.size() == want.size());
    bool same = true;
    for (std::size_t i = 0; i < want.size(); ++i) same = same && nodes[i] == want[i];
    CHECK(same);
    // IDIM 2 with every particle at z = 1, off the plane z = 0 (SPH110 reads the particles' nodes through this).
    bool off_plane = false;
    for (const auto& d : r.diagnostics) off_plane = off_plane || d.code == "SPH110";
    CHECK(off_plane);
}

}  // namespace test_particle_nodes_cpp
