// The parts of the program and the one-way arrows between them (docs/architecture.md, "Parts and
// arrows"): each part may include only the parts listed here. A new arrow is a design change: change
// this table and the picture together.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace test_layering_cpp {  // each test file's names stay its own in a unity batch

namespace {

namespace fs = std::filesystem;

// part -> the parts its files may include (its own always). text/ is the floor: source text, spans, edits;
// diag/ stands on it and grammar/ on both, so no two parts include each other. The build enforces the same
// table (cmake/rooms.cmake: each room's files see only its own and the lower rooms' folders); this scan
// names the offending line, headers no source includes too.
const std::map<std::string, std::set<std::string>> kAllowed = {
    {"text", {}},
    {"io", {}},
    {"diag", {"text"}},
    {"grammar", {"diag", "text"}},
    {"model", {"grammar", "diag", "text"}},
    {"preproc", {"model", "grammar", "diag", "text"}},
    {"lint", {"preproc", "model", "grammar", "diag", "text"}},
    {"refsolver", {"preproc", "model", "grammar", "diag", "text"}},
    {"engine", {"lint", "preproc", "model", "grammar", "diag", "text"}},
    {"edit", {"engine", "lint", "preproc", "model", "grammar", "diag", "text"}},
    {"lsp", {"edit", "engine", "lint", "preproc", "model", "grammar", "diag", "text"}},
    // The MCP server (`sphdeck mcp`) stands on the editor server: its JSON-RPC reader and file URIs.
    {"mcp", {"lsp", "edit", "engine", "lint", "preproc", "model", "grammar", "diag", "text"}},
    {"verify", {"engine", "refsolver", "lint", "preproc", "model", "grammar", "diag", "text", "io"}},
    {"cli",
     {"mcp", "lsp", "edit", "verify", "engine", "refsolver", "lint", "preproc", "model", "grammar", "diag", "text",
      "io"}},
    // The Python module stands beside cli/ (python/CMakeLists.txt): it reuses the rooms, never cli/.
    {"python",
     {"mcp", "lsp", "edit", "verify", "engine", "refsolver", "lint", "preproc", "model", "grammar", "diag", "text",
      "io"}},
};

struct Violation {
    std::string file;
    int line;
    std::string header;
};

struct Scan {
    std::vector<Violation> violations;
    std::size_t includes = 0;  // project includes seen, to know the scan read the tree
};

Scan scan() {
    const fs::path root(SPHDECK_SOURCE_DIR);
    const std::regex include(R"(^\s*#\s*include\s*"(([a-z_]+)/[^"]*)\")");
    Scan out;
    for (const auto& [part, allowed] : kAllowed) {
        if (!fs::is_directory(root / part)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / part)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".cpp" && ext != ".hpp" && ext != ".h") continue;
            const std::string relative = fs::relative(entry.path(), root).generic_string();
            std::ifstream in(entry.path());
            std::string text;
            int line = 0;
            while (std::getline(in, text)) {
                ++line;
                std::smatch m;
                if (!std::regex_search(text, m, include)) continue;
                ++out.includes;
                const std::string target = m[2];
                if (target == part || allowed.count(target) || !kAllowed.count(target)) continue;
                out.violations.push_back({relative, line, m[1]});
            }
        }
    }
    return out;
}

}  // namespace

TEST_CASE("layering: every part includes only the parts below it (docs/architecture.md)") {
    const Scan s = scan();
    CHECK(s.includes > 300);  // about 450 in November 2026
    for (const Violation& v : s.violations)
        FAIL_CHECK(v.file << ":" << v.line << " includes \"" << v.header << "\", which its part may not import");
}

TEST_CASE("layering: every part named in the table is a folder of the tree") {
    const fs::path root(SPHDECK_SOURCE_DIR);
    // Not a structured binding: clang 14 cannot capture one in doctest's message lambda.
    for (const auto& entry : kAllowed) {
        const std::string& part = entry.first;
        CHECK_MESSAGE(fs::is_directory(root / part), part);
    }
}

TEST_CASE("layering: the editor server keeps the protocol; what is at a position comes from engine/") {
    // Which card and field is at line:column and which ids are named where is the engine's position
    // index (engine/position_index.hpp, engine/id_lookup.hpp), shared by every feature: lsp/ does not
    // walk card sequences or decode card lines itself (issue 27 item 5).
    const fs::path root(SPHDECK_SOURCE_DIR);
    const std::set<std::string> decoding = {"model/card_decoder.hpp", "model/radioss_card_decoder.hpp",
                                            "model/radioss_card_sequence.hpp", "model/deck_check.hpp"};
    const std::regex include(R"(^\s*#\s*include\s*"([^"]*)\")");
    CHECK(fs::is_regular_file(root / "engine" / "position_index.hpp"));
    CHECK(fs::is_regular_file(root / "engine" / "id_lookup.hpp"));
    for (const auto& entry : fs::directory_iterator(root / "lsp")) {
        std::ifstream in(entry.path());
        std::string text;
        int line = 0;
        while (std::getline(in, text)) {
            ++line;
            std::smatch m;
            if (std::regex_search(text, m, include) && decoding.count(m[1]))
                FAIL_CHECK("lsp/" << entry.path().filename().string() << ":" << line << " includes " << m[1]
                                  << ": ask engine/position_index.hpp");
        }
    }
}
}  // namespace test_layering_cpp
