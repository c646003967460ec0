// RAD040, the starter's value checks (lint/starter_checks.hpp): the table against its layouts and
// docs/radioss.md, a seeded value past each bound planted into a block of its law (an error on the
// planted line), the same block with good values silent, and the shipped SOL2SPH deck before and
// after its fix. RAD042: /TH selections against the kind their keyword names.
#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "engine/check.hpp"
#include "grammar/radioss/generated_layouts.hpp"
#include "lint/starter_checks.hpp"
#include "test_support.hpp"

namespace test_starter_checks_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace rad = grammar::radioss;
using lint::radioss::Allowed;
using lint::radioss::StarterCheck;
using lint::radioss::StarterLaw;

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

engine::CheckResult check(const std::string& text) {
    return engine::check_buffer(text, "deck_0000.rad", {}, grammar::DeckFormat::Radioss);
}

// The lines (1-based) of the findings of `code`.
std::multiset<std::uint32_t> lines_of(const engine::CheckResult& r, std::string_view code) {
    std::multiset<std::uint32_t> out;
    for (const auto& d : r.diagnostics)
        if (d.code == code) out.insert(d.span.line);
    return out;
}

const rad::FormatSpec& newest(const StarterLaw& law) {
    if (!law.layout.empty()) return law.layout.front();
    const rad::KeywordSpec* g = rad::generated::keyword_named(law.names.front());
    REQUIRE(g != nullptr);
    return g->formats.front();
}

// A value each check accepts, and one past its bound.
double good(Allowed a) {
    switch (a) {
        case Allowed::ZeroToOne:
        case Allowed::AtMostOne: return 0.5;
        case Allowed::ZeroToHalf: return 0.3;
        case Allowed::AboveOne: return 1.4;
        default: return 1.0;
    }
}
double bad(Allowed a) {
    switch (a) {
        case Allowed::Positive: return -1.0;
        case Allowed::AboveMinusOne: return -1.0;
        case Allowed::NotZero: return 0.0;
        case Allowed::ZeroToOne: return 1.5;
        case Allowed::AtMostOne: return 1.5;
        case Allowed::ZeroToHalf: return 0.5;
        case Allowed::AtMostHundred: return 101.0;
        case Allowed::AboveOne: return 1.0;
        case Allowed::NotNegative: return -1.0;
    }
    return 0.0;
}

// "MAT_SRC!0&MAT_Iflag=1&MLAW51_Rho>0" → values that make it hold.
void satisfy(std::string_view condition, std::map<std::string, double>& values) {
    while (!condition.empty()) {
        const std::size_t amp = condition.find('&');
        const std::string_view part = condition.substr(0, amp);
        const std::size_t op = part.find_first_of("=!>");
        const std::string name(part.substr(0, op));
        const double number = std::stod(std::string(part.substr(op + 1)));
        if (part[op] == '=')
            values[name] = number;
        else if (part[op] == '>' && values[name] <= number)
            values[name] = number + 1;
        else if (part[op] == '!' && values[name] == number)
            values[name] = number + 1;
        condition = amp == std::string_view::npos ? std::string_view{} : condition.substr(amp + 1);
    }
}

std::string cell(const rad::FieldSpec& f, double v) {
    const std::size_t width = f.width ? f.width : f.cell == rad::Cell::Real ? 20 : 10;
    std::ostringstream s;
    if (f.cell == rad::Cell::Int)
        s << static_cast<long long>(v);
    else if (f.cell == rad::Cell::Real)
        s << v << (v == static_cast<long long>(v) ? ".0" : "");
    std::string text = f.name.empty() ? std::string() : s.str();
    return std::string(width > text.size() ? width - text.size() : 0, ' ') + text;
}

struct Planted {
    std::string text;
    std::uint32_t line = 0;  // the line of the planted field
};

// A deck with one block of `law`'s first name, every field of its cards read once at `values`
// (0 when absent), the field `planted` marked.
Planted deck_of(const StarterLaw& law, const std::map<std::string, double>& values, std::string_view planted) {
    const rad::FormatSpec& format = newest(law);
    std::string text = "#RADIOSS STARTER\n/BEGIN\nseed\n      2026\n" + std::string(3, ' ') + "\n" +
                       std::string(3, ' ') + "\n" + std::string(law.names.front()) + "/1\nseeded\n";
    std::uint32_t line = 9, at = 0;
    std::map<std::string, double> earlier;  // for the cards' conditions
    for (const rad::CardSpec& card : format.cards) {
        if (card.repeat == rad::Repeat::Repeated) break;
        struct Earlier final : rad::EarlierValues {
            const std::map<std::string, double>* v;
            double operator()(std::string_view f) const override {
                auto it = v->find(std::string(f));
                return it == v->end() ? 0.0 : it->second;
            }
        } e;
        e.v = &values;
        if (!rad::generated::condition_holds(card.when, e)) continue;
        std::string row;
        for (const rad::FieldSpec& f : card.fields) {
            auto it = values.find(std::string(f.name));
            row += cell(f, it == values.end() ? 0.0 : it->second);
            if (f.name == planted) at = line;
        }
        text += row + "\n";
        ++line;
    }
    return {text + "/END\n", at};
}

}  // namespace

TEST_CASE("starter checks: every field of the table is a field of its law's layout, and docs/radioss.md lists it") {
    const std::string docs = slurp(SPHDECK_SOURCE_DIR "/docs/radioss.md");
    for (const StarterLaw& law : lint::radioss::starter_laws()) {
        const rad::FormatSpec& format = newest(law);
        for (const StarterCheck& check : law.checks) {
            INFO(law.names.front() << " " << check.field);
            bool found = false;
            for (const rad::CardSpec& card : format.cards)
                found = found || card.index(check.field) < card.fields.size();
            CHECK(found);
            CHECK(docs.find("`" + std::string(check.source) + "`") != std::string::npos);
            CHECK(docs.find("| " + std::to_string(check.message) + " ") != std::string::npos);
        }
        for (std::string_view name : law.names) CHECK(lint::radioss::starter_law_of(std::string(name) + "/12") == &law);
    }
    CHECK(lint::radioss::starter_law_of("/MAT/LAW99/1") == nullptr);
}

TEST_CASE("starter checks: a value past each bound is an error on its line; good values are silent") {
    std::size_t seeded = 0;
    for (const StarterLaw& law : lint::radioss::starter_laws()) {
        std::map<std::string, double> values;
        for (const StarterCheck& c : law.checks) values[std::string(c.field)] = good(c.allowed);
        const Planted clean = deck_of(law, values, "");
        INFO(clean.text);
        CHECK(lines_of(check(clean.text), "RAD040").empty());
        for (const StarterCheck& c : law.checks) {
            std::map<std::string, double> seeded_values = values;
            satisfy(c.when, seeded_values);
            for (const rad::CardSpec& card : newest(law).cards)
                if (card.index(c.field) < card.fields.size()) satisfy(card.when, seeded_values);
            seeded_values[std::string(c.field)] = bad(c.allowed);
            const Planted p = deck_of(law, seeded_values, c.field);
            INFO(law.names.front() << " " << c.field << " = " << bad(c.allowed) << "\n" << p.text);
            REQUIRE(p.line != 0);
            const auto found = lines_of(check(p.text), c.reported_by.empty() ? "RAD040" : c.reported_by);
            CHECK(found.count(p.line) >= 1);
            ++seeded;
        }
    }
    CHECK(seeded >= 20);
}

TEST_CASE("starter checks: the shipped SOL2SPH deck passes, and fires without its yield card or with A = 0") {
    const std::string path = SPHDECK_SOURCE_DIR "/decks/sol2sph/bumper_0000.rad";
    const std::string fixed = slurp(path);
    CHECK(lines_of(check(fixed), "RAD040").empty());
    // The deck as shipped before: the LAW2 block ends after E and Nu (starter error 301).
    const std::string yield =
        "#                  a                   b                   n           EPS_p_max"
        "            SIG_max0\n                0.35                0.28                0.32\n";
    const std::size_t at = fixed.find(yield);
    REQUIRE(at != std::string::npos);
    std::string unfixed = fixed;
    unfixed.erase(at, yield.size());
    const auto line_of = [](const std::string& text, std::size_t offset) {
        return static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + offset, '\n') + 1);
    };
    CHECK(lines_of(check(unfixed), "RAD040") == std::multiset<std::uint32_t>{line_of(unfixed, at) - 1});
    // A = 0 written.
    std::string zero = fixed;
    zero.replace(zero.find("                0.35", at), 20, "                 0.0");
    CHECK(lines_of(check(zero), "RAD040") == std::multiset<std::uint32_t>{line_of(fixed, at) + 1});
    // A negative density on the same block: SPH119 says it (the table's density row names it).
    std::string rho = fixed;
    rho.replace(rho.find("              7.8E-6"), 20, "             -7.8E-6");
    CHECK(lines_of(check(rho), "SPH119").size() == 1);
    CHECK(lines_of(check(rho), "RAD040").empty());
}

TEST_CASE("starter checks: a line deleted from a /MAT/LAW51 Iform 10 is message 99 on the block's last line") {
    const std::string whole = slurp(SPHDECK_SOURCE_DIR "/decks/tests/rad/RAD040_silent_law51_eos.rad");
    CHECK(lines_of(check(whole), "RAD040").empty());
    const std::size_t block = whole.find("/MAT/LAW51/1\n");
    const std::size_t end = whole.find("/MAT/LAW6/2\n");
    REQUIRE(block != std::string::npos);
    // The block's value lines (not comments), after its header and title.
    std::vector<std::size_t> values;
    for (std::size_t at = whole.find('\n', whole.find('\n', block) + 1) + 1; at < end; at = whole.find('\n', at) + 1)
        if (whole[at] != '#') values.push_back(at);
    REQUIRE(values.size() == 24);
    // From the third card (P_EXT) on, every deletion leaves the last card (D, PCJ, C14) blank.
    for (std::size_t k = 2; k < values.size(); ++k) {
        std::string deck = whole;
        deck.erase(values[k], whole.find('\n', values[k]) + 1 - values[k]);
        const auto r = check(deck);
        // The block's last value line (a comment line may follow it).
        std::size_t last = deck.rfind('\n', deck.find("/MAT/LAW6/2\n") - 1);
        while (deck[deck.rfind('\n', last - 1) + 1] == '#') last = deck.rfind('\n', last - 1);
        const std::uint32_t last_line =
            static_cast<std::uint32_t>(std::count(deck.begin(), deck.begin() + last, '\n') + 1);
        INFO("card " << k + 1 << " deleted");
        CHECK(lines_of(r, "RAD040") == std::multiset<std::uint32_t>{last_line});
        const diag::Diagnostic* d = test::find_code(r.diagnostics, "RAD040");
        REQUIRE(d);
        CHECK(d->message.find("starter message 99") != std::string::npos);
        CHECK(d->message.find("ends before card") != std::string::npos);
    }
}
}  // namespace test_starter_checks_cpp
