// *DEFINE_SPH_MESH_BOX particles (preproc/sph_mesh_box.hpp): counts, cell-centre positions and
// volumes of decks/tests/preview/mesh_box.k, the boxes that are not previewed, the cap, and
// `sphdeck smooth` previewing them with the deck's particles.
#include <doctest/doctest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "engine/check.hpp"
#include "preproc/preview.hpp"
#include "preproc/sph_mesh_box.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_sph_mesh_box_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string box_deck = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/preview/mesh_box.k";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("mesh box: NX x NY x NZ particles at the cell centres, each with its cell's volume") {
    const engine::CheckResult r = engine::check_file(box_deck);
    const preproc::MeshBoxParticles g = preproc::generate_mesh_box_particles(r.model);
    REQUIRE(g.boxes.size() == 3);
    CHECK(g.boxes[0].particles == 24);
    CHECK(g.boxes[0].part == 1);
    CHECK(g.boxes[0].dx == doctest::Approx(0.5));
    CHECK(g.boxes[0].dy == doctest::Approx(1.0));
    CHECK(g.boxes[0].dz == doctest::Approx(2.0));
    REQUIRE(g.size() == 24);
    std::set<double> xs(g.x.begin(), g.x.end()), ys(g.y.begin(), g.y.end()), zs(g.z.begin(), g.z.end());
    CHECK(xs == std::set<double>{0.25, 0.75, 1.25, 1.75});
    CHECK(ys == std::set<double>{1.5, 2.5, 3.5});
    CHECK(zs == std::set<double>{-1.0, 1.0});
    for (double v : g.volume) CHECK(v == doctest::Approx(1.0));
    CHECK(std::all_of(g.part.begin(), g.part.end(), [](long long p) { return p == 1; }));
    // IDSEG removes particles the preview cannot place; NX 0 generates nothing.
    CHECK(g.boxes[1].particles == 0);
    CHECK(contains(g.boxes[1].skipped, "IDSEG"));
    CHECK(g.boxes[2].particles == 0);
    CHECK(contains(g.boxes[2].skipped, "NX, NY and NZ"));
}

TEST_CASE("mesh box: a box beyond the cap is not generated") {
    const engine::CheckResult r = engine::check_file(box_deck);
    const preproc::MeshBoxParticles g = preproc::generate_mesh_box_particles(r.model, 10);
    CHECK(g.size() == 0);
    CHECK(contains(g.boxes[0].skipped, "24 particles exceed"));
    // An absurd count is refused before any allocation.
    const engine::CheckResult big = engine::check_buffer(
        "*KEYWORD\n*DEFINE_SPH_MESH_BOX\n       0.0       0.0       0.0       1.0       1.0       1.0\n"
        "         1 100000000 100000000 100000000         0         0       0.0\n*END\n",
        "big.k");
    const preproc::MeshBoxParticles gb = preproc::generate_mesh_box_particles(big.model);
    CHECK(gb.size() == 0);
    REQUIRE(gb.boxes.size() == 1);
    CHECK(contains(gb.boxes[0].skipped, "exceed"));
}

TEST_CASE("mesh box: the preview takes the generated particles like the deck's own") {
    const engine::CheckResult r = engine::check_file(box_deck);
    const preproc::MeshBoxParticles g = preproc::generate_mesh_box_particles(r.model);
    const model::Model m = preproc::with_mesh_box_particles(r.model, g);
    CHECK(m.particles.size() == r.model.particles.size() + 24);
    const preproc::Preview p = preproc::compute_preview(m);
    REQUIRE(p.parts.size() == 1);
    CHECK(p.parts[0].particles == 24);
    CHECK(p.parts[0].mass_total == doctest::Approx(24 * 1000.0));  // RO 1000 x cell volume 1
    CHECK(p.parts[0].spacing == doctest::Approx(0.5));
    CHECK(std::all_of(p.particles.located.begin(), p.particles.located.end(), [](auto l) { return l == 1; }));
}

TEST_CASE("smooth command: *DEFINE_SPH_MESH_BOX particles are previewed") {
    test::TempDir dir;
    const test::Run run = test::run_sphdeck(dir, "smooth '" + box_deck + "'");
    INFO(run.out, run.err);
    CHECK(run.exit_code == 0);
    CHECK(contains(run.out, "24 particles in 1 part(s)"));
    CHECK(contains(run.out,
                   "*DEFINE_SPH_MESH_BOX: 24 particles of part 1 (4 x 3 x 2, cells 0.5 x 1 x 2) included above"));
    CHECK(contains(run.out, "*DEFINE_SPH_MESH_BOX of part 1: not previewed: IDSEG is set"));
}

TEST_CASE("smooth command: --format json lists the mesh boxes") {
    test::TempDir dir;
    const test::Run run = test::run_sphdeck(dir, "smooth --format json '" + box_deck + "'");
    INFO(run.out, run.err);
    REQUIRE(run.exit_code == 0);
    const auto j = nlohmann::json::parse(run.out);
    CHECK(j["particles"] == 24);
    REQUIRE(j["mesh_boxes"].size() == 3);
    CHECK(j["mesh_boxes"][0]["particles"] == 24);
    CHECK(j["mesh_boxes"][0]["counts"] == nlohmann::json::array({4, 3, 2}));
    CHECK(j["mesh_boxes"][0]["skipped"] == "");
    CHECK(j["mesh_boxes"][1]["particles"] == 0);
    CHECK(j["mesh_boxes"][1]["skipped"].get<std::string>().find("IDSEG") != std::string::npos);
}
}  // namespace test_sph_mesh_box_cpp
