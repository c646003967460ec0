// Radioss /PARAMETER (model/radioss_parameters.hpp): global INTEGER and REAL values substituted
// into later cells as [name], -[name], &name or -&name; use before definition and undefined
// names (DK012), a REAL in an integer cell (DK013), redefinition (DK014), kinds that are not
// evaluated (DK001, info) and malformed definitions.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include "engine/check.hpp"
#include "model/radioss_parameters.hpp"
#include "test_support.hpp"

namespace test_radioss_parameters_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;
using test::find_code;

namespace {

std::string i10(const std::string& v) { return fmt::format("{:>10}", v); }
std::string r20(const std::string& v) { return fmt::format("{:>20}", v); }
std::string node(const std::string& id, const std::string& x, const std::string& y = "0.0") {
    return i10(id) + r20(x) + r20(y) + r20("0.0") + "\n";
}
std::string real_parameter(int id, const std::string& name, const std::string& value) {
    return fmt::format("/PARAMETER/GLOBAL/REAL/{}\ntitle\n{:<10}{:>20}\n", id, name, value);
}
std::string integer_parameter(int id, const std::string& name, const std::string& value) {
    return fmt::format("/PARAMETER/GLOBAL/INTEGER/{}\ntitle\n{:<10}{:>10}\n", id, name, value);
}

engine::CheckResult check(const std::string& body) {
    return engine::check_buffer("#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n" + body + "/END\n", "deck_0000.rad", {},
                                grammar::DeckFormat::Radioss);
}

// The x coordinate the model holds for node `id`.
double x_of(const engine::CheckResult& r, long long id) {
    const auto& n = r.model.nodes;
    for (std::size_t i = 0; i < n.id.size(); ++i)
        if (n.id[i] == id) return n.x[i];
    FAIL("no node ", id);
    return 0;
}

}  // namespace

TEST_CASE("radioss parameters: the four reference forms, and what is no reference") {
    using model::radioss_parameter_reference;
    auto a = radioss_parameter_reference("[width]");
    REQUIRE(a);
    CHECK(a->name == "width");
    CHECK_FALSE(a->negated);
    CHECK(a->closed);
    auto b = radioss_parameter_reference("-[width]");
    REQUIRE(b);
    CHECK(b->negated);
    auto c = radioss_parameter_reference("-&w");
    REQUIRE(c);
    CHECK(c->name == "w");
    CHECK(c->negated);
    auto d = radioss_parameter_reference("[widthwid");
    REQUIRE(d);
    CHECK_FALSE(d->closed);
    for (const char* no : {"1.0", "[]", "[a]b", "&", "-", "", "width"}) {
        INFO(no);
        CHECK_FALSE(radioss_parameter_reference(no));
    }
}

TEST_CASE("radioss parameters: global INTEGER and REAL values reach later cells") {
    auto r = check(real_parameter(1, "width", "2.5") + integer_parameter(2, "first", "1001") + "/NODE\n" +
                   node("[first]", "[width]") + node("1002", "-[width]") + node("1003", "&width") +
                   node("1004", "-&width") + node("1005", "[first]"));
    CHECK(r.diagnostics.empty());
    CHECK(x_of(r, 1001) == 2.5);
    CHECK(x_of(r, 1002) == -2.5);
    CHECK(x_of(r, 1003) == 2.5);
    CHECK(x_of(r, 1004) == -2.5);
    CHECK(x_of(r, 1005) == 1001.0);  // an INTEGER in a real cell
    // A parameter value may itself use an earlier parameter.
    r = check(real_parameter(1, "a", "1.5") + real_parameter(2, "b", "-[a]") + "/NODE\n" + node("1", "[b]"));
    CHECK(r.diagnostics.empty());
    CHECK(x_of(r, 1) == -1.5);
}

TEST_CASE("radioss parameters: use before the definition names the definition (DK012)") {
    auto r = check("/NODE\n" + node("1001", "[width]") + real_parameter(1, "width", "2.5"));
    REQUIRE(count_code(r.diagnostics, "DK012") == 1);
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK012");
    CHECK(d->message.find("before its definition") != std::string::npos);
    CHECK(d->span.line == 6);
    CHECK(d->span.column == 24);  // "[width]" right-aligned in columns 11-30
    CHECK(d->span.end_column == 31);
    REQUIRE(d->notes.size() == 1);
    CHECK(d->notes[0].span.line == 9);  // the name on the definition card
    CHECK(d->notes[0].span.column == 1);
    CHECK(x_of(r, 1001) == 0.0);  // no value: unknown
}

TEST_CASE("radioss parameters: undefined names, case mismatch, a reference cut by its cell (DK012)") {
    auto r = check(real_parameter(1, "width", "2.5") + "/NODE\n" + node("1", "[depth]"));
    REQUIRE(count_code(r.diagnostics, "DK012") == 1);
    CHECK(find_code(r.diagnostics, "DK012")->message == "undefined parameter 'depth'");

    r = check(real_parameter(1, "width", "2.5") + "/NODE\n" + node("1", "[WIDTH]"));
    REQUIRE(count_code(r.diagnostics, "DK012") == 1);
    CHECK(find_code(r.diagnostics, "DK012")->message.find("did you mean 'width'") != std::string::npos);

    // A 10-column id cell cannot hold "[widthwide]": the reference is cut.
    r = check(integer_parameter(1, "widthwide", "5") + "/NODE\n" + " [widthwide]" + r20("0.0") + r20("0.0") +
              r20("0.0") + "\n");
    REQUIRE(count_code(r.diagnostics, "DK012") >= 1);
    CHECK(find_code(r.diagnostics, "DK012")->message.find("no closing ']'") != std::string::npos);
}

TEST_CASE("radioss parameters: a REAL in an integer cell (DK013)") {
    auto r = check(real_parameter(1, "id", "7.0") + "/NODE\n" + node("[id]", "0.0"));
    REQUIRE(count_code(r.diagnostics, "DK013") == 1);
    CHECK(find_code(r.diagnostics, "DK013")->message == "real parameter 'id' used in integer field node_ID");
    CHECK(r.model.nodes.id.empty());
}

TEST_CASE("radioss parameters: a second definition keeps the first (DK014)") {
    auto r =
        check(real_parameter(1, "width", "2.5") + real_parameter(2, "width", "3.5") + "/NODE\n" + node("1", "[width]"));
    REQUIRE(count_code(r.diagnostics, "DK014") == 1);
    const diag::Diagnostic* d = find_code(r.diagnostics, "DK014");
    CHECK(d->severity == diag::Severity::Warning);
    CHECK(d->span.line == 10);
    REQUIRE(d->notes.size() == 1);
    CHECK(d->notes[0].span.line == 7);
    CHECK(x_of(r, 1) == 2.5);
}

TEST_CASE("radioss parameters: expressions, text and local parameters are not evaluated (DK001)") {
    for (const char* kind : {"GLOBAL/REAL_EXPR", "GLOBAL/INT_EXPR", "LOCAL/REAL", "GLOBAL/TEXT"}) {
        INFO(kind);
        auto r = check(fmt::format("/PARAMETER/{}/1\ntitle\nhalf      [width] / 2\n", kind) + "/NODE\n" +
                       node("1", "[half]"));
        REQUIRE(count_code(r.diagnostics, "DK001") == 1);
        const diag::Diagnostic* d = find_code(r.diagnostics, "DK001");
        CHECK(d->severity == diag::Severity::Info);
        CHECK(d->message.find("'half' is not evaluated") != std::string::npos);
        CHECK(d->span.line == 7);
        CHECK(r.diagnostics.size() == 1);  // its use is neither undefined nor a bad number
        CHECK(x_of(r, 1) == 0.0);
    }
}

TEST_CASE("radioss parameters: malformed definitions are reported, not a crash") {
    auto r = check("/PARAMETER/GLOBAL/REAL/1\ntitle only\n");
    CHECK(count_code(r.diagnostics, "DK008") == 1);
    r = check("/PARAMETER/GLOBAL/REAL/1\ntitle\n" + std::string(10, ' ') + r20("1.0") + "\n");
    REQUIRE(count_code(r.diagnostics, "DK008") == 1);
    CHECK(find_code(r.diagnostics, "DK008")->message.find("name") != std::string::npos);
    r = check(real_parameter(1, "a", "abc"));
    CHECK(count_code(r.diagnostics, "DK003") == 1);
    r = check(real_parameter(1, "a", "1.0") + "b                        2.0\n");
    CHECK(count_code(r.diagnostics, "DK009") == 1);
    r = check("/PARAMETER/GLOBAL/REAL/1\n");  // not even a title
    CHECK(count_code(r.diagnostics, "DK008") == 1);
}

// A fuzzer's header with an empty segment: its segments read GLOBAL and REAL, but the table found for it has no
// name and value card (the value was then taken from a card of one field: an uncaught out_of_range).
TEST_CASE("radioss parameters: a header read by a table without the name and value card is not evaluated") {
    const auto r = check("/PARAMETER//GLOBAL/REAL/1\ntitle\n" + fmt::format("{:<10}{:>20}\n", "width", "2.5") +
                         "/NODE\n" + node("1", "[width]"));
    CHECK(count_code(r.diagnostics, "DK008") == 0);
    REQUIRE(count_code(r.diagnostics, "DK001") == 1);
    CHECK(find_code(r.diagnostics, "DK001")
              ->message.find("no name and value card for the header "
                             "/PARAMETER//GLOBAL/REAL/1") != std::string::npos);
    CHECK(x_of(r, 1) == 0.0);  // not evaluated: its use keeps no value
}
}  // namespace test_radioss_parameters_cpp
