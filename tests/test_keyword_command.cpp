// `sphdeck keyword`: runs the built binary and checks what it prints and returns.
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace test_keyword_command_cpp {  // each test file's names stay its own in a unity batch

namespace {

struct Run {
    std::string output;  // stdout and stderr together
    int exit_code = -1;
};

// Runs `sphdeck ARGS` through the shell (arguments are single-quoted by the caller).
Run sphdeck(const std::string& args) {
    Run r;
    const std::string command = std::string("'") + SPHDECK_BINARY + "' " + args + " 2>&1";
    std::FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("keyword command: *CONTROL_SPH prints its cards, columns, defaults and FORM values") {
    const Run r = sphdeck("keyword '*CONTROL_SPH'");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "*CONTROL_SPH"));
    CHECK(contains(r.output, "Card 1"));
    CHECK(contains(r.output, "Card 2 (optional"));
    CHECK(contains(r.output, "NCBS"));
    CHECK(contains(r.output, "1-10"));
    CHECK(contains(r.output, "71-80"));
    CHECK(contains(r.output, "MEMORY (NMNEIGH)"));
    CHECK(contains(r.output, "150 (0 = default)"));
    CHECK(contains(r.output, "12 = moving-least-squares"));
    CHECK(contains(r.output, "-2 = 2D axisymmetric"));
}

TEST_CASE("keyword command: names are found without '*', in lower case and with options") {
    const Run lower = sphdeck("keyword control_sph");
    CHECK(lower.exit_code == 0);
    CHECK(contains(lower.output, "*CONTROL_SPH"));

    const Run section = sphdeck("keyword '*SECTION_SPH_ELLIPSE_TITLE'");
    INFO(section.output);
    CHECK(section.exit_code == 0);
    CHECK(contains(section.output, "*SECTION_SPH_ELLIPSE_TITLE"));
    CHECK(contains(section.output, "TITLE"));
    CHECK(contains(section.output, "HXCSLH"));  // the _ELLIPSE card
}

TEST_CASE("keyword command: an alias resolves to the canonical keyword") {
    const Run r = sphdeck("keyword mat_009");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "*MAT_NULL"));
    CHECK(contains(r.output, "aliases: *MAT_009"));
    CHECK(contains(r.output, "RO"));
}

TEST_CASE("keyword command: --format long shows widened columns") {
    const Run r = sphdeck("keyword '*CONTROL_SPH' --format long");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "1-20 "));
    CHECK(contains(r.output, "141-160"));
}

TEST_CASE("keyword command: an unknown keyword exits 2 with a suggestion") {
    const Run typo = sphdeck("keyword '*CONTRL_SPH'");
    INFO(typo.output);
    CHECK(typo.exit_code == 2);
    CHECK(contains(typo.output, "unknown keyword '*CONTRL_SPH'"));
    CHECK(contains(typo.output, "did you mean *CONTROL_SPH?"));

    const Run option = sphdeck("keyword '*CONTROL_SPH_BOGUS'");
    INFO(option.output);
    CHECK(option.exit_code == 2);
    CHECK(contains(option.output, "no option _BOGUS"));
}

TEST_CASE("keyword command: --list names every keyword with its aliases") {
    const Run r = sphdeck("keyword --list");
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "*CONTROL_SPH "));
    CHECK(contains(r.output, "*MAT_NULL (*MAT_009)"));
    CHECK(contains(r.output, "*ELEMENT_SPH"));
}

TEST_CASE("keyword command: keywords without a hand-written schema show their generated layout") {
    const Run list = sphdeck("keyword --list");
    CHECK(contains(list.output, "*CONTROL_SPH_INCOMPRESSIBLE"));
    CHECK(contains(list.output, "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE"));

    const Run r = sphdeck("keyword '*CONTROL_IMPLICIT_AUTO'");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "layout generated from pydyna"));
    CHECK(contains(r.output, "read only when IAUTO == 3"));
    CHECK(contains(r.output, "further lines are not checked"));

    const Run contact = sphdeck("keyword '*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE'");
    CHECK(contains(contact.output, "an id of a DEFINE_BOX"));  // SABOXID, from pydyna's links
}

TEST_CASE("keyword command: an OpenRadioss card prints its formats, cells, notes and source") {
    const Run r = sphdeck("keyword /sphglo");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.output, "/SPHGLO  (OpenRadioss starter keyword)"));
    CHECK(contains(r.output, "source: CFG radioss2017/CARDS/sphglo.cfg"));
    CHECK(contains(r.output, "format 2017 (decks of Invers 2017 and later)"));
    CHECK(contains(r.output, "format 120 (decks of Invers 120 to 2016)"));
    CHECK(contains(r.output, "in V4 decks (Invers below 51) integers are 8 and reals 16 wide"));
    CHECK(contains(r.output, "  1-20     Alpha_sort  real     0: 0.25"));
    CHECK(contains(r.output, "  51-60    Isol2sph    integer  0: 1"));

    // A LIST card and its count; an alias and a header with ids.
    const Run list = sphdeck("keyword /INISPHCEL/FULL");
    INFO(list.output);
    CHECK(contains(list.output, "LIST: nvarsph values in all, 5 a line"));
    CHECK(contains(list.output, "cards 1-5 repeat as a group"));
    CHECK(contains(sphdeck("keyword /PROP/TYPE34/7").output, "/PROP/SPH  (OpenRadioss starter keyword)"));
    // Engine cards are list-directed: no columns.
    CHECK(contains(sphdeck("keyword /DT/SPHCEL").output, "values list-directed"));
}

TEST_CASE("keyword command: an unknown OpenRadioss card exits 2 with a suggestion") {
    const Run r = sphdeck("keyword /SPHGLOB");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.output, "unknown OpenRadioss keyword '/SPHGLOB'; did you mean /SPHGLO?"));
}

TEST_CASE("keyword command: --list shows the Radioss cards; --solver keeps one solver's") {
    const Run all = sphdeck("keyword --list");
    CHECK(contains(all.output, "/SPHGLO "));
    CHECK(contains(all.output, "/PROP/SPH (/PROP/TYPE34)"));
    CHECK(contains(all.output, "*CONTROL_SPH "));
    const Run radioss = sphdeck("keyword --list --solver radioss");
    CHECK(contains(radioss.output, "[radioss starter] global SPH parameters"));
    CHECK(contains(radioss.output, "[radioss engine] particle time step"));
    CHECK(!contains(radioss.output, "*CONTROL_SPH"));
    const Run dyna = sphdeck("keyword --list --solver lsdyna");
    CHECK(contains(dyna.output, "*CONTROL_SPH "));
    CHECK(!contains(dyna.output, "/SPHGLO"));
    CHECK(sphdeck("keyword --list --solver abaqus").exit_code != 0);
}
}  // namespace test_keyword_command_cpp
