// Card schema tables: geometry of every card, lookup of names and options, format layouts.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "grammar/keywords/schema.hpp"

namespace test_keywords_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::CardFormat;
using keywords::CardRepeat;
using keywords::CardSpec;
using keywords::FieldType;
using keywords::KeywordSchema;

namespace {

// Every card of a schema: base cards and the cards its options add.
std::vector<const CardSpec*> every_card(const KeywordSchema& k) {
    std::vector<const CardSpec*> cards;
    for (const CardSpec& c : k.cards) cards.push_back(&c);
    for (const auto& o : k.options) {
        for (const CardSpec& c : o.cards_before) cards.push_back(&c);
        for (const CardSpec& c : o.cards_after) cards.push_back(&c);
    }
    return cards;
}

// "start:width" of every slot, e.g. "0:10 10:16".
std::string slots(const CardSpec& card, CardFormat f) {
    std::string s;
    for (const auto& slot : keywords::layout(card, f)) {
        if (!s.empty()) s += ' ';
        s += std::to_string(slot.start) + ":" + std::to_string(slot.width);
    }
    return s;
}

std::vector<std::string> card_names(const keywords::KeywordMatch& m) {
    std::vector<std::string> names;
    for (const CardSpec* c : keywords::cards_for(m)) names.emplace_back(c->name);
    return names;
}

const KeywordSchema& schema(std::string_view name) {
    auto m = keywords::find_keyword(name);
    REQUIRE(m.has_value());
    return *m->schema;
}

bool is_upper_name(std::string_view s) {
    if (s.size() < 2 || s.front() != '*') return false;
    return std::all_of(s.begin() + 1, s.end(), [](char c) {
        return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
    });
}

}  // namespace

TEST_CASE("keywords: every field lies inside its card, sorted and without overlap") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            std::uint32_t end = 0;  // 1-based last column of the previous field
            for (const auto& f : card->fields) {
                INFO(k.name << " / " << card->name << " / " << f.name);
                CHECK(f.column >= 1);
                CHECK(f.width >= 1);
                CHECK(f.column > end);  // sorted, no overlap
                end = f.column + f.width - 1u;
                CHECK(end <= card->line_width);
            }
        }
    }
}

TEST_CASE("keywords: field names are unique within a card and options within a keyword") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            std::set<std::string> names;
            for (const auto& f : card->fields) {
                if (f.type == FieldType::Unused) continue;
                INFO(k.name << " / " << card->name << " / " << f.name);
                CHECK(!f.name.empty());
                CHECK(names.insert(std::string(f.name)).second);
                for (auto a : f.aliases) CHECK(names.insert(std::string(a)).second);
            }
        }
        std::set<std::string> options;
        for (const auto& o : k.options) {
            INFO(k.name << " _" << o.suffix);
            CHECK(options.insert(std::string(o.suffix)).second);
            for (auto a : o.aliases) CHECK(options.insert(std::string(a)).second);
        }
    }
}

TEST_CASE("keywords: defaults agree with enums and ranges") {
    for (const KeywordSchema& k : keywords::all_keywords()) {
        for (const CardSpec* card : every_card(k)) {
            for (const auto& f : card->fields) {
                INFO(k.name << " / " << card->name << " / " << f.name);
                if (f.default_value && !f.choices.empty()) {
                    const auto v = static_cast<long long>(*f.default_value);
                    CHECK(static_cast<double>(v) == *f.default_value);
                    CHECK(f.choice(v) != nullptr);
                }
                if (f.min && f.max) CHECK(*f.min <= *f.max);
                if (f.default_value && f.min) CHECK(*f.default_value >= *f.min);
                if (f.default_value && f.max) CHECK(*f.default_value <= *f.max);
                if (f.required) CHECK(!f.default_value);
                if (!f.default_text.empty()) CHECK(f.type == FieldType::Text);
                if (!f.default_text.empty() && !f.text_choices.empty())
                    CHECK(std::find(f.text_choices.begin(), f.text_choices.end(), f.default_text) !=
                          f.text_choices.end());
                if (f.type == FieldType::Text) CHECK(!f.default_value);
            }
        }
    }
}

TEST_CASE("keywords: names, aliases, conditions and unique flags are consistent") {
    std::set<std::string> names;
    for (const KeywordSchema& k : keywords::all_keywords()) {
        INFO(k.name);
        CHECK(is_upper_name(k.name));
        CHECK(names.insert(std::string(k.name)).second);
        for (auto a : k.aliases) {
            CHECK(is_upper_name(a));
            CHECK(names.insert(std::string(a)).second);
        }
        CHECK(!k.doc.empty());
        CHECK(k.repeat_group <= k.cards.size());
        const bool control = k.name.rfind("*CONTROL_", 0) == 0;
        CHECK(k.unique == (control || k.name == "*KEYWORD" || k.name == "*TITLE"));
        // A condition names a field of an earlier card.
        std::set<std::string> seen;
        for (const CardSpec& c : k.cards) {
            if (c.present_if) CHECK(seen.count(std::string(c.present_if->field)) == 1);
            for (const auto& f : c.fields) seen.insert(std::string(f.name));
        }
        // Optional cards only at the end of the base cards.
        bool optional_seen = false;
        for (const CardSpec& c : k.cards) {
            if (c.repeat == CardRepeat::Optional)
                optional_seen = true;
            else if (optional_seen)
                CHECK(c.repeat != CardRepeat::Once);
        }
    }
}

TEST_CASE("keywords: every keyword of the SPH card reference is in the tables") {
    const char* expected[] = {
        "*CONTROL_SPH",
        "*SECTION_SPH",
        "*ELEMENT_SPH",
        "*NODE",
        "*PART",
        "*BOUNDARY_SPH_SYMMETRY_PLANE",
        "*BOUNDARY_SPH_FLOW",
        "*BOUNDARY_SPH_NON_REFLECTING",
        "*DEFINE_BOX",
        "*DEFINE_BOX_SPH",
        "*DEFINE_SPH_TO_SPH_COUPLING",
        "*DEFINE_ADAPTIVE_SOLID_TO_SPH",
        "*CONTROL_BULK_VISCOSITY",
        "*HOURGLASS",
        "*CONTROL_TIMESTEP",
        "*CONTROL_TERMINATION",
        "*CONTROL_SOLUTION",
        "*CONTROL_MPP_DECOMPOSITION_SCALE_FACTOR_SPH",
        "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS",
        "*MAT_NULL",
        "*MAT_ELASTIC",
        "*MAT_PLASTIC_KINEMATIC",
        "*MAT_JOHNSON_COOK",
        "*EOS_GRUNEISEN",
        "*EOS_LINEAR_POLYNOMIAL",
        "*EOS_MURNAGHAN",
        "*MAT_ADD_EROSION",
        "*SET_NODE_LIST",
        "*SET_PART_LIST",
        "*PARAMETER",
        "*PARAMETER_EXPRESSION",
        "*PARAMETER_DUPLICATION",
        "*INCLUDE",
        "*INCLUDE_PATH",
        "*INCLUDE_PATH_RELATIVE",
        "*INCLUDE_TRANSFORM",
        "*KEYWORD",
        "*TITLE",
        "*COMMENT",
        "*END",
        "*DEFINE_CURVE",
        "*LOAD_BODY_X",
        "*LOAD_BODY_Y",
        "*LOAD_BODY_Z",
        "*INITIAL_VELOCITY",
        "*INITIAL_VELOCITY_NODE",
        "*INITIAL_VELOCITY_GENERATION",
        "*DEFINE_SPH_MESH_BOX",  // beyond the reference: read for `sphdeck smooth` (docs/sph-keywords.md)
    };
    for (const char* name : expected) {
        INFO(name);
        auto m = keywords::find_keyword(name);
        REQUIRE(m.has_value());
        CHECK(m->schema->name == name);
        CHECK(m->options.empty());
        CHECK(m->unknown_options.empty());
    }
    CHECK(keywords::all_keywords().size() == std::size(expected));
}

TEST_CASE("keywords: lookup by case, alias and options") {
    SUBCASE("case and star") {
        auto m = keywords::find_keyword("control_sph");
        REQUIRE(m);
        CHECK(m->schema->name == "*CONTROL_SPH");
        CHECK(keywords::find_keyword("*Control_Sph")->schema->name == "*CONTROL_SPH");
        CHECK(keywords::find_keyword("  *NODE +")->schema->name == "*NODE");
        CHECK(keywords::find_keyword("*NODE%")->schema->name == "*NODE");
        CHECK(keywords::find_keyword("*KEYWORD long=s")->schema->name == "*KEYWORD");
        CHECK_FALSE(keywords::find_keyword("*NOT_A_KEYWORD"));
        CHECK_FALSE(keywords::find_keyword(""));
        CHECK_FALSE(keywords::find_keyword("*"));
    }
    SUBCASE("aliases") {
        CHECK(keywords::find_keyword("*MAT_009")->schema->name == "*MAT_NULL");
        CHECK(keywords::find_keyword("*MAT_001")->schema->name == "*MAT_ELASTIC");
        CHECK(keywords::find_keyword("*MAT_003")->schema->name == "*MAT_PLASTIC_KINEMATIC");
        CHECK(keywords::find_keyword("*mat_015")->schema->name == "*MAT_JOHNSON_COOK");
        CHECK(keywords::find_keyword("*CONTROL_TIME_STEP")->schema->name == "*CONTROL_TIMESTEP");
        CHECK(keywords::find_keyword("*SET_NODE")->schema->name == "*SET_NODE_LIST");
        CHECK(keywords::find_keyword("*SET_PART")->schema->name == "*SET_PART_LIST");
        CHECK(keywords::find_keyword("*SET_PART_TITLE")->schema->name == "*SET_PART_LIST");
        // Other *SET_PART_ keywords keep their own (generated) layouts.
        CHECK(keywords::find_keyword("*SET_PART_ADD")->schema->name == "*SET_PART_ADD");
        auto m = keywords::find_keyword("*MAT_009_TITLE");
        REQUIRE(m);
        CHECK(m->schema->name == "*MAT_NULL");
        CHECK(m->has("TITLE"));
    }
    SUBCASE("options, longest base first") {
        auto m = keywords::find_keyword("*SECTION_SPH_ELLIPSE_TITLE");
        REQUIRE(m);
        CHECK(m->schema->name == "*SECTION_SPH");
        REQUIRE(m->options.size() == 2);
        CHECK(m->options[0]->suffix == "ELLIPSE");
        CHECK(m->options[1]->suffix == "TITLE");
        CHECK(m->unknown_options.empty());
        CHECK(card_names(*m) == std::vector<std::string>{"Title", "Card 1", "Card 2"});

        auto box = keywords::find_keyword("*DEFINE_BOX_SPH");
        REQUIRE(box);
        CHECK(box->schema->name == "*DEFINE_BOX_SPH");
        CHECK(box->options.empty());
        auto box_title = keywords::find_keyword("*define_box_sph_title");
        REQUIRE(box_title);
        CHECK(box_title->schema->name == "*DEFINE_BOX_SPH");
        CHECK(box_title->has("TITLE"));

        auto tensor = keywords::find_keyword("*SECTION_SPH_TENSOR");
        REQUIRE(tensor);
        CHECK(tensor->has("ELLIPSE"));
        CHECK(card_names(*tensor) == std::vector<std::string>{"Card 1", "Card 2"});

        auto volume = keywords::find_keyword("*ELEMENT_SPH_VOLUME");
        REQUIRE(volume);
        CHECK(volume->schema->name == "*ELEMENT_SPH");
        CHECK(volume->has("VOLUME"));

        auto path = keywords::find_keyword("*INCLUDE_PATH_RELATIVE");
        REQUIRE(path);
        CHECK(path->schema->name == "*INCLUDE_PATH_RELATIVE");
        auto expr = keywords::find_keyword("*PARAMETER_EXPRESSION_LOCAL");
        REQUIRE(expr);
        CHECK(expr->schema->name == "*PARAMETER_EXPRESSION");
        CHECK(expr->has("LOCAL"));
    }
    SUBCASE("unknown options are kept as views into the name") {
        const std::string name = "*Section_Sph_Ellipse_Bogus";
        auto m = keywords::find_keyword(name);
        REQUIRE(m);
        CHECK(m->schema->name == "*SECTION_SPH");
        CHECK(m->has("ELLIPSE"));
        REQUIRE(m->unknown_options.size() == 1);
        CHECK(m->unknown_options[0] == "Bogus");
        CHECK(m->unknown_options[0].data() == name.data() + 21);

        // a hand-written base with an unknown option falls back to the generated layouts when
        // LS-DYNA has the whole name (tests/test_generated_layouts.cpp)
        auto incompressible = keywords::find_keyword("*CONTROL_SPH_INCOMPRESSIBLY");
        REQUIRE(incompressible);
        CHECK(incompressible->unknown_options == std::vector<std::string_view>{"INCOMPRESSIBLY"});

        auto twice = keywords::find_keyword("*SECTION_SPH_TITLE_TITLE");
        REQUIRE(twice);
        CHECK(twice->options.size() == 1);
        CHECK(twice->unknown_options.size() == 1);
    }
}

TEST_CASE("keywords: cards in reading order") {
    auto gen = keywords::find_keyword("*SET_NODE_LIST_GENERATE_TITLE");
    REQUIRE(gen);
    CHECK(card_names(*gen) == std::vector<std::string>{"Title", "Card 1", "Ranges"});
    CHECK(keywords::cards_for(*gen).back()->repeat == CardRepeat::Repeated);

    auto list = keywords::find_keyword("*SET_NODE_LIST");
    REQUIRE(list);
    CHECK(card_names(*list) == std::vector<std::string>{"Card 1", "Ids"});

    auto part = keywords::find_keyword("*PART");
    REQUIRE(part);
    CHECK(card_names(*part) == std::vector<std::string>{"Heading", "Card 2"});
    CHECK(keywords::repeat_group_size(*part) == 2);
    CHECK(keywords::repeat_group_size(*list) == 0);

    auto coupling = keywords::find_keyword("*DEFINE_SPH_TO_SPH_COUPLING_ID");
    REQUIRE(coupling);
    CHECK(card_names(*coupling) == std::vector<std::string>{"ID card", "Card 1", "Card 2"});

    auto elastic = keywords::find_keyword("*MAT_ELASTIC");
    REQUIRE(elastic);
    const CardSpec* card11 = keywords::cards_for(*elastic)[1];
    REQUIRE(card11->present_if);
    CHECK(card11->present_if->field == "E");
    CHECK(card11->present_if->holds(-1.0));
    CHECK_FALSE(card11->present_if->holds(2.0e5));

    auto velocity = keywords::find_keyword("*INITIAL_VELOCITY");
    REQUIRE(velocity);
    REQUIRE(velocity->schema->cards.size() == 3);
    CHECK(velocity->schema->cards[2].present_if->field == "NSIDEX");

    CHECK(keywords::find_keyword("*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS")->schema->cards.empty());
    CHECK(schema("*COMMENT").free_text);
}

TEST_CASE("keywords: *CONTROL_SPH fields as the reference gives them") {
    const KeywordSchema& k = schema("*CONTROL_SPH");
    REQUIRE(k.cards.size() == 3);
    CHECK(k.cards[0].repeat == CardRepeat::Once);
    CHECK(k.cards[1].repeat == CardRepeat::Optional);
    CHECK(k.cards[2].repeat == CardRepeat::Optional);

    const auto* idim = k.cards[0].field("IDIM");
    REQUIRE(idim);
    CHECK_FALSE(idim->default_value);
    CHECK_FALSE(idim->zero_is_default);
    CHECK_FALSE(idim->required);
    CHECK(idim->choice(-2));
    CHECK_FALSE(idim->choice(1));

    const auto* memory = k.cards[0].field("nmneigh");
    REQUIRE(memory);
    CHECK(memory->name == "MEMORY");
    CHECK(*memory->default_value == 150);

    const auto* form = k.cards[0].field("FORM");
    REQUIRE(form);
    for (long long v : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 13, 15, 16}) CHECK(form->choice(v));
    for (long long v : {11, 14, 17, -1}) CHECK_FALSE(form->choice(v));

    CHECK(k.cards[1].field("INI")->choices.size() == 3);
    CHECK(k.cards[1].field("IEROD")->choices.size() == 4);
    CHECK(k.cards[2].fields[3].type == FieldType::Unused);
    CHECK(k.cards[2].field("ISHIFT")->column == 51);

    const auto& sec = schema("*SECTION_SPH");
    CHECK(sec.cards[0].field("CSLH")->zero_is_default);
    CHECK(sec.cards[0].field("SPHKERN")->choices.size() == 4);

    const auto* tssfac = schema("*CONTROL_TIMESTEP").cards[0].field("TSSFAC");
    REQUIRE(tssfac);
    CHECK(*tssfac->default_value == doctest::Approx(0.9));
    CHECK(tssfac->zero_is_default);
}

TEST_CASE("keywords: layouts in standard, I10 and long format") {
    const CardSpec& node = schema("*NODE").cards[0];
    CHECK(slots(node, CardFormat::Standard) == "0:8 8:16 24:16 40:16 56:8 64:8");
    CHECK(slots(node, CardFormat::I10) == "0:10 10:16 26:16 42:16 58:10 68:10");    // I10, 3E16, 2I10
    CHECK(slots(node, CardFormat::Long) == "0:20 20:20 40:20 60:20 80:20 100:20");  // I20, 3E20, 2I20

    const CardSpec& particle = schema("*ELEMENT_SPH").cards[0];
    CHECK(slots(particle, CardFormat::Standard) == "0:8 8:8 16:16 32:10");
    CHECK(slots(particle, CardFormat::I10) == "0:10 10:10 20:16 36:10");  // 2I10, E16, I10
    CHECK(slots(particle, CardFormat::Long) == "0:20 20:20 40:20 60:20");

    const CardSpec& control = schema("*CONTROL_SPH").cards[0];
    CHECK(slots(control, CardFormat::I10) == slots(control, CardFormat::Standard));
    CHECK(slots(control, CardFormat::Long) == "0:20 20:20 40:20 60:20 80:20 100:20 120:20 140:20");
    CHECK(keywords::significant_width(control, CardFormat::Standard) == 80);
    CHECK(keywords::significant_width(control, CardFormat::I10) == 80);
    CHECK(keywords::significant_width(control, CardFormat::Long) == 160);

    // The unused columns 31-40 of card 3 widen like a field.
    const CardSpec& card3 = schema("*CONTROL_SPH").cards[2];
    CHECK(slots(card3, CardFormat::Long) == "0:20 20:20 40:20 60:20 80:20 100:20");

    // A gap that is not written as a field widens the same way.
    CardSpec gap{.name = "gap",
                 .fields = {{.name = "A", .column = 1, .width = 8}, {.name = "B", .column = 17, .width = 8}}};
    CHECK(slots(gap, CardFormat::I10) == "0:10 20:10");
    CHECK(slots(gap, CardFormat::Long) == "0:20 40:20");

    // Titles and file names run to column 160 in long format.
    const CardSpec& file = schema("*INCLUDE").cards[0];
    CHECK(slots(file, CardFormat::Long) == "0:160");
    CHECK(slots(file, CardFormat::I10) == "0:80");
    const CardSpec& expression = schema("*PARAMETER_EXPRESSION").cards[0];
    CHECK(slots(expression, CardFormat::Long) == "0:20 20:140");

    // *DEFINE_CURVE points: 2 x F20 stay 20 wide.
    const CardSpec& point = schema("*DEFINE_CURVE").cards[1];
    CHECK(slots(point, CardFormat::Long) == "0:20 20:20");
}

TEST_CASE("keywords: did you mean") {
    auto s = keywords::similar_keywords("*CONTROL_SHP");
    REQUIRE_FALSE(s.empty());
    CHECK(s.front() == "*CONTROL_SPH");
    CHECK(s.size() <= 3);

    auto sec = keywords::similar_keywords("*secton_sph_ellipse");
    REQUIRE_FALSE(sec.empty());
    CHECK(sec.front() == "*SECTION_SPH");

    CHECK(keywords::similar_keywords("*ELEMENT_SPHH", 1) == std::vector<std::string_view>{"*ELEMENT_SPH"});
    CHECK(keywords::similar_keywords("*COMPLETELY_DIFFERENT_THING").empty());
}

TEST_CASE("keywords: to_string of the schema enums") {
    CHECK(keywords::to_string(FieldType::Integer) == "I");
    CHECK(keywords::to_string(FieldType::Real) == "F");
    CHECK(keywords::to_string(FieldType::Text) == "A");
    CHECK(keywords::to_string(FieldType::Label) == "I/A");
    CHECK(keywords::to_string(FieldType::Unused) == "-");
    CHECK(keywords::to_string(CardRepeat::Repeated) == "repeated");
    CHECK(keywords::to_string(keywords::Compare::Less) == "<");
}
}  // namespace test_keywords_cpp
