// The language server: reads LSP messages from a stream, answers on another (stdio for
// `sphdeck lsp`, string streams in the tests). One thread; requests are answered in the order they
// came. The lifecycle (LSP 3.17): requests before `initialize` get ServerNotInitialized, requests
// after `shutdown` InvalidRequest, `exit` ends the loop (exit code 0 after shutdown, 1 without).
//
// Messages that are already waiting are read together before any is handled: a `$/cancelRequest`
// among them cancels a request not yet answered (RequestCancelled), and a run of didChange
// notifications costs one re-check, done before the next request that reads a deck or once the
// waiting messages are handled.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "lsp/json_rpc.hpp"
#include "lsp/workspace.hpp"

namespace sphdeck::lsp {

struct ServerOptions {
    std::size_t max_body = default_max_body;  // larger messages are skipped
    std::size_t max_batch = 1024;             // messages read ahead before handling them
    std::ostream* log = nullptr;              // problems with messages, for the editor's log (stderr)
};

class Server {
public:
    Server(std::istream& in, std::ostream& out, ServerOptions options = {});

    // Serves until `exit` or the end of the input; returns the process exit code.
    int run();

private:
    void handle(ReadResult& read);
    void handle_request(const nlohmann::json& id, const std::string& method, const nlohmann::json& params);
    void handle_notification(const std::string& method, nlohmann::json& params);
    nlohmann::json initialize(const nlohmann::json& params);
    nlohmann::json document_request(const std::string& method, const nlohmann::json& params);
    void send(const nlohmann::json& message);
    void log(const std::string& line);

    MessageReader reader_;
    std::ostream& out_;
    ServerOptions options_;
    Workspace workspace_;
    bool initialized_ = false, shut_down_ = false, exited_ = false;
    nlohmann::json inlay_settings_ = nlohmann::json::object();  // the client's "inlayHints" settings
    bool watch_dynamically_ = false;                            // the client registers file watchers on request
    std::set<std::string> cancelled_;                           // ids (dumped) of waiting requests the client cancelled
};

}  // namespace sphdeck::lsp
