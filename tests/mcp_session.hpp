// Drives the MCP server (mcp/server.hpp) over string streams: the client's lines in, the server's
// messages out, parsed. For tests/test_mcp_*.cpp.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mcp/server.hpp"

namespace sphdeck::test {

using json = nlohmann::json;

// Runs a server on `lines` (one message each; a newline is added) and returns every line it wrote.
inline std::vector<json> mcp_exchange(const std::vector<std::string>& lines, mcp::ServerOptions options = {}) {
    std::string input;
    for (const std::string& line : lines) input += line + "\n";
    std::istringstream in(input);
    std::ostringstream out;
    mcp::Server server(in, out, options);
    server.run();
    std::vector<json> messages;
    std::istringstream written(out.str());
    for (std::string line; std::getline(written, line);) messages.push_back(json::parse(line));
    return messages;
}

inline std::string mcp_request(int id, const std::string& method, const json& params = json::object()) {
    return json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", params}}.dump();
}

inline std::string mcp_initialize(const json& capabilities = json::object(),
                                  const std::string& version = "2025-06-18") {
    return mcp_request(1, "initialize",
                       {{"protocolVersion", version},
                        {"capabilities", capabilities},
                        {"clientInfo", {{"name", "doctest"}, {"version", "1"}}}});
}

inline const std::string mcp_initialized = R"({"jsonrpc":"2.0","method":"notifications/initialized"})";

// The working directory set to `folder` for a scope, and back however the scope ends.
struct InFolder {
    std::filesystem::path before = std::filesystem::current_path();
    explicit InFolder(const std::filesystem::path& folder) { std::filesystem::current_path(folder); }
    ~InFolder() { std::filesystem::current_path(before); }
    InFolder(const InFolder&) = delete;
    InFolder& operator=(const InFolder&) = delete;
};

// initialize, then tools/call of `tool` (id 2) without roots, run from `root` (the root is then the working
// directory): the answer to the call. The source folder by default, so that "decks/..." is found from
// wherever the tests run (ctest runs them there, a developer perhaps from build/).
inline json mcp_call(const std::string& tool, const json& arguments,
                     const std::filesystem::path& root = SPHDECK_SOURCE_DIR) {
    InFolder in(root);
    const auto out = mcp_exchange(
        {mcp_initialize(), mcp_initialized, mcp_request(2, "tools/call", {{"name", tool}, {"arguments", arguments}})});
    REQUIRE(out.size() == 2);
    return out[1];
}

// The structured result of a call that must succeed.
inline json mcp_result(const std::string& tool, const json& arguments,
                       const std::filesystem::path& root = SPHDECK_SOURCE_DIR) {
    const json answer = mcp_call(tool, arguments, root);
    INFO(answer.dump());
    REQUIRE(answer.contains("result"));
    REQUIRE(answer["result"]["isError"] == false);
    return answer["result"]["structuredContent"];
}

}  // namespace sphdeck::test
