// The Radioss reader and decoder (radioss-format.md §2-§5): lines, headers, versions and cell
// widths, free format, titles, #include, /END, the engine deck, and the model it fills.
#include <doctest/doctest.h>
#include <tao/pegtl/contrib/analyze.hpp>

#include <cmath>
#include <set>

#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/line_grammar.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/read_deck.hpp"
#include "engine/check.hpp"
#include "model/radioss_decoder.hpp"
#include "test_support.hpp"

namespace test_radioss_reader_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::radioss::read_buffer;
using test::count_code;
using test::find_code;

namespace {

std::string i10(const std::string& v) { return std::string(v.size() < 10 ? 10 - v.size() : 0, ' ') + v; }
std::string r20(const std::string& v) { return std::string(v.size() < 20 ? 20 - v.size() : 0, ' ') + v; }

// A starter deck of version `version` with `body` after /BEGIN.
std::string deck(const std::string& body, int version = 2026) {
    return "#RADIOSS STARTER\n/BEGIN\nrun\n" + i10(std::to_string(version)) + "\n" + body + "/END\n";
}

engine::CheckResult check(const std::string& text, const std::string& name = "deck_0000.rad") {
    return engine::check_buffer(text, name, {}, grammar::DeckFormat::Radioss);
}

const model::RadiossFacts& facts(const engine::CheckResult& r) {
    REQUIRE(r.model.radioss.has_value());
    return *r.model.radioss;
}

const std::string kWater = "/PART/2\nwater\n" + i10("2") + i10("3") + "\n/MAT/LAW6/3\nwater\n" + r20("1.0E-6") + "\n";

}  // namespace

TEST_CASE("radioss: the line grammar has no infinite loops") {
    CHECK(tao::pegtl::analyze<grammar::radioss::rules::file>(-1) == 0);
}

TEST_CASE("radioss: comment, header and data lines; the header path keeps its ids") {
    auto d = read_buffer(
        "#RADIOSS STARTER\n$ dollar comment\n/node\n# x\n  # indented hash is data\n"
        "         1                 0.0\n/PROP/Sph/7\n",
        "d.rad");
    REQUIRE(d.blocks.size() == 2);
    CHECK(d.blocks[0].keyword == "/NODE");
    CHECK(d.blocks[0].line_count == 2);
    CHECK(d.text(d.lines[d.blocks[0].first_line]) == "  # indented hash is data");
    CHECK(d.blocks[1].keyword == "/PROP/SPH/7");
    CHECK(d.blocks[1].arguments == "/PROP/Sph/7");
    CHECK(d.blocks[1].span.line == 7);
    CHECK(d.blocks[1].span.column == 1);
    CHECK(d.blocks[1].span.end_column == 12);
    CHECK(d.diagnostics.empty());
}

TEST_CASE("radioss: CRLF, a BOM, no final newline, trailing blank lines of a block") {
    auto d = read_buffer("\xEF\xBB\xBF#RADIOSS STARTER\r\n/NODE\r\n         1\r\n\r\n   \r\n/END", "d.rad");
    REQUIRE(d.blocks.size() == 2);
    CHECK(d.blocks[0].line_count == 1);  // the blank lines before /END are not cards
    CHECK(d.text(d.lines[0]) == "         1");
    CHECK(d.diagnostics.empty());
}

TEST_CASE("radioss: RAD001 when the first line is not a comment") {
    auto d = read_buffer("/BEGIN\nrun\n", "run_0000.rad");
    REQUIRE(count_code(d.diagnostics, "RAD001") == 1);
    CHECK(find_code(d.diagnostics, "RAD001")->span.line == 1);
    // Any comment may come first: the starter's reader takes it as a comment (issue 26, class I).
    CHECK(count_code(read_buffer("# my deck\n#RADIOSS STARTER\n/BEGIN\n", "run_0000.rad").diagnostics, "RAD001") == 0);
    CHECK(count_code(read_buffer("# RADIOSS \n/BEGIN\n", "run_0000.rad").diagnostics, "RAD001") == 0);
    CHECK(count_code(read_buffer("", "run_0000.rad").diagnostics, "RAD001") == 1);
    CHECK(count_code(read_buffer("#RADIOSS STARTER   \n", "run_0000.rad").diagnostics, "RAD001") == 0);
    CHECK(count_code(read_buffer("/RUN/run/1\n", "run_0001.rad").diagnostics, "RAD001") == 0);  // an engine deck
    // Another name is an include or a fragment, not a starter deck: no header asked for.
    CHECK(count_code(read_buffer("/BEGIN\n", "materials.rad").diagnostics, "RAD001") == 0);
    CHECK(count_code(read_buffer("/BEGIN\n", "parts.inc").diagnostics, "RAD001") == 0);
}

TEST_CASE("radioss: data before any header and an indented header are reported") {
    auto d = read_buffer("#RADIOSS STARTER\n  12   3\n   /NODE\n         1\n", "d.rad");
    CHECK(count_code(d.diagnostics, "DK027") == 1);
    CHECK(count_code(d.diagnostics, "DK020") == 1);
    REQUIRE(d.blocks.size() == 1);
    CHECK(d.blocks[0].keyword == "/NODE");
}

TEST_CASE("radioss: /END ends the deck, #enddata ends an included file") {
    auto d = read_buffer("#RADIOSS STARTER\n/NODE\n         1\n/END\n/NODE\n         2\n", "d.rad");
    CHECK(d.blocks.size() == 2);  // /NODE and /END
    CHECK(count_code(d.diagnostics, "DK017") == 1);
    CHECK(d.lines.size() == 1);

    test::TempDir dir;
    dir.write("nodes.inc", "/NODE\n         5\n#enddata\n/NODE\n         6\n");
    auto r = grammar::radioss::read_file(dir.write("m_0000.rad", "#RADIOSS STARTER\n#include nodes.inc\n/END\n"));
    REQUIRE(r.blocks.size() == 2);
    CHECK(r.blocks[0].line_count == 1);
    CHECK(count_code(r.diagnostics, "DK017") == 1);
}

TEST_CASE("radioss: an included file's blocks start at its first header, with its file in every span") {
    // The starter reads a keyword's cards from its own file (an #include line there is skipped)
    // and finds an included file's blocks by their headers: the lines of sub/lead.inc before its
    // first header (a licence text, the QA decks' qadiags.inc) belong to no block, silently.
    test::TempDir dir;
    dir.write("sub/lead.inc",
              "Copyright> text\n         7                 1.0                 2.0                 3.0\n");
    dir.write("sub/nodes.inc",
              "Copyright> text\n/NODE\n         9                 1.0                 2.0                 3.0\n");
    const std::string main = dir.write("m_0000.rad", deck("/NODE\n" + i10("1") + "\n#include sub/lead.inc\n" +
                                                          i10("8") + "\n#include sub/nodes.inc\n"));
    auto r = engine::check_file(main);
    REQUIRE(r.model.nodes.id.size() == 3);
    CHECK(r.model.nodes.id[0] == 1);
    CHECK(r.model.nodes.id[1] == 8);  // the block goes on after an include without headers
    CHECK(r.model.nodes.id[2] == 9);
    CHECK(r.model.nodes.z[2] == 3.0);
    CHECK(count_code(r.diagnostics, "DK002") == 0);
    CHECK(count_code(r.diagnostics, "DK027") == 0);
    REQUIRE(r.deck.sources.size() == 3);
    CHECK(r.deck.sources.file(2).parent == 0);
    const grammar::CardLine& first = r.deck.lines[r.deck.blocks[2].first_line];  // blocks: /BEGIN, /NODE, /NODE
    CHECK(first.file == 2);
    CHECK(first.line == 3);

    // After an included file with blocks of its own, the includer's lines before its next
    // header belong to no block sphdeck can follow: reported, not read into the child's block.
    const std::string after = dir.write("n_0000.rad", deck("/NODE\n#include sub/nodes.inc\n" + i10("8") + "\n"));
    auto a = engine::check_file(after);
    CHECK(a.model.nodes.id.size() == 1);
    CHECK(count_code(a.diagnostics, "DK027") == 1);

    auto missing = grammar::radioss::read_file(dir.write("x_0000.rad", "#RADIOSS STARTER\n#include nothing.inc\n"));
    REQUIRE(count_code(missing.diagnostics, "DK010") == 1);
    CHECK(find_code(missing.diagnostics, "DK010")->span.column == 10);
    dir.write("self.inc", "#include self.inc\n");
    auto cycle = grammar::radioss::read_file(dir.write("y_0000.rad", "#RADIOSS STARTER\n#include self.inc\n"));
    CHECK(count_code(cycle.diagnostics, "DK011") == 1);
}

TEST_CASE("radioss: #include files read and bytes read are bounded like the LS-DYNA reader's") {
    test::TempDir dir;
    for (int i = 0; i < 30; ++i) {
        const std::string next = "d" + std::to_string(i + 1) + ".inc";
        dir.write("d" + std::to_string(i) + ".inc", "#include " + next + "\n#include " + next + "\n");
    }
    dir.write("d30.inc", "/NODE\n");
    grammar::dyna::ReaderOptions few;
    few.max_include_files = 40;
    auto limited = grammar::radioss::read_file(dir.write("m_0000.rad", "#RADIOSS STARTER\n#include d0.inc\n"), few);
    CHECK(limited.stats.files == 41);
    CHECK(count_code(limited.diagnostics, "DK011") >= 1);

    dir.write("big.inc", "/NODE\n" + std::string(1000, '#') + "\n");
    grammar::dyna::ReaderOptions small;
    small.max_total_bytes = 500;
    auto refused = grammar::radioss::read_file(dir.write("b_0000.rad", "#RADIOSS STARTER\n#include big.inc\n"), small);
    CHECK(refused.stats.files == 1);
    CHECK(count_code(refused.diagnostics, "DK011") == 1);
}

TEST_CASE("radioss: the engine deck next to the starter is read; /DT cards belong there") {
    test::TempDir dir;
    const std::string body =
        kWater + "/PROP/SPH/2\nw\n" + r20("8.0E-6") + "\n\n/NODE\n" + i10("1") + "\n/SPHCEL/2\n" + i10("1") + "\n";
    const std::string starter = dir.write("run_0000.rad", deck(body));
    dir.write("run_0001.rad", "/RUN/run/1\n  1.0\n/DT/SPHCEL/STOP\n 0.3, 1.0E-7\n/DT/NODA/CST/1\n0.67 0.0\n/END\n");
    auto r = engine::check_file(starter);
    REQUIRE(r.deck.sources.size() == 2);
    const auto& f = facts(r);
    CHECK(f.engine_deck);
    REQUIRE(f.time_steps.size() == 2);
    CHECK(f.time_steps[0].kind == model::DtKind::SphCell);
    CHECK(f.time_steps[0].keyword3 == "STOP");
    CHECK(f.time_steps[0].dtsca.value == 0.3);
    CHECK(f.time_steps[0].dtmin.value == 1.0e-7);
    CHECK(f.time_steps[1].kind == model::DtKind::Nodal);
    CHECK(f.time_steps[1].iflag == 1);
    CHECK(r.model.controls.tssfac.value == 0.67);  // /DT/NODA replaces the SPH factor
    CHECK(count_code(r.diagnostics, "RAD020") == 0);

    CHECK(grammar::radioss::engine_file_name("a/run_0000.rad") == "a/run_0001.rad");
    CHECK(grammar::radioss::engine_file_name("bird.rad") == "bird_0001.rad");
    CHECK(!grammar::radioss::engine_file_name("run_0001.rad"));
    CHECK(grammar::radioss::is_engine_file_name("run_0002.rad"));
    CHECK(!grammar::radioss::is_engine_file_name("run_0000.rad"));

    auto misplaced = check(deck(body + "/DT/SPHCEL/STOP\n0.3 0.0\n"));
    CHECK(count_code(misplaced.diagnostics, "DK001") == 1);
    CHECK(facts(misplaced).time_steps.empty());
}

TEST_CASE("radioss: format detection by content, then by name") {
    using grammar::DeckFormat;
    CHECK(grammar::detect_format("#RADIOSS STARTER\n", "x.k") == DeckFormat::Radioss);
    CHECK(grammar::detect_format("$ c\n\n/BEGIN\n", "x") == DeckFormat::Radioss);
    CHECK(grammar::detect_format("$ c\n*KEYWORD\n", "x.rad") == DeckFormat::LsDyna);
    CHECK(grammar::detect_format("", "run_0000.rad") == DeckFormat::Radioss);
    CHECK(grammar::detect_format("", "deck.k") == DeckFormat::LsDyna);
    auto r = engine::check_buffer(deck("/NODE\n" + i10("3") + "\n"), "plain.txt", {}, std::nullopt);
    CHECK(r.model.radioss.has_value());
    CHECK(r.model.nodes.id.size() == 1);
}

TEST_CASE("radioss: cell widths follow Invers: 10/20 from format 51, 8/16 in V4 decks") {
    auto now = check(deck("/NODE\n" + i10("12") + r20("1.5") + r20("2.5") + r20("3.5") + "\n"));
    REQUIRE(now.model.nodes.id.size() == 1);
    CHECK(now.model.nodes.id[0] == 12);
    CHECK(now.model.nodes.y[0] == 2.5);
    CHECK(facts(now).version == 2026);

    auto v4 = check(
        "#RADIOSS STARTER\n/BEGIN\nrun\n      44\n/NODE\n      12             1.5             2.5             3.5\n/END\n");
    REQUIRE(v4.model.nodes.id.size() == 1);
    CHECK(facts(v4).version == 44);
    CHECK(v4.model.nodes.id[0] == 12);
    CHECK(v4.model.nodes.z[0] == 3.5);
    CHECK(v4.diagnostics.empty());
    CHECK(grammar::radioss::cell_width(grammar::radioss::Cell::Real, 44) == 16);
    CHECK(grammar::radioss::line_width(44) == 80);
}

TEST_CASE("radioss: comma free format") {
    auto r = check(deck("/NODE\n5, 1.0, 2.0, 3.0\n6,4.0,,6.0\n"));
    REQUIRE(r.model.nodes.id.size() == 2);
    CHECK(r.model.nodes.x[0] == 1.0);
    CHECK(r.model.nodes.z[1] == 6.0);
    CHECK(r.model.nodes.y[1] == 0.0);
    CHECK(r.diagnostics.empty());
}

TEST_CASE("radioss: /PROP/SPH in each format, with the starter's defaults") {
    const std::string card1 = r20("8.0E-6") + r20("0.0") + r20("") + r20("0.1") + i10("0") + i10("3") + "\n";
    const std::string card2 = i10("") + r20("2.4") + r20("0.5") + i10("") + r20("0.0") + r20("3.0") + "\n";
    auto r = check(deck(kWater + "/PROP/SPH/2\nwater\n" + card1 + card2 + r20("1.1") + "\n"));
    const auto& p = facts(r).sph_properties.at(0);
    CHECK(p.format == 2026);
    CHECK(p.title == "water");
    CHECK(p.mp.value == 8.0e-6);
    CHECK(p.qa.value == 2.0);  // 0 → 2
    CHECK(p.qa.explicit_value);
    CHECK(p.qb.value == 1.0);  // blank → 1
    CHECK(!p.qb.explicit_value);
    CHECK(p.alpha_cs.value == 0.1);
    CHECK(p.h_1d.value == 3);
    CHECK(p.order.value == 0);
    CHECK(p.h.value == 2.4);
    CHECK(p.xi_stab.value == 0.5);
    CHECK(p.hmin.value == 0.2);
    CHECK(p.hmax.value == 3.0);
    CHECK(p.hcst.value == 1.1);
    // The shared model: an SPH section with h as its explicit smoothing length.
    const model::Section* s = r.model.section("2");
    REQUIRE(s);
    CHECK(s->sph);
    CHECK(s->sphini.value == 2.4);

    // 2019: no hmin/hmax; text there is past the card's last field (DK006), a third card DK009.
    auto old = check(deck(kWater + "/PROP/TYPE34/2\nwater\n" + card1 + card2 + r20("1.1") + "\n", 2019));
    const auto& q = facts(old).sph_properties.at(0);
    CHECK(q.format == 2019);
    CHECK(q.hmax.value == 2.0);
    CHECK(!q.hmin_hmax_hcst_read);
    REQUIRE(count_code(old.diagnostics, "DK006") == 1);
    CHECK(find_code(old.diagnostics, "DK006")->message.find("Invers is 2019") != std::string::npos);
    CHECK(count_code(old.diagnostics, "DK009") == 1);

    // 130 has no h_1D; 51 no Xi_Stab; 44 reads 16/8 cells and takes the title from the header.
    auto f130 = check(deck(kWater + "/PROP/SPH/2\nw\n" + card1 + i10("1") + r20("2.0") + "\n", 130));
    CHECK(facts(f130).sph_properties.at(0).h_1d.value == 0);
    CHECK(facts(f130).sph_properties.at(0).order.value == 1);
    auto f51 = check(deck(kWater + "/PROP/SPH/2\nw\n" + r20("1.0E-5") + "\n" + i10("-1") + r20("2.0") + "\n", 51));
    CHECK(facts(f51).sph_properties.at(0).order.value == -1);
    CHECK(facts(f51).sph_properties.at(0).mp.value == 1.0e-5);
    auto v4 = check(
        "#RADIOSS STARTER\n/BEGIN\nrun\n      44\n/PROP/TYPE34/2/old water\n"
        "          2.0E-5             0.0\n       1             3.0\n/END\n");
    const auto& w = facts(v4).sph_properties.at(0);
    CHECK(w.title == "old water");
    CHECK(w.mp.value == 2.0e-5);
    CHECK(w.h.value == 3.0);
    CHECK(w.order.value == 1);
}

TEST_CASE("radioss: /SPHCEL masses as the starter takes them") {
    const std::string body = kWater + "/PROP/SPH/2\nw\n" + r20("0.0") + "\n\n/NODE\n" + i10("1") + "\n" + i10("2") +
                             "\n" + i10("3") + "\n" + i10("4") + "\n/SPHCEL/2\n" + i10("1") + i10("1") + r20("4.0E-6") +
                             "\n" + i10("2") + i10("2") + r20("8.0") + "\n" + i10("3") + i10("0") + r20("5.0E-6") +
                             "\n" + i10("4") + "\n";
    auto r = check(deck(body));
    const auto& p = r.model.particles;
    REQUIRE(p.size() == 4);
    CHECK(p.node[1] == 2);
    CHECK(p.part[1] == 2);
    CHECK(p.mass[0] == 4.0e-6);
    CHECK(p.volume[1] == 1);  // Type 2: a volume
    CHECK(p.mass[1] == 8.0);
    CHECK(p.mass[2] == 5.0e-6);  // Type 0 with a mass: that mass
    CHECK(p.mass[3] == 1.0);     // Type 0 without one: mp, and mp 0 becomes 1
    CHECK(facts(r).cells.from_property[3] == 1);
    CHECK(count_code(r.diagnostics, "RAD023") == 1);
}

TEST_CASE("radioss: parts, materials, EOS, groups and elements land in the model") {
    const std::string body = kWater + "/EOS/POLYNOMIAL/3\nwater eos\n" + r20("0.0") + r20("2200.0") + "\n" +
                             "/MAT/PLAS_JOHNS/4\nsteel\n" + r20("7.8E-6") + "\n" + r20("210.0") + r20("0.3") + "\n" +
                             "/GRNOD/NODE/10\nn\n" + i10("1") + i10("2") + "\n" + i10("3") + "\n" +
                             "/GRNOD/PART/11\np\n" + i10("5") + "\n" + "/BRICK/5\n" + i10("1") + i10("1") + i10("2") +
                             i10("3") + i10("4") + i10("5") + i10("6") + i10("7") + i10("8") + "\n" + "/TETRA10/5\n" +
                             i10("2") + "\n" + i10("1") + i10("2") + i10("3") + i10("4") + i10("5") + i10("6") +
                             i10("7") + i10("8") + i10("9") + i10("10") + "\n" + "/PROP/SHELL/9\nshell\n";
    auto r = check(deck(body));
    const auto& f = facts(r);
    REQUIRE(r.model.parts.size() == 1);
    CHECK(r.model.parts[0].section.value == "2");
    CHECK(r.model.parts[0].material.value == "3");
    CHECK(r.model.parts[0].eos.value == "3");  // the EOS of its material
    CHECK(r.model.material("3")->density.value == 1.0e-6);
    REQUIRE(f.materials.size() == 2);
    CHECK(f.materials[0].law == 6);
    CHECK(f.materials[1].law == 2);
    CHECK(f.materials[1].young == 210.0);
    CHECK(f.eos_of(3)->c[1] == 2200.0);
    REQUIRE(r.model.node_sets.size() == 2);
    CHECK(r.model.node_sets[0].members == std::vector<long long>{1, 2, 3});
    CHECK(r.model.node_sets[1].members == std::vector<long long>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
    CHECK(f.bricks.size() == 1);
    CHECK(f.tetra10.size() == 1);
    CHECK(f.tetra10.nodes[9] == 10);
    CHECK(r.model.section("9") != nullptr);  // any /PROP is known by id
}

TEST_CASE("radioss: /SPHBCS, frames and planes") {
    const std::string frame = "/FRAME/FIX/7\nf\n" + r20("1.0") + r20("0.0") + r20("0.0") + "\n" + r20("0.0") +
                              r20("1.0") + r20("0.0") + "\n" + r20("-1.0") + r20("0.0") + r20("0.0") + "\n";
    const std::string sym = "/SPHBCS/TIED/1\nt\n" + i10("Y") + i10("7") + i10("0") + i10("") + i10("1") + "\n" +
                            "/SPHBCS/SLIDEX/2\ns\n" + i10("") + "\n" + "/SPHBCS/SLIDE/3\nx\n" + i10("X") + i10("7") +
                            "\n";
    auto r = check(deck(frame + sym));
    const auto& f = facts(r);
    REQUIRE(f.symmetries.size() == 3);
    CHECK(f.symmetries[0].kind == model::SymmetryKind::Tied);
    CHECK(f.symmetries[0].axis == 1);
    CHECK(f.symmetries[0].ilev.value == 1);
    CHECK(f.symmetries[1].kind == model::SymmetryKind::Slide);  // the first five letters count
    CHECK(f.symmetries[1].dir.value == "X");                    // blank Dir: X
    REQUIRE(r.model.symmetry_planes.size() == 3);
    // Frame 7 through (1, 0, 0): its lines after the origin are Y' (+y) and Z' (-x), and
    // X' = Y' x Z' = +z (hm_read_frm.F). Plane 1 (Dir Y) has the normal +y, plane 3 (Dir X) +z.
    const auto& plane = r.model.symmetry_planes[0];
    CHECK(plane.tail[0] == 1.0);
    CHECK(plane.head[0] == doctest::Approx(1.0));
    CHECK(plane.head[1] == doctest::Approx(1.0));
    CHECK(plane.head[2] == doctest::Approx(0.0));
    CHECK(r.model.symmetry_planes[1].head[0] == 1.0);
    const auto& x_plane = r.model.symmetry_planes[2];
    CHECK(x_plane.head[0] == doctest::Approx(1.0));
    CHECK(x_plane.head[1] == doctest::Approx(0.0));
    CHECK(x_plane.head[2] == doctest::Approx(1.0));
}

TEST_CASE("radioss: /SPHGLO defaults and the first one only") {
    auto r = check(deck("/SPHGLO\n" + r20("0.0") + i10("0") + i10("0") + i10("0") + "\n/SPHGLO\n" + r20("0.3") + "\n"));
    const auto& g = facts(r).sph_global;
    CHECK(g.alpha_sort.value == 0.25);
    CHECK(g.nneigh.value == 120);  // an explicit 0 gives 120, not 240
    CHECK(g.lneigh.value == 120);
    CHECK(g.ignored.size() == 1);
    CHECK(count_code(r.diagnostics, "DK018") == 1);
    CHECK(count_code(r.diagnostics, "RAD022") == 1);
}

TEST_CASE("radioss: /BEGIN units and run name") {
    auto r = check("#RADIOSS STARTER\n/BEGIN\nbird strike\n      2021\n" + r20("g") + r20("mm") + r20("ms") + "\n" +
                   r20("kg") + r20("m") + r20("s") + "\n/END\n");
    const auto& f = facts(r);
    CHECK(f.begin_present);
    CHECK(f.version == 2021);
    CHECK(f.run_name == "bird strike");
    CHECK(f.input_units[0] == "g");
    CHECK(f.work_units[2] == "s");
}

TEST_CASE("radioss: bad values are reported at their cells") {
    auto r = check(deck("/NODE\n" + i10("x1") + r20("1.0.0") + r20("2.0") + "\n" + i10("2.0") + "\n"));
    REQUIRE(count_code(r.diagnostics, "DK002") == 1);
    CHECK(find_code(r.diagnostics, "DK002")->span.column == 9);
    REQUIRE(count_code(r.diagnostics, "DK003") == 1);
    CHECK(find_code(r.diagnostics, "DK003")->span.column == 26);
    CHECK(count_code(r.diagnostics, "DK004") == 1);
    CHECK(r.model.nodes.id == std::vector<long long>{2});
    // A tab that moves X into Y's cell when expanded to column 17 (one that moves nothing is silent).
    auto tab = check(deck("/NODE\n         1\t               1.0\n"));
    CHECK(count_code(tab.diagnostics, "DK016") == 1);
    CHECK(count_code(check(deck("/NODE\n         1\t1.0\n")).diagnostics, "DK016") == 0);
}

TEST_CASE("radioss: RAD025 two numbers glued in one fixed cell, the first one kept") {
    auto r = check(deck("/SPHGLO\n       0.1     15000       120       240\n"));
    REQUIRE(count_code(r.diagnostics, "RAD025") == 1);
    const auto* d = find_code(r.diagnostics, "RAD025");
    CHECK(d->span.column == 8);
    CHECK(d->message.find("keeps 0.1") != std::string::npos);
    const auto& g = facts(r).sph_global;
    CHECK(g.alpha_sort.value == 0.1);
    CHECK(g.maxsph.value == 120);  // the next cells are read where they stand
    CHECK(g.lneigh.value == 240);
    // In free format the blanks separate nothing: commas do.
    CHECK(count_code(check(deck("/SPHGLO\n0.1, 15000, 120, 240\n")).diagnostics, "RAD025") == 0);
}

TEST_CASE("radioss: unknown keywords are errors, each at its line, with a suggestion") {
    auto r = check(deck("/SPHCELL/2\n" + i10("1") + "\n/FOO/BAR/1\n/FOO/BAR/2\n"));
    REQUIRE(count_code(r.diagnostics, "DK001") == 3);
    bool suggested = false;
    for (const auto& d : r.diagnostics) {
        if (d.code != "DK001") continue;
        CHECK(d.severity == diag::Severity::Error);
        suggested |= d.message.find("did you mean /SPHCEL?") != std::string::npos;
    }
    CHECK(suggested);
    CHECK(grammar::radioss::find_keyword("/MAT/LAW99/3") == grammar::radioss::find_keyword("/MAT"));
    CHECK(grammar::radioss::find_keyword("/MAT/LAW6/3")->family == "/MAT");  // a law table of the /MAT family
    CHECK(grammar::radioss::find_keyword("/MATX/1") == nullptr);
}

TEST_CASE("radioss: bad input never crashes the reader or the decoder") {
    std::string binary;
    for (int k = 0; k < 4096; ++k) binary += static_cast<char>((k * 7919) % 256);
    const std::string huge = "/NODE\n" + std::string(2'000'000, '9') + "\n" + std::string(100000, '/') + "\n";
    const std::string inputs[] = {
        "",
        "\n\n\n",
        "/",
        "//\n/ /\n/\t\n",
        "#include\n#include   \n#enddata",
        binary,
        huge,
        "#RADIOSS STARTER\n/BEGIN\n\n-5\n/PROP/SPH\n/SPHCEL\n,,,,\n/SPHBCS\n/MAT/LAW6\n/TETRA10/1\n1\n",
        deck("/SPHCEL/x\n1\n/BRICK/2\n1 2 3\n/DT/SPHCEL\n")};
    for (const auto& text : inputs) {
        CHECK_NOTHROW(check(text, "fuzz_0000.rad"));
        CHECK_NOTHROW(engine::check_buffer(text, "fuzz.rad", {}, std::nullopt));
    }
}

TEST_CASE("radioss: card tables: unique names, formats newest first") {
    std::set<std::string_view> names;
    for (const auto& k : grammar::radioss::all_keywords()) {
        CAPTURE(k.name);
        CHECK(names.insert(k.name).second);
        for (auto alias : k.aliases) CHECK(names.insert(alias).second);
        REQUIRE(!k.formats.empty());
        for (std::size_t f = 1; f < k.formats.size(); ++f) CHECK(k.formats[f - 1].since > k.formats[f].since);
    }
    std::size_t segments = 0;
    const auto* sph = grammar::radioss::find_keyword("/PROP/TYPE34/7", &segments);
    REQUIRE(sph);
    CHECK(sph->name == "/PROP/SPH");
    CHECK(segments == 2);
    CHECK(sph->format_for(2024).since == 2019);
    CHECK(sph->format_for(44).since == 0);
    CHECK(grammar::radioss::find_keyword("/DT/SPCEL/STOP")->name == "/DT/SPHCEL");
}
}  // namespace test_radioss_reader_cpp
