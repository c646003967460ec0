// Decks reached through symbolic links behave exactly as the same decks reached directly (issue 38):
// `check`, `check --fix`, `format --includes`, `diff` and the editor compare files by their canonical
// path (grammar::SourceFile::key) and name them by a path that leads to the file read
// (grammar::normal_path: `link/..` is not folded away lexically).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include "grammar/file_paths.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_symlinked_decks_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace fs = std::filesystem;

namespace {

// root/project/model/deck.k        the deck: includes parts.k, ../common/mat.k and ../store/parts.k
// root/project/model/parts.k  ->   ../store/parts.k (a symbolic link to an include)
// root/project/store/parts.k       so the deck includes this file twice, by two names
// root/project/common/mat.k
// root/model-link  ->  project/model (a symbolic link to the deck's folder)
// root/common/mat.k                a decoy: where model-link/../common/mat.k leads if `..` is folded lexically
// Each file has a safe fix (a keyword in lower case) and a value to realign.
void make_tree(const fs::path& root) {
    const auto write = [&](const std::string& name, const std::string& text) {
        fs::create_directories((root / name).parent_path());
        std::ofstream(root / name, std::ios::binary) << text;
    };
    write("project/model/deck.k",
          "*KEYWORD\n*INCLUDE\nparts.k\n*INCLUDE\n../common/mat.k\n*INCLUDE\n../store/parts.k\n"
          "*control_termination\n  0.5\n*END\n");
    write("project/store/parts.k", "*database_glstat\n  0.01\n");
    write("project/common/mat.k", "*database_matsum\n  0.02\n");
    write("common/mat.k", "*database_matsum\n  0.03\n");
    fs::create_symlink("../store/parts.k", root / "project/model/parts.k");
    fs::create_symlink("project/model", root / "model-link");
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The findings of `check --format json` as (file read, line, code), files by canonical path.
std::set<std::tuple<std::string, int, std::string>> findings(const test::TempDir& dir, const std::string& deck) {
    const test::Run r = test::run_sphdeck(dir, "check --format json --no-config " + deck);
    REQUIRE(r.exit_code == 0);
    std::set<std::tuple<std::string, int, std::string>> out;
    const nlohmann::json report = nlohmann::json::parse(r.out);  // kept: the loop must not walk a temporary
    for (const auto& d : report["diagnostics"])
        out.emplace(fs::canonical(dir.path() / d["file"].get<std::string>()).string(), d["line"].get<int>(),
                    d["code"].get<std::string>());
    return out;
}

const char* const tree_files[] = {"project/model/deck.k", "project/store/parts.k", "project/common/mat.k",
                                  "common/mat.k"};

}  // namespace

TEST_CASE("symlinked decks: canonical and normal paths") {
    test::TempDir dir;
    make_tree(dir.path());
    const fs::path root = fs::canonical(dir.path());
    CHECK(grammar::canonical_path(root / "model-link/parts.k") == root / "project/store/parts.k");
    CHECK(grammar::canonical_path(root / "model-link/../common/mat.k") == root / "project/common/mat.k");
    // Folded lexically only where that names the same file.
    CHECK(grammar::normal_path(root / "project/model/../common/mat.k") == root / "project/common/mat.k");
    CHECK(grammar::normal_path(root / "model-link/../common/mat.k") == root / "project/common/mat.k");
    CHECK(grammar::normal_path("a/./b//c.k") == "a/b/c.k");
}

TEST_CASE("symlinked decks: check finds the same findings in the same files through a linked folder") {
    test::TempDir dir;
    make_tree(dir.path());
    const auto direct = findings(dir, "project/model/deck.k");
    CHECK(findings(dir, "model-link/deck.k") == direct);
    // Every file is named by a path to the file read, never to the decoy.
    for (const auto& [file, line, code] : direct) CHECK(file != fs::canonical(dir.path() / "common/mat.k").string());
    CHECK(direct.size() == 3);  // the lower-case keywords of the deck, of parts.k (read twice) and of mat.k
}

TEST_CASE("symlinked decks: an include checked by its name is checked in its deck, both named as reached") {
    test::TempDir dir;
    make_tree(dir.path());
    CHECK(findings(dir, "model-link/parts.k") == findings(dir, "project/store/parts.k"));
    const test::Run r = test::run_sphdeck(dir, "check --format concise --no-config model-link/parts.k");
    CHECK(r.out.find("model-link/parts.k: checked as included by model-link/deck.k\n") != std::string::npos);
    CHECK(r.out.find("model-link/parts.k:1:1: info:") != std::string::npos);  // the keyword in lower case
}

TEST_CASE("symlinked decks: check --fix and --diff mend each file once, through links as directly") {
    test::TempDir linked, direct;
    make_tree(linked.path());
    make_tree(direct.path());
    // --diff: the file included by two names is one file with one diff.
    const test::Run diff = test::run_sphdeck(linked, "check --diff --no-config model-link/deck.k");
    CHECK(diff.exit_code == 1);
    std::size_t headers = 0;
    for (std::size_t at = 0; (at = diff.out.find("\n+++ ", at)) != std::string::npos; ++at) ++headers;
    CHECK(headers == 3);  // deck.k, store/parts.k, project/common/mat.k
    CHECK(diff.out.find("common/mat.k") != std::string::npos);
    CHECK(diff.out.find("b/common/mat.k") == std::string::npos);  // never the decoy

    CHECK(test::run_sphdeck(linked, "check --fix --no-config model-link/deck.k").exit_code == 0);
    CHECK(test::run_sphdeck(direct, "check --fix --no-config project/model/deck.k").exit_code == 0);
    for (const char* name : tree_files) {
        CAPTURE(name);
        CHECK(slurp(linked.path() / name) == slurp(direct.path() / name));
    }
    CHECK(fs::is_symlink(linked.path() / "project/model/parts.k"));
    CHECK(slurp(linked.path() / "project/store/parts.k").rfind("*DATABASE_GLSTAT\n", 0) == 0);
    CHECK(slurp(linked.path() / "common/mat.k") == "*database_matsum\n  0.03\n");  // the decoy untouched
}

TEST_CASE("symlinked decks: format --includes writes a link's target and keeps the link") {
    test::TempDir linked, direct;
    make_tree(linked.path());
    make_tree(direct.path());
    CHECK(test::run_sphdeck(linked, "format --includes model-link/deck.k").exit_code == 0);
    CHECK(test::run_sphdeck(direct, "format --includes project/model/deck.k").exit_code == 0);
    for (const char* name : tree_files) {
        CAPTURE(name);
        CHECK(slurp(linked.path() / name) == slurp(direct.path() / name));
    }
    CHECK(fs::is_symlink(linked.path() / "project/model/parts.k"));
    CHECK(fs::is_symlink(direct.path() / "project/model/parts.k"));
    CHECK(slurp(linked.path() / "project/store/parts.k") == "*DATABASE_GLSTAT\n      0.01\n");
    CHECK(slurp(linked.path() / "common/mat.k") == "*database_matsum\n  0.03\n");
    CHECK(test::run_sphdeck(linked, "format --check --includes model-link/deck.k").exit_code == 0);
}

TEST_CASE("symlinked decks: diff reads the same deck through a link and directly") {
    test::TempDir dir;
    make_tree(dir.path());
    const test::Run same = test::run_sphdeck(dir, "diff model-link/deck.k project/model/deck.k");
    CHECK(same.exit_code == 0);
    CHECK(same.out.find("no difference in what the solver reads") != std::string::npos);
}

TEST_CASE("symlinked decks: the editor publishes the findings of the files read, through a link as directly") {
    test::TempDir dir;
    make_tree(dir.path());
    const auto published_codes = [&](const std::string& deck) {
        std::set<std::pair<std::string, std::string>> out;  // (canonical file, code)
        std::vector<nlohmann::json> published;
        lsp::Workspace workspace{[&](const nlohmann::json& params) { published.push_back(params); }};
        const std::string path = (dir.path() / deck).string();
        REQUIRE(workspace.open(lsp::uri_from_path(path), slurp(path), 1));
        workspace.flush();
        for (const auto& p : published) {
            const fs::path file = lsp::path_from_uri(p["uri"].get<std::string>());
            CHECK(fs::exists(file));
            for (const auto& d : p["diagnostics"])
                out.emplace(fs::canonical(file).string(), d["code"].get<std::string>());
        }
        return out;
    };
    const auto direct = published_codes("project/model/deck.k");
    CHECK(published_codes("model-link/deck.k") == direct);
    CHECK(direct.count({fs::canonical(dir.path() / "project/common/mat.k").string(), "DK021"}) == 1);
    CHECK(direct.count({fs::canonical(dir.path() / "common/mat.k").string(), "DK021"}) == 0);
}
}  // namespace test_symlinked_decks_cpp
