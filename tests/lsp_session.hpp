// Drives the language server in-process through string streams: messages in, messages out.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lsp/json_rpc.hpp"
#include "lsp/server.hpp"

namespace sphdeck::test {

// One message framed as LSP sends it.
inline std::string frame(const nlohmann::json& message) {
    std::ostringstream out;
    lsp::write_message(out, message);
    return out.str();
}

inline nlohmann::json request(int id, const std::string& method, nlohmann::json params = nlohmann::json::object()) {
    return {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}};
}

inline nlohmann::json notify(const std::string& method, nlohmann::json params = nlohmann::json::object()) {
    return {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
}

// Every message in `bytes` (what the server wrote).
inline std::vector<nlohmann::json> messages_in(const std::string& bytes) {
    std::istringstream in(bytes);
    lsp::MessageReader reader(in);
    std::vector<nlohmann::json> out;
    for (lsp::ReadResult r = reader.next(); r.status != lsp::ReadStatus::end; r = reader.next())
        if (r.status == lsp::ReadStatus::message) out.push_back(std::move(r.message));
    return out;
}

struct Served {
    std::vector<nlohmann::json> messages;
    int exit_code = -1;

    // The response to request `id`, or null.
    nlohmann::json answer(int id) const {
        for (const auto& m : messages)
            if (m.contains("id") && m["id"] == id && !m.contains("method")) return m;
        return nullptr;
    }
    // The last diagnostics published for `uri`, or null when none were.
    nlohmann::json last_published(const std::string& uri) const {
        nlohmann::json out;
        for (const auto& m : messages)
            if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri)
                out = m["params"];
        return out;
    }
    std::size_t publications(const std::string& uri) const {
        std::size_t n = 0;
        for (const auto& m : messages)
            n += m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri;
        return n;
    }
};

// Runs a server over `input` (raw bytes) to its end.
inline Served serve_bytes(const std::string& input, lsp::ServerOptions options = {}) {
    std::istringstream in(input);
    std::ostringstream out;
    lsp::Server server(in, out, options);
    Served s;
    s.exit_code = server.run();
    s.messages = messages_in(out.str());
    return s;
}

inline Served serve(const std::vector<nlohmann::json>& messages, lsp::ServerOptions options = {}) {
    std::string input;
    for (const auto& m : messages) input += frame(m);
    return serve_bytes(input, options);
}

inline nlohmann::json initialize_request(int id = 1) {
    return request(id, "initialize", {{"capabilities", nlohmann::json::object()}});
}

inline nlohmann::json did_open(const std::string& uri, const std::string& text, int version = 1) {
    return notify("textDocument/didOpen",
                  {{"textDocument", {{"uri", uri}, {"languageId", "lsdyna"}, {"version", version}, {"text", text}}}});
}

inline nlohmann::json did_change(const std::string& uri, int version, nlohmann::json changes) {
    return notify("textDocument/didChange",
                  {{"textDocument", {{"uri", uri}, {"version", version}}}, {"contentChanges", std::move(changes)}});
}

}  // namespace sphdeck::test
