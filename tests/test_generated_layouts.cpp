// The layouts generated from pydyna (grammar/keywords/generated/): lookup, options, formats, and
// the differences from the hand-written tables, listed in a committed file a reviewer reads.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grammar/dyna/reader.hpp"
#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/keywords/schema.hpp"
#include "engine/check.hpp"

namespace test_generated_layouts_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using keywords::CardSpec;
using keywords::FieldSpec;
using keywords::FieldType;

namespace {

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

bool same_type(FieldType hand, FieldType generated) {
    // An id written I/A by hand is an integer in pydyna's classes.
    return hand == generated || (hand == FieldType::Label && generated == FieldType::Integer);
}

// Field by field, card by card: names (aliases count), columns, widths and types of the base cards
// (options left out) of one keyword known both ways.
void compare(const keywords::KeywordSchema& hand, const keywords::KeywordSchema& gen, std::ostringstream& out) {
    std::vector<const CardSpec*> gen_cards;
    for (const CardSpec& c : gen.cards)
        if (!c.unknown_layout) gen_cards.push_back(&c);
    if (gen_cards.size() != hand.cards.size())
        out << hand.name << ": " << hand.cards.size() << " card(s) by hand, " << gen_cards.size() << " generated"
            << (gen.cards.size() != gen_cards.size() ? " before an unknown layout" : "") << "\n";
    for (std::size_t i = 0; i < std::min(gen_cards.size(), hand.cards.size()); ++i) {
        const CardSpec& h = hand.cards[i];
        const CardSpec& g = *gen_cards[i];
        for (const FieldSpec& hf : h.fields) {
            if (hf.type == FieldType::Unused) continue;
            auto at = std::find_if(g.fields.begin(), g.fields.end(),
                                   [&](const FieldSpec& f) { return f.column == hf.column; });
            std::ostringstream where;
            where << hand.name << " card " << i + 1 << " column " << hf.column << ": ";
            if (at == g.fields.end() || at->type == FieldType::Unused) {
                out << where.str() << hf.name << " by hand, no field generated\n";
                continue;
            }
            if (!hf.is_named(at->name) && upper(hf.name) != upper(at->name))
                out << where.str() << "named " << hf.name << " by hand, " << at->name << " generated\n";
            if (at->width != hf.width)
                out << where.str() << hf.name << " width " << hf.width << " by hand, " << at->width << " generated\n";
            const FieldType generated_type = at->doc.starts_with("integer") ? FieldType::Integer : at->type;
            if (!same_type(hf.type, generated_type))
                out << where.str() << hf.name << " type " << keywords::to_string(hf.type) << " by hand, "
                    << keywords::to_string(generated_type) << " generated\n";
        }
        for (const FieldSpec& gf : g.fields) {
            if (gf.type == FieldType::Unused) continue;
            const bool known = std::any_of(h.fields.begin(), h.fields.end(),
                                           [&](const FieldSpec& f) { return f.column == gf.column; });
            if (!known)
                out << hand.name << " card " << i + 1 << " column " << gf.column << ": " << gf.name
                    << " generated, no field by hand\n";
        }
    }
}

std::string differences() {
    std::ostringstream out;
    for (const keywords::KeywordSchema& hand : keywords::all_keywords()) {
        auto gen = keywords::generated::find_generated(hand.name);
        if (!gen) {
            out << hand.name << ": not in the generated layouts\n";
            continue;
        }
        compare(hand, *gen->schema, out);
    }
    return out.str();
}

}  // namespace

TEST_CASE("generated layouts: sorted, and every keyword decodes") {
    const auto all = keywords::generated::layouts();
    CHECK(all.size() >= 3684);
    CHECK(std::is_sorted(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.name < b.name; }));
    for (const auto& e : all) {
        auto m = keywords::generated::find_generated(e.name);
        REQUIRE_MESSAGE(m.has_value(), e.name);
        CHECK(m->schema->generated);
    }
}

TEST_CASE("generated layouts: hand-written tables win, the rest falls back to the generated ones") {
    auto sph = keywords::find_keyword("*CONTROL_SPH");
    REQUIRE(sph);
    CHECK_FALSE(sph->schema->generated);
    auto isph = keywords::find_keyword("*CONTROL_SPH_INCOMPRESSIBLE");
    REQUIRE(isph);
    CHECK(isph->schema->generated);
    CHECK(isph->unknown_options.empty());
    // options: _ID adds the id card; TITLE stands for ID when there is no TITLE option
    auto contact = keywords::find_keyword("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID");
    REQUIRE(contact);
    CHECK(contact->schema->cards.front().fields.front().name == "CID");
    auto titled = keywords::find_keyword("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TITLE");
    REQUIRE(titled);
    CHECK(titled->has("ID"));
    CHECK_FALSE(keywords::find_keyword("*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_BOGUS").has_value());
    CHECK_FALSE(keywords::find_keyword("*NOT_A_KEYWORD").has_value());
    // every *SECTION_ keyword takes _TITLE, also where pydyna does not list it; others do not
    auto solid = keywords::find_keyword("*SECTION_SOLID_TITLE");
    REQUIRE(solid);
    CHECK(solid->has("TITLE"));
    CHECK(solid->schema->cards.front().name == "Title");
    CHECK_FALSE(keywords::find_keyword("*CONTROL_IMPLICIT_AUTO_TITLE").has_value());
    // a condition the table can decide: *CONTROL_IMPLICIT_AUTO card 2 when IAUTO = 3
    auto implicit = keywords::find_keyword("*CONTROL_IMPLICIT_AUTO");
    REQUIRE(implicit);
    REQUIRE(implicit->schema->cards.size() >= 2);
    REQUIRE(implicit->schema->cards[1].present_if);
    CHECK(implicit->schema->cards[1].present_if->holds(3.0));
    CHECK_FALSE(implicit->schema->cards[1].present_if->holds(1.0));
}

// The list is committed: a change to the generator or to a hand table shows up in review.
TEST_CASE("generated layouts: differences from the hand-written tables are listed") {
    const std::filesystem::path file =
        std::filesystem::path(SPHDECK_SOURCE_DIR) / "grammar" / "keywords" / "generated" / "differences.txt";
    std::ifstream in(file);
    std::stringstream committed;
    committed << in.rdbuf();
    const std::string now = differences();
    if (committed.str() != now) {
        std::ofstream(file.string() + ".new") << now;
        FAIL_CHECK("differences changed: compare " << file.string() << ".new with the committed file");
    }
}

TEST_CASE("generated layouts: a pydyna integer field is checked as a number and called an integer field") {
    auto r = engine::check_buffer("*KEYWORD\n*LOAD_NODE_POINT\n        80       abc\n*NODE\n      80\n", "d.k");
    REQUIRE(r.diagnostics.size() >= 1);
    bool found = false;
    for (const auto& d : r.diagnostics)
        if (d.code == "DK003") found = d.message == "'abc' in integer field DOF is not a number";
    CHECK(found);
}

namespace {

bool has_finding(const engine::CheckResult& r, std::string_view code, std::string_view message) {
    for (const auto& d : r.diagnostics)
        if (d.code == code && d.message == message) return true;
    return false;
}

}  // namespace

TEST_CASE("generated layouts: every name of the layouts file, written on a keyword line, is known") {
    // Through the reader: a name holding '-' or '/' (*CONSTRAINED_TIE-BREAK, *MAT_SIMPLIFIED_RUBBER/FOAM)
    // must reach the table whole. pydyna's aliases (*MAT_SAMP_1 for *MAT_SAMP-1) are names of the file
    // too; "*ELEMENT_SOLID_DOF (ten nodes format)" is read as *ELEMENT_SOLID_DOF and a hint.
    std::string text = "*KEYWORD\n";
    std::size_t names = 0;
    for (const auto& e : keywords::generated::layouts()) {
        text += std::string(e.name) + "\n";
        ++names;
    }
    text += "*CASE_BEGIN_1\n*CASE_END_1\n*CASE_BEGIN_12\n*CASE_END_12\n";
    const auto deck = grammar::dyna::read_buffer(text, "all.k");
    REQUIRE(deck.blocks.size() == names + 5);
    std::size_t unknown = 0;
    for (std::size_t i = 1; i < deck.blocks.size(); ++i) {
        const std::string& k = deck.blocks[i].keyword;
        auto m = keywords::find_keyword(k);
        const bool known = m && m->unknown_options.empty();
        if (!known) ++unknown;
        CHECK_MESSAGE(known, k);
    }
    CHECK(unknown == 0);
    CHECK(deck.blocks[1 + 0].keyword.find(' ') == std::string::npos);
    CHECK_FALSE(keywords::find_keyword("*CASE_BEGIN_X").has_value());
    CHECK_FALSE(keywords::find_keyword("*CASE_BEGIN_1_2").has_value());
}

TEST_CASE("generated layouts: a condition naming two fields is decided by both") {
    // *BOUNDARY_PRESCRIBED_MOTION: the OFFSET1/OFFSET2/LRB card follows when abs(DOF) is 9, 10 or 11
    // or VAD is 4 (pydyna: "abs(self.dof) in [9, 10, 11] or self.vad == 4"); else the block ends.
    const std::string head = "*KEYWORD\n*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
    const std::string offsets = "       abc\n";
    const std::string message = "'abc' in real field OFFSET1 is not a number";
    auto by_vad = engine::check_buffer(head + "         1         1         4         1\n" + offsets, "d.k");
    CHECK(has_finding(by_vad, "DK003", message));
    auto by_dof = engine::check_buffer(head + "         1       -10         2         1\n" + offsets, "d.k");
    CHECK(has_finding(by_dof, "DK003", message));
    auto neither = engine::check_buffer(head + "         1         1         2         1\n" + offsets, "d.k");
    CHECK_FALSE(has_finding(neither, "DK003", message));
    auto match = keywords::find_keyword("*BOUNDARY_PRESCRIBED_MOTION_NODE");
    REQUIRE(match);
    const auto& cond = match->schema->cards.at(1).present_if;
    REQUIRE(cond.has_value());
    CHECK(cond->field == "DOF");
    REQUIRE(cond->or_else.size() == 1);
    CHECK(cond->or_else[0].field == "VAD");
}

TEST_CASE("generated layouts: *ELEMENT_SOLID is read in its one-line and two-line forms") {
    auto match = keywords::find_keyword("*ELEMENT_SOLID");
    REQUIRE(match);
    CHECK(keywords::repeat_group_size(*match) == 2);
    // two-line form: the node line's third field is N3 (columns 17-24), not the first line's N1
    auto two = engine::check_buffer("*KEYWORD\n*ELEMENT_SOLID\n       1       1\n       1       2     abc\n", "d.k");
    CHECK(has_finding(two, "DK003", "'abc' in integer field N3 is not a number"));
    // one-line form: columns 17-24 are N1, and the next line is the next element
    auto one = engine::check_buffer(
        "*KEYWORD\n*ELEMENT_SOLID\n       1       1     abc       2       3       4       5       6       7       8\n"
        "       2       1       1       2       3       4       5       6     xyz       8\n",
        "d.k");
    CHECK(has_finding(one, "DK003", "'abc' in integer field N1 is not a number"));
    CHECK(has_finding(one, "DK003", "'xyz' in integer field N7 is not a number"));
}
}  // namespace test_generated_layouts_cpp
