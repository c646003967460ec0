// The MCP server's protocol (mcp/server.hpp, mcp/transport.hpp): lifecycle, version negotiation,
// tools/list, the roots exchange, and every kind of bad input answered with a JSON-RPC error while the
// server goes on.
#include <doctest/doctest.h>

#include <filesystem>
#include <set>

#include "lsp/uri.hpp"
#include "mcp_session.hpp"
#include "mcp/tool.hpp"

namespace test_mcp_protocol_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::test;

namespace {
int error_code_of(const json& answer) { return answer.at("error").at("code").get<int>(); }
const std::string ping = R"({"jsonrpc":"2.0","id":99,"method":"ping"})";
}  // namespace

TEST_CASE("mcp: initialize answers the version, the tools capability and the server's name") {
    const auto out = mcp_exchange({mcp_initialize(), mcp_initialized, ping});
    REQUIRE(out.size() == 2);
    const json& result = out[0]["result"];
    CHECK(out[0]["id"] == 1);
    CHECK(result["protocolVersion"] == "2025-06-18");  // the client's, when the server speaks it
    CHECK(result["capabilities"].contains("tools"));
    CHECK(result["serverInfo"]["name"] == "sphdeck");
    CHECK(out[1] == json{{"jsonrpc", "2.0"}, {"id", 99}, {"result", json::object()}});
}

TEST_CASE("mcp: a version the server does not know is answered with its latest") {
    const auto out = mcp_exchange({mcp_initialize(json::object(), "1999-01-01")});
    REQUIRE(out.size() == 1);
    CHECK(out[0]["result"]["protocolVersion"] == sphdeck::mcp::protocol_versions[0]);
}

TEST_CASE("mcp: tools/list declares every tool with an object input schema") {
    const auto out = mcp_exchange({mcp_initialize(), mcp_initialized, mcp_request(2, "tools/list")});
    REQUIRE(out.size() == 2);
    const json& tools = out[1]["result"]["tools"];
    std::set<std::string> names;
    for (const json& tool : tools) {
        names.insert(tool["name"].get<std::string>());
        CHECK(tool["inputSchema"]["type"] == "object");
        CHECK(tool["inputSchema"]["properties"].is_object());
        CHECK(!tool["description"].get<std::string>().empty());
    }
    CHECK(names == std::set<std::string>{"check_deck", "fix_deck", "format_deck", "explain_rule", "keyword_layout",
                                         "smoothing_preview", "diff_decks"});
}

TEST_CASE("mcp: bad messages get JSON-RPC errors and the server goes on") {
    const auto out = mcp_exchange({
        mcp_initialize(),
        "{not json",                                                // -32700
        "[1, 2]",                                                   // a batch: -32600
        R"({"id": 3, "method": "ping"})",                           // no jsonrpc: -32600
        R"({"jsonrpc": "2.0", "id": {"a": 1}, "method": "ping"})",  // an object id: -32600
        R"({"jsonrpc": "2.0", "id": 4, "method": 5})",              // a number method: -32600
        mcp_request(5, "resources/list"),                           // -32601
        mcp_request(6, "tools/call", {{"name", "no_such_tool"}}),   // -32602
        mcp_request(7, "tools/call", {{"name", "explain_rule"}, {"arguments", {{"rule", 3}}}}),   // wrong type
        mcp_request(8, "tools/call", {{"name", "explain_rule"}, {"arguments", json::object()}}),  // missing
        mcp_request(9, "tools/call", {{"name", "explain_rule"}, {"arguments", {{"rule", "SPH030"}, {"x", 1}}}}),
        mcp_request(10, "tools/call",
                    {{"name", "keyword_layout"}, {"arguments", {{"name", "*PART"}, {"format", "wide"}}}}),
        mcp_request(11, "tools/call", {{"arguments", json::object()}}),  // no name
        R"({"jsonrpc":"2.0","method":"notifications/unknown"})",         // a notification: no answer
        ping,
    });
    REQUIRE(out.size() == 14);
    CHECK(error_code_of(out[1]) == -32700);
    CHECK(out[1]["id"].is_null());
    CHECK(error_code_of(out[2]) == -32600);
    CHECK(error_code_of(out[3]) == -32600);
    CHECK(out[3]["id"] == 3);
    CHECK(error_code_of(out[4]) == -32600);
    CHECK(out[4]["id"].is_null());
    CHECK(error_code_of(out[5]) == -32600);
    CHECK(error_code_of(out[6]) == -32601);
    for (int k = 7; k <= 12; ++k) {
        CAPTURE(k);
        CHECK(error_code_of(out[static_cast<std::size_t>(k)]) == -32602);
    }
    CHECK(out[7]["error"]["message"].get<std::string>().find("no_such_tool") != std::string::npos);
    CHECK(out[9]["error"]["message"].get<std::string>().find("'rule'") != std::string::npos);
    CHECK(out[11]["error"]["message"].get<std::string>().find("one of") != std::string::npos);
    CHECK(out[13]["id"] == 99);
}

TEST_CASE("mcp: tools before initialize get -32002; ping works at any time") {
    const auto out = mcp_exchange({mcp_request(2, "tools/list"), ping});
    REQUIRE(out.size() == 2);
    CHECK(error_code_of(out[0]) == -32002);
    CHECK(out[1]["result"] == json::object());
}

TEST_CASE("mcp: a line above the bound is dropped with an error, never held; blank lines are skipped") {
    sphdeck::mcp::ServerOptions options;
    options.max_line = 64;
    const auto out = mcp_exchange({"", std::string(1000, 'x'), "   ", ping}, options);
    REQUIRE(out.size() == 2);
    CHECK(error_code_of(out[0]) == -32600);
    CHECK(out[1]["id"] == 99);
}

TEST_CASE("mcp: with the roots capability the server asks roots/list and confines paths to them") {
    const std::filesystem::path source(SPHDECK_SOURCE_DIR);
    const std::string root_uri = sphdeck::lsp::uri_from_path(source / "decks" / "demo");
    const json roots_answer = {{"jsonrpc", "2.0"},
                               {"id", "sphdeck-roots-1"},
                               {"result", {{"roots", {{{"uri", root_uri}, {"name", "demo"}}}}}}};
    const auto check = [](int id, const std::string& path) {
        return mcp_request(id, "tools/call",
                           {{"name", "check_deck"}, {"arguments", {{"path", path}, {"geometry", false}}}});
    };
    const auto out = mcp_exchange({
        mcp_initialize({{"roots", {{"listChanged", true}}}}),
        mcp_initialized,
        check(2, "sph_mistakes_2d.k"),  // comes before the roots: waits for them
        roots_answer.dump(),
        check(3, (source / "decks" / "run" / "water_column_2d.k").string()),  // another folder
        check(4, "../run/water_column_2d.k"),                                 // climbing out
        check(5, "/etc/passwd"),
    });
    REQUIRE(out.size() == 6);
    CHECK(out[1]["method"] == "roots/list");
    CHECK(out[1]["id"] == "sphdeck-roots-1");
    CHECK(out[2]["id"] == 2);
    CHECK(out[2]["result"]["isError"] == false);
    CHECK(!out[2]["result"]["structuredContent"]["diagnostics"].empty());
    for (std::size_t k = 3; k <= 5; ++k) {
        CAPTURE(k);
        CHECK(error_code_of(out[k]) == -32602);
        CHECK(out[k]["error"]["message"].get<std::string>().find("outside the roots") != std::string::npos);
    }
}

TEST_CASE("mcp: roots/list_changed asks again; an empty list of roots confines everything") {
    const auto out = mcp_exchange({
        mcp_initialize({{"roots", json::object()}}),
        mcp_initialized,
        R"({"jsonrpc":"2.0","id":"sphdeck-roots-1","result":{"roots":[]}})",
        R"({"jsonrpc":"2.0","method":"notifications/roots/list_changed"})",
        R"({"jsonrpc":"2.0","id":"sphdeck-roots-2","result":{"roots":[]}})",
        mcp_request(2, "tools/call",
                    {{"name", "check_deck"}, {"arguments", {{"path", "decks/demo/sph_mistakes_2d.k"}}}}),
    });
    REQUIRE(out.size() == 4);
    CHECK(out[1]["id"] == "sphdeck-roots-1");
    CHECK(out[2]["method"] == "roots/list");
    CHECK(out[2]["id"] == "sphdeck-roots-2");
    CHECK(error_code_of(out[3]) == -32602);
}

TEST_CASE("mcp: a client that never answers roots/list gets an error, not a hang") {
    const auto out = mcp_exchange({
        mcp_initialize({{"roots", json::object()}}),
        mcp_initialized,
        mcp_request(2, "tools/call", {{"name", "explain_rule"}, {"arguments", {{"rule", "SPH030"}}}}),  // no file
        mcp_request(3, "tools/call",
                    {{"name", "check_deck"}, {"arguments", {{"path", "decks/demo/sph_mistakes_2d.k"}}}}),
    });
    REQUIRE(out.size() == 4);
    CHECK(out[2]["result"]["isError"] == false);
    CHECK(error_code_of(out[3]) == -32602);
}
}  // namespace test_mcp_protocol_cpp
