#include "mcp/server.hpp"

#include <algorithm>
#include <exception>

#include "lsp/json_rpc.hpp"
#include "mcp/tool.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;
namespace error_code = lsp::error_code;

// Messages held while waiting for the client's roots: a bound, so that a client that floods instead
// of answering costs no unbounded memory.
constexpr std::size_t max_set_aside = 4096;

bool valid_id(const json& id) { return id.is_string() || id.is_number_integer(); }

json tool_listing(const Tool& tool) {
    return {{"name", tool.name},
            {"title", tool.title},
            {"description", tool.description},
            {"inputSchema", tool.input_schema},
            {"annotations", {{"readOnlyHint", tool.name != "fix_deck"}, {"openWorldHint", false}}}};
}

json tool_result(const std::string& text, json structured, bool is_error) {
    json out = {{"content", json::array({{{"type", "text"}, {"text", text}}})}, {"isError", is_error}};
    if (!structured.is_null()) out["structuredContent"] = std::move(structured);
    return out;
}
}  // namespace

Server::Server(std::istream& in, std::ostream& out, ServerOptions options)
    : reader_(in, options.max_line), out_(out), options_(options) {}

int Server::run() {
    for (;;) {
        const LineResult read = next();
        if (read.status == LineStatus::end) return 0;
        handle(read);
    }
}

LineResult Server::next() {
    if (!set_aside_.empty()) {
        LineResult read = std::move(set_aside_.front());
        set_aside_.pop_front();
        return read;
    }
    return reader_.next();
}

void Server::send(const json& message) { write_line(out_, message); }

void Server::log(const std::string& line) {
    if (options_.log) *options_.log << "sphdeck mcp: " << line << '\n' << std::flush;
}

void Server::handle(const LineResult& read) {
    if (read.status == LineStatus::parse_error || read.status == LineStatus::too_large) {
        log(read.error);
        send(lsp::error_response(nullptr,
                                 read.status == LineStatus::parse_error ? error_code::parse_error
                                                                        : error_code::invalid_request,
                                 read.error));
        return;
    }
    const json& m = read.message;
    if (!m.is_object()) {  // a batch (an array) is no longer part of MCP, nor any other value
        send(lsp::error_response(nullptr, error_code::invalid_request, "a message must be a JSON-RPC object"));
        return;
    }
    const json id = m.contains("id") ? m["id"] : json();
    const bool has_id = m.contains("id");
    if (m.value("jsonrpc", json()) != "2.0") {
        send(lsp::error_response(has_id && valid_id(id) ? id : json(), error_code::invalid_request,
                                 "\"jsonrpc\" must be \"2.0\""));
        return;
    }
    if (!m.contains("method")) {
        if (has_id && (m.contains("result") || m.contains("error")))
            handle_response(m);
        else
            send(lsp::error_response(has_id && valid_id(id) ? id : json(), error_code::invalid_request, "no method"));
        return;
    }
    if (!m["method"].is_string() || (has_id && !valid_id(id)) ||
        (m.contains("params") && !m["params"].is_object() && !m["params"].is_array())) {
        send(lsp::error_response(has_id && valid_id(id) ? id : json(), error_code::invalid_request,
                                 "a request has a string method, a string or integer id and object params"));
        return;
    }
    const std::string method = m["method"].get<std::string>();
    if (!has_id) {
        handle_notification(method);
        return;
    }
    const json params = m.contains("params") ? m["params"] : json::object();
    try {
        handle_request(id, method, params);
    } catch (const std::exception& e) {  // a bug: the server answers and goes on
        log(std::string("internal error: ") + e.what());
        send(lsp::error_response(id, error_code::internal_error, std::string("internal error: ") + e.what()));
    }
}

void Server::handle_request(const json& id, const std::string& method, const json& params) {
    if (method == "initialize") {
        if (!params.is_object() || !params.contains("protocolVersion") || !params["protocolVersion"].is_string()) {
            send(lsp::error_response(id, error_code::invalid_params, "initialize needs params.protocolVersion"));
            return;
        }
        send(lsp::response(id, initialize(params)));
        return;
    }
    if (method == "ping") {
        send(lsp::response(id, json::object()));
        return;
    }
    if (method != "tools/list" && method != "tools/call") {
        send(lsp::error_response(id, error_code::method_not_found, "unknown method '" + method + "'"));
        return;
    }
    if (!initialized_) {
        send(lsp::error_response(id, error_code::server_not_initialized, "the client has not sent initialize"));
        return;
    }
    if (method == "tools/list") {
        json listed = json::array();
        for (const Tool& tool : tools()) listed.push_back(tool_listing(tool));
        send(lsp::response(id, {{"tools", std::move(listed)}}));
        return;
    }
    try {
        send(lsp::response(id, call_tool(params)));
    } catch (const InvalidParams& e) {
        send(lsp::error_response(id, error_code::invalid_params, e.what()));
    }
}

json Server::initialize(const json& params) {
    const std::string asked = params["protocolVersion"].get<std::string>();
    const auto known = std::find(std::begin(protocol_versions), std::end(protocol_versions), asked);
    const std::string version = known != std::end(protocol_versions) ? asked : protocol_versions[0];
    const json capabilities = params.value("capabilities", json::object());
    client_has_roots_ = capabilities.is_object() && capabilities.contains("roots");
    initialized_ = true;
    return {{"protocolVersion", version},
            {"capabilities", {{"tools", {{"listChanged", false}}}}},
            {"serverInfo", {{"name", "sphdeck"}, {"title", "sphdeck SPH deck checker"}, {"version", SPHDECK_VERSION}}},
            {"instructions",
             "sphdeck checks LS-DYNA keyword decks and OpenRadioss starter decks for SPH runs. Call check_deck after "
             "writing or editing a deck: each finding has file, line, column, a rule code (explain_rule tells more) "
             "and often a fix; fix_deck applies the mechanical ones. keyword_layout gives a keyword's columns."}};
}

json Server::call_tool(const json& params) {
    if (!params.is_object() || !params.contains("name") || !params["name"].is_string())
        throw InvalidParams("tools/call needs params.name, a string");
    const std::string name = params["name"].get<std::string>();
    const Tool* tool = find_tool(name);
    if (!tool) throw InvalidParams("unknown tool '" + name + "'");
    const Arguments args(params.contains("arguments") ? params["arguments"] : json(), tool->input_schema);
    static const Roots none;
    const ToolContext context{tool->reads_files ? roots() : none};
    try {
        ToolResult result = tool->run(args, context);
        const std::string text =
            result.text.empty() ? result.structured.dump(2, ' ', false, json::error_handler_t::replace) : result.text;
        return tool_result(text, std::move(result.structured), false);
    } catch (const InvalidParams&) {
        throw;
    } catch (const std::exception& e) {  // ToolFailure, a deck that cannot be read: the model reads why
        return tool_result(std::string("sphdeck: error: ") + e.what(), json(), true);
    }
}

void Server::handle_notification(const std::string& method) {
    if (method == "notifications/initialized") {
        if (client_has_roots_ && !roots_id_) request_roots();
    } else if (method == "notifications/roots/list_changed") {
        if (client_has_roots_) request_roots();
    }
    // notifications/cancelled and any other: nothing to do (requests are answered one at a time).
}

void Server::request_roots() {
    const json id = "sphdeck-roots-" + std::to_string(++next_id_);
    roots_id_ = id.dump();
    roots_.reset();
    send({{"jsonrpc", "2.0"}, {"id", id}, {"method", "roots/list"}, {"params", json::object()}});
}

void Server::handle_response(const json& message) {
    if (!roots_id_ || message["id"].dump() != *roots_id_) return;  // an answer to nothing asked: dropped
    roots_id_.reset();
    if (message.contains("result")) {
        roots_ = Roots::from_list(message["result"]);
    } else {
        log("roots/list failed: " + message.value("error", json()).dump() + "; the root is the working directory");
        roots_ = Roots::working_directory();
    }
}

const Roots& Server::roots() {
    if (!client_has_roots_) {
        if (!roots_) roots_ = Roots::working_directory();
        return *roots_;
    }
    if (!roots_ && !roots_id_) request_roots();
    // Reads on until the client answers roots/list; the other messages wait their turn.
    while (!roots_) {
        LineResult read = reader_.next();
        if (read.status == LineStatus::end) throw InvalidParams("the client never answered roots/list");
        if (set_aside_.size() >= max_set_aside) throw InvalidParams("the client has not answered roots/list");
        const json& m = read.message;
        if (read.status == LineStatus::message && m.is_object() && !m.contains("method") && m.contains("id") &&
            roots_id_ && m["id"].dump() == *roots_id_)
            handle_response(m);
        else
            set_aside_.push_back(std::move(read));
    }
    return *roots_;
}

}  // namespace sphdeck::mcp
