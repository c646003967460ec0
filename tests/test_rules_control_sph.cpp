// The *CONTROL_SPH rules where the deck-driven tests cannot reach: severities and messages that
// depend on the run type (--solver), the over-a-million-particles case, and raw keyword readings.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include "engine/check.hpp"
#include "lint/rules.hpp"
#include "test_support.hpp"

namespace test_rules_control_sph_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// A minimal fluid deck: one particle of a *MAT_NULL + *EOS_MURNAGHAN part, with the given
// *CONTROL_SPH cards (card 1 first) and extra keywords before *END.
std::string fluid_deck(const std::string& control_sph, const std::string& extra = "",
                       const std::string& keyword = "*KEYWORD") {
    return keyword +
           "\n"
           "*CONTROL_TERMINATION\n"
           "       1.0\n"
           "*CONTROL_SPH\n" +
           control_sph +
           "*CONTROL_BULK_VISCOSITY\n"
           "       1.0       1.0\n"
           "*SECTION_SPH\n"
           "         1       1.2       1.0       1.0\n"
           "*PART\n"
           "water\n"
           "         1         1         1         1\n"
           "*MAT_NULL\n"
           "         1    1000.0\n"
           "*EOS_MURNAGHAN\n"
           "         1       7.0    1.0e+7       1.0\n"
           "*NODE\n"
           "       1             0.0             0.0             0.0\n"
           "*ELEMENT_SPH\n"
           "       1       1           0.001\n" +
           extra + "*END\n";
}

const std::string form12 = "         1         0   1.0e+20         3       150        12       0.0   1.0e+15\n";
const std::string form9 = "         1         0   1.0e+20         3       150         9       0.0   1.0e+15\n";

engine::CheckResult run(const std::string& text, lint::Solver solver = lint::Solver::Unknown,
                        const std::string& source = "") {
    engine::CheckOptions o;
    o.rules.solver = solver;
    o.rules.solver_source = source;
    return engine::check_buffer(text, "deck.k", o);
}

// Deck with the plain *SECTION_SPH swapped for an ellipse section (FORM 9/10 decks).
std::string with_ellipse(std::string text) {
    const std::string plain = "*SECTION_SPH\n         1       1.2       1.0       1.0\n";
    text.replace(text.find(plain), plain.size(),
                 "*SECTION_SPH_ELLIPSE\n         1       1.2       1.0       1.0\n       1.2       1.2       1.2\n");
    return text;
}

}  // namespace

TEST_CASE("SPH010: FORM 12 is an error on SMP, information when the run type is unknown, silent on MPP") {
    SUBCASE("unknown: information naming the missing evidence (the run type is not in the deck)") {
        auto r = run(fluid_deck(form12));
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH010");
        REQUIRE(d);
        CHECK(d->severity == diag::Severity::Info);
        CHECK(d->message ==
              "FORM 12 (MLS) runs only in MPP; nothing shows this is an MPP run (no --solver, no *CONTROL_MPP_*, no "
              "memory2=)");
        CHECK(d->span.line == 5);
        CHECK(d->span.column >= 51);
        CHECK(d->span.end_column <= 61);
    }
    SUBCASE("--solver smp: error naming the option") {
        auto r = run(fluid_deck(form12), lint::Solver::Smp, "--solver");
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH010");
        REQUIRE(d);
        CHECK(d->severity == diag::Severity::Error);
        CHECK(d->message == "FORM 12 (MLS) runs only in MPP; the run is SMP (--solver smp)");
    }
    SUBCASE("smp from the configuration file, even with MPP keywords in the deck") {
        auto r = run(fluid_deck(form12, "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS\n"), lint::Solver::Smp,
                     "/project/sphdeck.toml");
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH010");
        REQUIRE(d);
        CHECK(d->severity == diag::Severity::Error);
        CHECK(d->message ==
              "FORM 12 (MLS) runs only in MPP; the run is SMP (solver = \"smp\" in /project/sphdeck.toml)");
    }
    SUBCASE("FORM 13 as well") {
        std::string form13 = form12;
        form13.replace(form13.find("12"), 2, "13");
        auto r = run(fluid_deck(form13), lint::Solver::Smp);
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH010");
        REQUIRE(d);
        CHECK(d->message == "FORM 13 (ISPH) runs only in MPP; the run is SMP (--solver smp)");
    }
    SUBCASE("--solver mpp: silent") {
        auto r = run(fluid_deck(form12), lint::Solver::Mpp, "--solver");
        CHECK(test::count_code(r.diagnostics, "SPH010") == 0);
    }
    SUBCASE("deck evidence: *CONTROL_MPP_ keyword or memory2=") {
        CHECK(test::count_code(
                  run(fluid_deck(form12, "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS\n")).diagnostics,
                  "SPH010") == 0);
        CHECK(test::count_code(run(fluid_deck(form12, "", "*KEYWORD memory2=20m")).diagnostics, "SPH010") == 0);
    }
    SUBCASE("other forms: silent whatever the solver") {
        std::string form1 = form12;
        form1.replace(form1.find("12"), 2, " 1");
        CHECK(test::count_code(run(fluid_deck(form1), lint::Solver::Smp).diagnostics, "SPH010") == 0);
    }
}

TEST_CASE("SPH022: FORM 9 on a run known to be MPP") {
    SUBCASE("--solver mpp") {
        auto r = run(with_ellipse(fluid_deck(form9)), lint::Solver::Mpp, "--solver");
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH022");
        REQUIRE(d);
        CHECK(d->severity == diag::Severity::Error);
        CHECK(d->message == "FORM 9 (ASPH) runs only in SMP; the run is MPP (--solver mpp)");
        CHECK(d->notes.empty());
        CHECK(test::count_code(r.diagnostics, "SPH020") == 0);
    }
    SUBCASE("memory2= on *KEYWORD, with a note there") {
        auto r = run(with_ellipse(fluid_deck(form9, "", "*KEYWORD memory2=20m")));
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH022");
        REQUIRE(d);
        CHECK(d->message == "FORM 9 (ASPH) runs only in SMP; the run is MPP (memory2= on *KEYWORD)");
        REQUIRE(d->notes.size() == 1);
        CHECK(d->notes[0].span.line == 1);
    }
    SUBCASE("--solver smp overrides the deck's MPP keywords") {
        auto r = run(with_ellipse(fluid_deck(form9, "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS\n")),
                     lint::Solver::Smp, "--solver");
        CHECK(test::count_code(r.diagnostics, "SPH022") == 0);
    }
}

TEST_CASE("SPH080: error, warning or info depending on DT, START and ENDTIM") {
    auto severity = [](const std::string& card1) {
        auto r = run(fluid_deck(card1));
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH080");
        return d ? std::optional<diag::Severity>(d->severity) : std::nullopt;
    };
    CHECK(severity("         1         0       0.1         3       150        15       0.1\n") ==
          diag::Severity::Error);
    CHECK(severity("         1         0                   3       150        15       1.5\n") ==
          diag::Severity::Warning);
    CHECK(severity("         1         0       0.5         3       150        15       0.0\n") == diag::Severity::Info);
    // DT 0 reads as the default 1e20 (zero means default for DT).
    CHECK(severity("         1         0       0.0         3       150        15       0.0\n") == std::nullopt);
}

TEST_CASE("SPH071: the count and the first five ids") {
    std::string nodes, particles;
    for (int i = 1; i <= 8; ++i) {
        nodes += fmt::format("{:>8}{:>16}{:>16}{:>16}\n", i + 1, fmt::format("{}.0", i + 1), "0.0", "0.0");
        particles += fmt::format("{:>8}{:>8}{:>16}\n", i + 1, i + 1, "0.001");
    }
    std::string parts;  // one part per particle keeps the preview rules quiet
    for (int i = 2; i <= 9; ++i) parts += fmt::format("p{}\n{:>10}{:>10}{:>10}{:>10}\n", i, i, 1, 1, 1);
    const std::string extra = "*PART\n" + parts + "*NODE\n" + nodes + "*ELEMENT_SPH\n" + particles +
                              "*DEFINE_BOX\n         1      -1.0       1.0      -1.0       1.0      -1.0       1.0\n";
    auto r =
        run(fluid_deck("         1         1   1.0e+20         3       150        15       0.0   1.0e+15\n", extra));
    const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH071");
    REQUIRE(d);
    CHECK(d->message ==
          "8 particles start outside box 1 and are deactivated at once (2, 3, 4, 5, 6, ...); expected every particle "
          "inside");
}

TEST_CASE("SPH072: *INITIAL_VELOCITY_NODE is read raw, per particle node") {
    const std::string card1 = "         1         0   1.0e+20         3       150        15       0.0      10.0\n";
    auto fires = run(fluid_deck(card1, "*INITIAL_VELOCITY_NODE\n         1      12.0       0.0       0.0\n"));
    const diag::Diagnostic* d = test::find_code(fires.diagnostics, "SPH072");
    REQUIRE(d);
    CHECK(
        d->message ==
        "initial speed 12.0 exceeds MAXV 10.0: those particles are deactivated at once; expected MAXV above every speed");
    // A node that is not a particle does not count.
    auto silent = run(fluid_deck(card1, "*INITIAL_VELOCITY_NODE\n         7      12.0       0.0       0.0\n"));
    CHECK(test::count_code(silent.diagnostics, "SPH072") == 0);
    // Nor does an *INITIAL_VELOCITY whose node set holds no particle.
    auto set = run(fluid_deck(card1,
                              "*SET_NODE_LIST\n         5\n         7\n*NODE\n       7             5.0             0.0"
                              "             0.0\n*INITIAL_VELOCITY\n         5\n      12.0\n"));
    CHECK(test::count_code(set.diagnostics, "SPH072") == 0);
}

TEST_CASE("SPH093: contact cards after the _ID and _MPP option cards") {
    const std::string sph =
        "         1         0   1.0e+20         3       150        15       0.0   1.0e+15\n"
        "         0         0         0         0         0         0         0       100\n"
        "         1         0      0.01\n";
    auto contact = [](const std::string& keyword, const std::string& before, const std::string& sstyp) {
        return keyword + "\n" + before + "         1         2" + sstyp +
               "         3\n       0.0       0.0\n"
               "       1.0       1.0      0.25       0.0\n";
    };
    auto count = [&](const std::string& c) { return test::count_code(run(fluid_deck(sph, c)).diagnostics, "SPH093"); };
    CHECK(count(contact("*CONTACT_AUTOMATIC_NODES_TO_SURFACE", "", "         3")) == 1);
    CHECK(count(contact("*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID", "        10wall contact\n", "         3")) == 1);
    CHECK(count(contact("*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID_MPP",
                        "        10\n         0       200\n&                  1\n", "         3")) == 1);
    // The slave side is a segment set: no particles there, ITHK is not involved.
    CHECK(count(contact("*CONTACT_AUTOMATIC_NODES_TO_SURFACE", "", "         0")) == 0);
    // ITHK 0: nothing to say.
    std::string ithk0 = sph;
    ithk0.replace(ithk0.rfind("         1         0      0.01"), 10, "         0");
    CHECK(test::count_code(
              run(fluid_deck(ithk0, contact("*CONTACT_AUTOMATIC_NODES_TO_SURFACE", "", "         3"))).diagnostics,
              "SPH093") == 0);
}

TEST_CASE("SPH091: out-of-range ISYMP is an error, ISYMP without planes an info") {
    auto severity = [](const std::string& isymp) {
        auto r =
            run(fluid_deck("         1         0   1.0e+20         3       150        15       0.0   1.0e+15\n"
                           "         0         0         0         0         0         0         0" +
                           isymp + "\n"));
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "SPH091");
        return d ? std::optional<diag::Severity>(d->severity) : std::nullopt;
    };
    CHECK(severity("         0") == diag::Severity::Error);
    CHECK(severity("       101") == diag::Severity::Error);
    CHECK(severity("        15") == diag::Severity::Info);
    CHECK(severity("       100") == std::nullopt);
}

TEST_CASE("SPH092: ISYMP 100 with symmetry planes and over a million particles") {
    // A deck of 1,000,001 particles is too big for the repository and slow to preview in a debug
    // build, so the family runs here on a model built directly: only the counts matter.
    model::Model m;
    m.controls.sph.present = true;
    m.symmetry_planes.push_back({});
    auto particles = [&m](std::size_t n) {
        m.particles.node.assign(n, 1);
        m.particles.part.assign(n, 1);
        m.particles.mass.assign(n, 0.001);
        m.particles.volume.assign(n, 0);
        m.particles.line.assign(n, 0);
    };
    auto findings = [&m](long long isymp) {
        m.controls.sph.isymp = model::Setting<long long>(isymp, isymp != 100, {});
        grammar::RawDeck deck;
        lint::RuleOptions options;
        std::vector<diag::Diagnostic> out;
        lint::RuleContext c(m, deck, options, out);
        lint::check_control_sph(c);
        return out;
    };
    particles(1'000'001);
    auto out = findings(100);
    const diag::Diagnostic* d = test::find_code(out, "SPH092");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Info);
    CHECK(d->message == "ISYMP 100 reserves ghosts for all 1000001 particles; expected 10 to 20 for a large model");
    CHECK(test::count_code(findings(15), "SPH092") == 0);
    particles(1'000'000);
    CHECK(test::count_code(findings(100), "SPH092") == 0);
    m.symmetry_planes.clear();
    particles(1'000'001);
    CHECK(test::count_code(findings(100), "SPH092") == 0);
}

TEST_CASE("SPH014: IHTC 1 needs CP and LAMBDA of the fluid; silent with IHTC 0 or a missing include") {
    const std::string control =
        "*KEYWORD\n*CONTROL_SPH_INCOMPRESSIBLE\n         0      0.01     1e+20     1e+20         {}\n";
    const std::string fluid = "*MAT_SPH_INCOMPRESSIBLE_FLUID\n         1    1000.0    1.0e-3\n    4180.0\n";
    auto with = [&](int ihtc, const std::string& more) {
        return test::count_code(
            engine::check_buffer(fmt::format(fmt::runtime(control), ihtc) + more, "d.k").diagnostics, "SPH014");
    };
    CHECK(with(1, fluid) == 1);                                               // LAMBDA blank
    CHECK(with(1, "") == 1);                                                  // no fluid material
    CHECK(with(1, fluid.substr(0, fluid.size() - 1) + "       0.6\n") == 0);  // both given
    CHECK(with(0, fluid) == 0);                                               // no heat transfer coefficients asked
    CHECK(with(1, "*INCLUDE\nfluids.k\n") == 0);                              // the fluid may be in the include
}
}  // namespace test_rules_control_sph_cpp
