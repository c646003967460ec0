// sphdeck.toml: parsing, errors with positions, discovery upwards, command-line overrides, and
// what the settings do to a run.
#include <doctest/doctest.h>

#include <filesystem>

#include "engine/config_file.hpp"
#include "lint/config.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_config_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace fs = std::filesystem;

namespace {

lint::ConfigError parse_error(const std::string& text) {
    lint::Config config;
    auto error = lint::parse_config(text, "/p/sphdeck.toml", config);
    REQUIRE(error.has_value());
    return *error;
}

diag::Diagnostic finding(const std::string& code, diag::Severity severity) {
    return diag::Diagnostic{code, severity, "m", grammar::Span{}, {}};
}

}  // namespace

TEST_CASE("config: every key is read") {
    lint::Config c;
    const auto error = lint::parse_config(R"(
select = ["SPH", "DK003", "form-advice"]
ignore = ["SPH032"]
solver = "mpp"
fail-on = "warning"
include-paths = ["mesh", "../shared"]

[severity]
SPH034 = "error"
unknown-keyword = "warning"
)",
                                          "/project/decks/sphdeck.toml", c);
    REQUIRE_FALSE(error.has_value());
    CHECK(c.path == "/project/decks/sphdeck.toml");
    CHECK(c.select == std::vector<std::string>{"SPH", "DK003", "form-advice"});
    CHECK(c.ignore == std::vector<std::string>{"SPH032"});
    CHECK(c.solver == "mpp");
    CHECK(c.fail_on == lint::FailOn::Warning);
    CHECK(c.include_paths == std::vector<std::string>{"/project/decks/mesh", "/project/shared"});
    CHECK(c.severity.at("SPH034") == diag::Severity::Error);
    CHECK(c.severity.at("DK001") == diag::Severity::Warning);  // names become codes
}

TEST_CASE("config: errors name the file, line and column") {
    auto e = parse_error("select = [\"SPH\"\nignore = 3\n");
    CHECK(e.file == "/p/sphdeck.toml");
    CHECK(e.line == 2);
    CHECK(e.to_string().starts_with("/p/sphdeck.toml:2:"));
    CHECK(e.to_string().find(": error: invalid TOML") != std::string::npos);

    e = parse_error("solver = \"smp\"\n  selct = [\"SPH\"]\n");
    CHECK(e.line == 2);
    CHECK(e.column == 3);
    CHECK(e.message.find("unknown key 'selct'") != std::string::npos);

    e = parse_error("ignore = \"SPH032\"\n");
    CHECK(e.line == 1);
    CHECK(e.message == "'ignore' must be an array of strings");

    e = parse_error("select = [\"DK003\", 7]\n");
    CHECK(e.column == 20);

    e = parse_error("ignore = [\"SPH032\", \"SPH3O\"]\n");
    CHECK(e.column == 21);
    CHECK(e.message.find("unknown rule 'SPH3O'; did you mean 'SPH030'") != std::string::npos);

    e = parse_error("[severity]\nSPH032 = \"fatal\"\n");
    CHECK(e.line == 2);
    CHECK(e.message.find("\"error\", \"warning\" or \"info\"") != std::string::npos);
    CHECK(parse_error("[severity]\nSPH = \"error\"\n").message.find("not one rule") != std::string::npos);
    CHECK(parse_error("severity = 1\n").message.find("must be a table") != std::string::npos);
    CHECK(parse_error("solver = \"cluster\"\n").message == "'solver' must be one of 'smp', 'mpp'");
    CHECK(parse_error("fail-on = true\n").message.find("'fail-on' must be one of") != std::string::npos);
    CHECK(parse_error("include-paths = [1]\n").message == "'include-paths' must be an array of strings");

    lint::Config c;
    auto missing = engine::load_config("/nonexistent/sphdeck.toml", c);
    REQUIRE(missing.has_value());
    CHECK(missing->to_string() == "/nonexistent/sphdeck.toml: error: cannot read the configuration file");
}

TEST_CASE("config: found in the deck's folder or the nearest folder above it") {
    test::TempDir dir;
    const std::string deck = dir.write("a/b/c/deck.k", "*KEYWORD\n*END\n");
    CHECK_FALSE(engine::find_config(deck).has_value());  // assumes no sphdeck.toml above the temp dir
    dir.write("sphdeck.toml", "");
    CHECK(engine::find_config(deck) == dir.path() / "sphdeck.toml");
    dir.write("a/.sphdeck.toml", "");
    CHECK(engine::find_config(deck) == dir.path() / "a" / ".sphdeck.toml");
    dir.write("a/sphdeck.toml", "");  // preferred over the hidden name in the same folder
    CHECK(engine::find_config(deck) == dir.path() / "a" / "sphdeck.toml");
    dir.write("a/b/c/sphdeck.toml", "");
    CHECK(engine::find_config(deck) == dir.path() / "a" / "b" / "c" / "sphdeck.toml");
}

TEST_CASE("config: command-line options override the file") {
    lint::Config c;
    c.select = {"SPH"};
    c.ignore = {"SPH032"};
    c.solver = "smp";
    c.fail_on = lint::FailOn::Warning;
    c.include_paths = {"/from/file"};
    lint::ConfigOverrides o;
    lint::apply_overrides(o, c);  // nothing given: the file stands
    CHECK(c.select == std::vector<std::string>{"SPH"});
    CHECK(c.solver == "smp");

    o.select = std::vector<std::string>{"DK"};
    o.ignore = {"DK001"};
    o.solver = "mpp";
    o.fail_on = lint::FailOn::Never;
    o.include_paths = {"/from/cli"};
    lint::apply_overrides(o, c);
    CHECK(c.select == std::vector<std::string>{"DK"});               // replaced
    CHECK(c.ignore == std::vector<std::string>{"SPH032", "DK001"});  // extended
    CHECK(c.solver == "mpp");
    CHECK(c.fail_on == lint::FailOn::Never);
    CHECK(c.include_paths == std::vector<std::string>{"/from/cli", "/from/file"});  // command line first
}

TEST_CASE("config: select, ignore and severity act on findings") {
    lint::Config c;
    c.select = {"SPH03", "bad-real"};
    c.ignore = {"sph032"};
    c.severity["SPH030"] = diag::Severity::Info;
    std::vector<diag::Diagnostic> ds = {finding("SPH030", diag::Severity::Error),
                                        finding("SPH032", diag::Severity::Warning),
                                        finding("DK003", diag::Severity::Error), finding("DK001", diag::Severity::Info),
                                        finding("SPH100", diag::Severity::Error)};
    lint::apply_rule_settings(c, ds);
    REQUIRE(ds.size() == 2);
    CHECK(ds[0].code == "SPH030");
    CHECK(ds[0].severity == diag::Severity::Info);
    CHECK(ds[1].code == "DK003");
}

TEST_CASE("config: fail-on thresholds") {
    const std::vector<diag::Diagnostic> warning = {finding("DK027", diag::Severity::Warning)};
    const std::vector<diag::Diagnostic> info = {finding("DK001", diag::Severity::Info)};
    lint::Config c;
    CHECK_FALSE(lint::fails(c, warning));  // default: error
    c.fail_on = lint::FailOn::Warning;
    CHECK(lint::fails(c, warning));
    CHECK_FALSE(lint::fails(c, info));
    c.fail_on = lint::FailOn::Info;
    CHECK(lint::fails(c, info));
    c.fail_on = lint::FailOn::Never;
    CHECK_FALSE(lint::fails(c, {finding("DK003", diag::Severity::Error)}));
}

TEST_CASE("config: the binary finds, applies, overrides and rejects config files") {
    test::TempDir dir;
    dir.write("decks/sub/bad.k", "*KEYWORD\n*CONTROL_TERMINATION\nabc\n*END\n");  // DK003 error
    const std::string deck = "decks/sub/bad.k";
    CHECK(test::run_sphdeck(dir, "check " + deck).exit_code == 1);

    dir.write("sphdeck.toml", "select = [\"DK\"]\n[severity]\nDK003 = \"warning\"\n");  // two folders up
    test::Run r = test::run_sphdeck(dir, "check --format concise " + deck);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("warning: 'abc'") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "check --fail-on warning " + deck).exit_code == 1);  // option over file
    CHECK(test::run_sphdeck(dir, "check --no-config " + deck).exit_code == 1);

    // The nearer file wins; there is no merging.
    dir.write("decks/sphdeck.toml", "fail-on = \"warning\"\nselect = [\"DK\"]\nignore = [\"DK003\"]\n");
    r = test::run_sphdeck(dir, "check --format concise " + deck);
    CHECK(r.exit_code == 0);
    CHECK(r.out.empty());
    CHECK(test::run_sphdeck(dir, "check --config sphdeck.toml --fail-on warning " + deck).exit_code == 1);

    dir.write("decks/sphdeck.toml", "ignore = [\"DK\"]\nsolvr = \"mpp\"\n");
    r = test::run_sphdeck(dir, "check --format json " + deck);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());  // nothing half-written
    CHECK(r.err.find("decks/sphdeck.toml:2:1: error: unknown key 'solvr'") != std::string::npos);
    CHECK(test::run_sphdeck(dir, "check --config missing.toml " + deck).exit_code == 2);
    CHECK(test::run_sphdeck(dir, "check --config sphdeck.toml --no-config " + deck).exit_code == 2);
}
}  // namespace test_config_cpp
