// `sphdeck smooth`: runs the built binary on the demo dam break (3200 particles on a 0.015 m
// lattice, CSLH 1.2: h0 = 0.018) and checks the table, the JSON, and the CSV, VTK and SVG files.
#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace sphdeck::test {
// Defined in test_io_writers.cpp.
bool python_available();
std::string validate_vtp(const std::string& path, std::size_t points, std::string* names);
bool xml_well_formed(const std::string& path);
}  // namespace sphdeck::test

using namespace sphdeck::test;

namespace {

const std::string demo = std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/dam_break_2d.k";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::size_t count_lines(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

// Runs a Python check (asserts) on the JSON document `json`; "" when it passes.
std::string check_json(const TempDir& dir, const std::string& json, const std::string& asserts) {
    dir.write("out.json", json);
    const std::string script = dir.write("check.py", "import json, sys\nd = json.load(open(sys.argv[1]))\n" + asserts);
    const std::string log = (dir.path() / "check.log").string();
    const std::string command =
        "python3 '" + script + "' '" + (dir.path() / "out.json").string() + "' > '" + log + "' 2>&1";
    if (std::system(command.c_str()) == 0) return "";
    std::ifstream in(log);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_CASE("smooth command: the table has one aligned row per part with h0 and its bounds") {
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());  // no progress bar when stderr is no terminal
    CHECK(contains(r.out, "3200 particles in 1 part(s), 2D, INI 0 (bucket sort, from *CONTROL_SPH)"));
    CHECK(contains(r.out, "part  particles  mass  spacing     h0   h_min  h_max  neighbours         dt  ini"));
    CHECK(contains(r.out, "   1       3200   720    0.015  0.018  0.0036  0.036     7/20/20"));
}

TEST_CASE("smooth command: without *CONTROL_SPH the header says the defaults apply, not where they come from") {
    std::ifstream in(demo, std::ios::binary);
    std::string text(std::istreambuf_iterator<char>(in), {});
    const std::size_t at = text.find("*CONTROL_SPH\n");
    REQUIRE(at != std::string::npos);
    const std::size_t next = text.find("\n*", at + 1);
    REQUIRE(next != std::string::npos);
    text.erase(at, next + 1 - at);  // the keyword and its cards
    TempDir dir;
    const std::string deck = dir.write("no_control.k", text);
    const Run r = run_sphdeck(dir, "smooth '" + deck + "'");
    INFO(r.out, r.err);
    CHECK(contains(r.out, "3200 particles in 1 part(s), 3D, INI 0 (bucket sort, default: no *CONTROL_SPH)"));
    CHECK_FALSE(contains(r.out, "from *CONTROL_SPH"));
}

TEST_CASE("smooth command: --format json gives particles, per-part h0 and statistics") {
    if (!python_available()) return;
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth --format json '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    CHECK(check_json(dir, r.out,
                     "assert d['particles'] == 3200\n"
                     "assert d['dimension'] == 2 and d['ini_forced'] is False\n"
                     "p = d['parts'][0]\n"
                     "assert len(d['parts']) == 1 and p['part'] == 1 and p['particles'] == 3200\n"
                     "assert abs(p['h0'] - 1.2 * 0.015) < 0.01 * 0.018, p['h0']\n"
                     "assert abs(p['h_min'] - 0.2 * p['h0']) < 1e-12 and abs(p['h_max'] - 2 * p['h0']) < 1e-12\n"
                     "assert abs(p['mass_total'] - 720) < 1e-6\n"
                     "assert abs(p['nn_distance']['median'] - 0.015) < 1e-9\n"
                     "assert p['neighbours'] == {'min': 7, 'median': 20, 'max': 20}\n"
                     "assert p['dt_estimate'] > 0 and p['ini'] == 0 and p['notes'] == []\n") == "");
}

TEST_CASE("smooth command: --ini forces the mode; INI 2 takes h0 from the particle volume") {
    if (!python_available()) return;
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth --format json --ini 2 '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    // V = 0.225 kg / 1000 kg/m3 per unit thickness; sqrt(V) = 0.015 m.
    CHECK(check_json(dir, r.out,
                     "p = d['parts'][0]\n"
                     "assert d['ini_forced'] is True and p['ini'] == 2, p['ini']\n"
                     "assert abs(p['h0'] - 0.018) < 0.01 * 0.018, p['h0']\n") == "");

    const Run table = run_sphdeck(dir, "smooth --ini 1 '" + demo + "'");
    CHECK(table.exit_code == 0);
    CHECK(contains(table.out, "INI 1 (global search, forced by --ini)"));

    const Run bad = run_sphdeck(dir, "smooth --ini 3 '" + demo + "'");
    CHECK(bad.exit_code == 2);
}

TEST_CASE("smooth command: --csv writes a header and one row per particle") {
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth --csv particles.csv '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    const std::string path = (dir.path() / "particles.csv").string();
    CHECK(count_lines(path) == 3201);
    std::ifstream in(path, std::ios::binary);
    std::string header, first;
    std::getline(in, header);
    std::getline(in, first);
    CHECK(header == "id,part,x,y,z,mass,nn_distance,h,neighbours\r");
    CHECK(first ==
          "1,1,0.0074999999999999997,0.0074999999999999997,0,0.22500000000000001,0.014999999999999999,"
          "0.018000000000000016,7\r");
    CHECK(contains(r.out, "wrote particles.csv (3200 particles)"));
}

TEST_CASE("smooth command: --vtk writes PolyData that validates, in ASCII and base64") {
    if (!python_available()) return;
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth --format json --vtk ascii.vtp '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    CHECK(contains(r.err, "wrote ascii.vtp (3200 points)"));  // stdout holds only the JSON
    std::string names;
    CHECK(validate_vtp((dir.path() / "ascii.vtp").string(), 3200, &names) == "");
    CHECK(names == "h id mass neighbours nn_distance part");

    const Run binary = run_sphdeck(dir, "smooth --vtk binary.vtp --vtk-binary '" + demo + "'");
    CHECK(binary.exit_code == 0);
    CHECK(validate_vtp((dir.path() / "binary.vtp").string(), 3200, nullptr) == "");
}

TEST_CASE("smooth command: --plot writes a well-formed SVG with both histograms of the part") {
    TempDir dir;
    const Run r = run_sphdeck(dir, "smooth --plot plot.svg '" + demo + "'");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    const std::string path = (dir.path() / "plot.svg").string();
    std::ifstream in(path, std::ios::binary);
    const std::string svg((std::istreambuf_iterator<char>(in)), {});
    CHECK(contains(svg, "part 1: h / nearest-neighbour distance"));
    CHECK(contains(svg, "part 1: neighbours"));
    if (python_available()) CHECK(xml_well_formed(path));
}

TEST_CASE("smooth command: a deck without particles, or no deck at all, exits with 2") {
    TempDir dir;
    dir.write("empty.k", "*KEYWORD\n*CONTROL_SPH\n         1\n*END\n");
    const Run r = run_sphdeck(dir, "smooth empty.k");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 2);
    CHECK(contains(r.err, "empty.k: no SPH particles (*ELEMENT_SPH): nothing to preview"));
    CHECK(r.out.empty());

    const Run missing = run_sphdeck(dir, "smooth missing.k");
    CHECK(missing.exit_code == 2);
    CHECK(contains(missing.err, "missing.k"));

    const Run unwritable = run_sphdeck(dir, "smooth --csv /nonexistent-folder/p.csv '" + demo + "'");
    CHECK(unwritable.exit_code == 2);
    CHECK(contains(unwritable.err, "cannot open '/nonexistent-folder/p.csv' for writing"));
}

TEST_CASE("smooth command: parts are listed in id order, each with its own spacing") {
    TempDir dir;
    // Two 2x2 blocks: part 1 at spacing 0.1, part 2 at 0.2, far apart; CSLH 1.2 on section 1.
    dir.write("two.k",
              "*KEYWORD\n*CONTROL_SPH\n         1         0     1e+20         3\n"
              "*SECTION_SPH\n         1       1.2       0.2       2.0\n"
              "*PART\nblock a\n         1         1\n*PART\nblock b\n         2         1\n"
              "*NODE\n"
              "       1             0.0             0.0             0.0\n"
              "       2             0.1             0.0             0.0\n"
              "       3             0.0             0.1             0.0\n"
              "       4             0.1             0.1             0.0\n"
              "       5            10.0             0.0             0.0\n"
              "       6            10.2             0.0             0.0\n"
              "       7            10.0             0.2             0.0\n"
              "       8            10.2             0.2             0.0\n"
              "*ELEMENT_SPH\n"
              "       5       2     1.0\n       6       2     1.0\n       7       2     1.0\n       8       2     1.0\n"
              "       1       1     1.0\n       2       1     1.0\n       3       1     1.0\n       4       1     1.0\n"
              "*END\n");
    const Run r = run_sphdeck(dir, "smooth two.k --plot two.svg");
    INFO(r.out, r.err);
    CHECK(r.exit_code == 0);
    const std::size_t one = r.out.find("\n   1          4"), two = r.out.find("\n   2          4");
    CHECK(one != std::string::npos);
    CHECK(two != std::string::npos);
    CHECK(one < two);
    // Column widths may change; the values on each part's row may not: h0 then HMIN*h0 follow
    // the spacing (0.1 and 0.2), so "0.1 0.12" and "0.2 0.24" appear with blanks between.
    auto squeezed = [](std::string text) {
        std::string out;
        for (char c : text)
            if (c != ' ' || out.empty() || out.back() != ' ') out += c;
        return out;
    };
    CHECK(contains(squeezed(r.out), "0.1 0.12"));
    CHECK(contains(squeezed(r.out), "0.2 0.24"));
    std::ifstream in(dir.path() / "two.svg", std::ios::binary);
    const std::string svg((std::istreambuf_iterator<char>(in)), {});
    CHECK(contains(svg, "part 2: neighbours"));
}
