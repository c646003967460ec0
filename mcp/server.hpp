// The MCP server (Model Context Protocol, https://modelcontextprotocol.io/specification): JSON-RPC 2.0
// over the stdio transport (mcp/transport.hpp), serving the tools of mcp/tool.hpp. One thread;
// requests are answered in the order they came.
//
// Lifecycle: `initialize` (the protocol version is the client's when supported, else the latest this
// server knows), then `notifications/initialized`; `ping` at any time; tools/list and tools/call after
// initialize (before: error -32002). Roots: when the client declares the roots capability, the server
// asks roots/list after initialized (and again on notifications/roots/list_changed), and a tools/call
// that comes before the answer waits for it; without the capability the root is the working directory.
//
// Bad input never ends the server: a line that is not JSON gets -32700, a message that is no JSON-RPC
// request -32600, an unknown method -32601, an unknown tool or arguments that do not fit its schema
// -32602; a tool that fails on what it read answers a result with isError.
#pragma once

#include <cstddef>
#include <deque>
#include <istream>
#include <optional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "mcp/roots.hpp"
#include "mcp/transport.hpp"

namespace sphdeck::mcp {

// The protocol versions this server speaks, newest first.
inline constexpr const char* protocol_versions[] = {"2025-11-25", "2025-06-18", "2025-03-26", "2024-11-05"};

struct ServerOptions {
    std::size_t max_line = default_max_line;  // longer messages are dropped
    std::ostream* log = nullptr;              // problems with messages (stderr, which clients log)
};

class Server {
public:
    Server(std::istream& in, std::ostream& out, ServerOptions options = {});
    // Serves until the end of the input; returns the process exit code (0).
    int run();

private:
    LineResult next();  // a message set aside while waiting for roots first, then the input
    void handle(const LineResult& read);
    void handle_request(const nlohmann::json& id, const std::string& method, const nlohmann::json& params);
    void handle_notification(const std::string& method);
    void handle_response(const nlohmann::json& message);
    nlohmann::json initialize(const nlohmann::json& params);
    nlohmann::json call_tool(const nlohmann::json& params);
    void request_roots();
    // The roots, once known: waits for the client's roots/list answer when one is due.
    const Roots& roots();
    void send(const nlohmann::json& message);
    void log(const std::string& line);

    LineReader reader_;
    std::ostream& out_;
    ServerOptions options_;
    std::deque<LineResult> set_aside_;  // read while waiting for the roots, handled after
    bool initialized_ = false;
    bool client_has_roots_ = false;
    std::optional<Roots> roots_;           // nullopt while asked for and not answered
    std::optional<std::string> roots_id_;  // the id (dumped) of the roots/list request in flight
    long long next_id_ = 0;
};

}  // namespace sphdeck::mcp
