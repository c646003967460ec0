// The typed model built from decoded cards.
#include <doctest/doctest.h>

#include "engine/check.hpp"
#include "test_support.hpp"

namespace test_model_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

TEST_CASE("model: controls, sections, parts and particles of the demo deck") {
    auto r = engine::check_file(std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/dam_break_2d.k");
    const model::Model& m = r.model;
    CHECK(m.controls.sph.present);
    CHECK(m.controls.sph.idim.value == model::Dimension::PlaneStrain);
    CHECK(m.controls.sph.form.value == model::Form::EnhancedFluid);
    CHECK(m.controls.sph.form.explicit_value);
    CHECK(m.controls.endtim.value == doctest::Approx(1.0));
    REQUIRE(m.sections.size() == 1);
    CHECK(m.sections[0].cslh.value == doctest::Approx(1.2));
    REQUIRE(m.parts.size() == 1);
    CHECK(m.parts[0].section.value == "1");
    CHECK(m.parts[0].eos.value == "1");
    CHECK(m.particles.size() == 3200);
    CHECK(m.nodes.id.size() == 3200);
    CHECK(m.symmetry_planes.size() == 3);
    CHECK(m.materials.at(0).density.value == doctest::Approx(1000.0));
}

TEST_CASE("model: blank fields take defaults and say so; zero means default where documented") {
    auto r = engine::check_buffer(
        "*KEYWORD\n*CONTROL_SPH\n                              2\n*SECTION_SPH\n         1       0.0\n", "d.k");
    const auto& c = r.model.controls.sph;
    CHECK(c.ncbs.value == 1);
    CHECK_FALSE(c.ncbs.explicit_value);
    CHECK(c.memory.value == 150);
    CHECK(c.idim.value == model::Dimension::PlaneStrain);
    CHECK(c.idim.explicit_value);
    CHECK(c.idim.span.column == 31);
    REQUIRE(r.model.sections.size() == 1);
    CHECK(r.model.sections[0].cslh.value == doctest::Approx(1.2));  // CSLH 0 = default (Workbench writes it)
}

TEST_CASE("model: IDIM 0 is a warning without a default, not an out-of-range error") {
    auto r = engine::check_buffer("*KEYWORD\n*CONTROL_SPH\n                             0\n", "d.k");
    CHECK(count_code(r.diagnostics, "DK007") == 0);
    REQUIRE(count_code(r.diagnostics, "DK008") == 1);
    CHECK(test::find_code(r.diagnostics, "DK008")->severity == diag::Severity::Warning);
}

TEST_CASE("model: NEND generates particles; *SET_NODE_LIST_TITLE members exclude the header") {
    auto r = engine::check_buffer(
        "*KEYWORD\n*NODE\n       1\n       2\n       3\n*ELEMENT_SPH\n       1       1          1.0e-3       3\n"
        "*SET_NODE_LIST_TITLE\noutlet\n         6\n         1         2\n",
        "d.k");
    CHECK(r.model.particles.size() == 3);
    CHECK(r.summary.particles == 3);
    REQUIRE(r.model.node_sets.size() == 1);
    CHECK(r.model.node_sets[0].members == std::vector<long long>{1, 2});
    CHECK(count_code(r.diagnostics, "REF001") == 0);
}

TEST_CASE("model: ids may be labels and numbers are normalised") {
    CHECK(model::normalise_id("  0001 ") == "1");
    CHECK(model::normalise_id("water") == "water");
}
}  // namespace test_model_cpp
