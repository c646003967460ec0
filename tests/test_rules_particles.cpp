// SPH081-SPH117 beyond the deck fixtures: grouping over many particles, field columns in
// free format, and what counts as an initial speed.
#include <doctest/doctest.h>

#include <string>

#include "engine/check.hpp"
#include "test_support.hpp"

namespace test_rules_particles_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;

namespace {

std::string head(const std::string& idim = "3") {
    return "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20" + std::string(10 - idim.size(), ' ') + idim +
           "       150        15\n*SECTION_SPH\n         1\n*PART\nwater\n         1         1         1         1\n"
           "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0  340000.0       1.0\n";
}

// n nodes along x, spacing 0.1, at height z.
std::string nodes(int first, int n, double z = 0.0) {
    std::string s = "*NODE\n";
    for (int i = 0; i < n; ++i) {
        char line[80];
        std::snprintf(line, sizeof line, "%8d%16.4f%16.4f%16.4f\n", first + i, 0.1 * i, 0.0, z);
        s += line;
    }
    return s;
}

}  // namespace

TEST_CASE("SPH112: many massless particles of one part make one finding with the count") {
    const int n = 100000;
    std::string deck = head() + nodes(1, n) + "*ELEMENT_SPH\n       1       1\n";
    deck += "       2       1             0.0" + std::to_string(n).insert(0, 8 - std::to_string(n).size(), ' ') + "\n";
    auto r = engine::check_buffer(deck, "d.k");  // NEND: particles 2..n from one line, MASS 0
    REQUIRE(count_code(r.diagnostics, "SPH112") == 1);
    const diag::Diagnostic* d = find_code(r.diagnostics, "SPH112");
    CHECK(d->severity == diag::Severity::Error);
    CHECK(d->message.find("100000 particles of part 1 (1, 2, 3, 4, 5, ...)") != std::string::npos);
    CHECK(d->span.column == 17);  // MASS, columns 17-32, blank on the first particle
}

TEST_CASE("SPH112: the MASS field is found in free format; a volume is information") {
    auto r = engine::check_buffer(head() + nodes(1, 1) + "*ELEMENT_SPH\n1,1,-1.0e-3\n", "d.k");
    const diag::Diagnostic* d = find_code(r.diagnostics, "SPH112");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Info);
    CHECK(d->span.column == 5);
}

TEST_CASE("SPH110: one finding for all particles off the plane, with the count") {
    std::string deck = head("2") + nodes(1, 3, 0.0) + nodes(4, 3, 2.0) +
                       "*ELEMENT_SPH\n1,1,1.0\n2,1,1.0\n3,1,1.0\n4,1,1.0\n5,1,1.0\n6,1,1.0\n";
    auto r = engine::check_buffer(deck, "d.k");
    REQUIRE(count_code(r.diagnostics, "SPH110") == 1);
    const diag::Diagnostic* d = find_code(r.diagnostics, "SPH110");
    CHECK(d->message.find("3 particles") != std::string::npos);
    CHECK(d->message.find("4, 5, 6") != std::string::npos);
    CHECK(d->span.column == 41);  // at the node's Z field, the value a person typed
    REQUIRE(!d->notes.empty());
    CHECK(d->notes[0].message.find("the particle of node 4") != std::string::npos);
    CHECK(d->notes[0].span.line > d->span.line);      // its *ELEMENT_SPH line, below the nodes
    CHECK(count_code(r.diagnostics, "SPH111") == 0);  // IDIM 2: negative x is not checked
}

TEST_CASE("SPH117: an initial velocity counts only on the nodes of its set") {
    const std::string particle = nodes(1, 1) + nodes(50, 1, 5.0) + "*ELEMENT_SPH\n       1       1             1.0\n";
    auto velocity = [](const std::string& nsid) {
        return "*INITIAL_VELOCITY\n" + std::string(10 - nsid.size(), ' ') + nsid + "\n      20.0\n";
    };
    const std::string sets = "*SET_NODE_LIST\n         7\n        50\n*SET_NODE_LIST\n         8\n         1\n";
    auto other = engine::check_buffer(head() + particle + sets + velocity("7"), "d.k");
    CHECK(count_code(other.diagnostics, "SPH117") == 0);  // node 50 is no particle
    auto own = engine::check_buffer(head() + particle + sets + velocity("8"), "d.k");
    REQUIRE(count_code(own.diagnostics, "SPH117") == 1);
    CHECK(find_code(own.diagnostics, "SPH117")->message.find("10 x 20") != std::string::npos);
    auto all = engine::check_buffer(head() + particle + sets + velocity("0"), "d.k");
    CHECK(count_code(all.diagnostics, "SPH117") == 1);
}

TEST_CASE("SPH117: gravity counts only with a constant curve") {
    const std::string particles = nodes(1, 1) + nodes(2, 1, 10.0) +
                                  "*ELEMENT_SPH\n       1       1             1.0\n       2       1             1.0\n";
    auto gravity = [](const std::string& o2) {
        return "*LOAD_BODY_Z\n         1      9.81\n*DEFINE_CURVE\n         1\n                 0.0                 1.0\n"
               "               100.0" +
               std::string(20 - o2.size(), ' ') + o2 + "\n";
    };
    auto constant = engine::check_buffer(head() + particles + gravity("1.0"), "d.k");
    REQUIRE(count_code(constant.diagnostics, "SPH117") == 1);
    CHECK(find_code(constant.diagnostics, "SPH117")->message.find("free-fall") != std::string::npos);
    auto ramp = engine::check_buffer(head() + particles + gravity("2.0"), "d.k");
    CHECK(count_code(ramp.diagnostics, "SPH117") == 0);
}
}  // namespace test_rules_particles_cpp
