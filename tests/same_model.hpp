// Two readings of one deck compared as the tests of decoding and re-checking need: every bulk column of
// the model (nodes, particles, their lines) and the findings in order (code, message, place, notes).
#pragma once

#include <doctest/doctest.h>

#include <vector>

#include "diag/diagnostic.hpp"
#include "model/model.hpp"

namespace sphdeck::test {

inline void check_same_bulk_columns(const model::Model& got, const model::Model& expected) {
    CHECK(got.nodes.id == expected.nodes.id);
    CHECK(got.nodes.x == expected.nodes.x);
    CHECK(got.nodes.y == expected.nodes.y);
    CHECK(got.nodes.z == expected.nodes.z);
    CHECK(got.particles.node == expected.particles.node);
    CHECK(got.particles.part == expected.particles.part);
    CHECK(got.particles.mass == expected.particles.mass);
    CHECK(got.particles.volume == expected.particles.volume);
    CHECK(got.particles.line == expected.particles.line);
}

inline void check_same_findings(const std::vector<diag::Diagnostic>& got,
                                const std::vector<diag::Diagnostic>& expected) {
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        CAPTURE(expected[i].message);
        CHECK(got[i].code == expected[i].code);
        CHECK(got[i].message == expected[i].message);
        CHECK(got[i].span.line == expected[i].span.line);
        CHECK(got[i].span.column == expected[i].span.column);
        CHECK(got[i].span.end_column == expected[i].span.end_column);
        CHECK(got[i].notes.size() == expected[i].notes.size());
    }
}

}  // namespace sphdeck::test
