#include "lsp/server.hpp"

#include <algorithm>
#include <array>
#include <exception>
#include <string_view>
#include <utility>
#include <vector>

#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {
namespace {
// A request that fails with a JSON-RPC error.
struct RpcError {
    int code;
    std::string message;
};

// The document requests the features answer; with no deck reading the file their answer is null.
constexpr std::array<std::string_view, 18> kDocumentFeatures = {"textDocument/hover",
                                                                "textDocument/definition",
                                                                "textDocument/references",
                                                                "textDocument/completion",
                                                                "textDocument/documentSymbol",
                                                                "textDocument/foldingRange",
                                                                "textDocument/codeAction",
                                                                "textDocument/semanticTokens/full",
                                                                "textDocument/semanticTokens/full/delta",
                                                                "textDocument/semanticTokens/range",
                                                                "textDocument/inlayHint",
                                                                "textDocument/signatureHelp",
                                                                "textDocument/formatting",
                                                                "textDocument/rangeFormatting",
                                                                "textDocument/prepareRename",
                                                                "textDocument/rename",
                                                                "textDocument/documentLink",
                                                                "textDocument/codeLens"};

// The "inlayHints" object of initializationOptions or of didChangeConfiguration's settings, also
// under a "sphdeck" section; null when there is none.
const nlohmann::json* inlay_settings_in(const nlohmann::json& options) {
    if (!options.is_object()) return nullptr;
    if (auto section = options.find("sphdeck"); section != options.end() && section->is_object())
        return inlay_settings_in(*section);
    auto hints = options.find("inlayHints");
    return hints != options.end() && hints->is_object() ? &*hints : nullptr;
}

bool valid_id(const nlohmann::json& id) { return id.is_number_integer() || id.is_string(); }

const nlohmann::json* member(const nlohmann::json& object, std::string_view name) {
    if (!object.is_object()) return nullptr;
    const auto found = object.find(name);
    return found == object.end() ? nullptr : &*found;
}

std::string string_member(const nlohmann::json& object, std::string_view name) {
    const nlohmann::json* value = member(object, name);
    return value && value->is_string() ? value->get<std::string>() : std::string();
}

std::int64_t version_of(const nlohmann::json& text_document) {
    const nlohmann::json* version = member(text_document, "version");
    return version && version->is_number_integer() ? version->get<std::int64_t>() : 0;
}

bool is_cancel(const ReadResult& read) {
    return read.status == ReadStatus::message && read.message.is_object() && !read.message.contains("id") &&
           string_member(read.message, "method") == "$/cancelRequest";
}
}  // namespace

Server::Server(std::istream& in, std::ostream& out, ServerOptions options)
    : reader_(in, options.max_body), out_(out), options_(options), workspace_([this](const nlohmann::json& params) {
          send(notification("textDocument/publishDiagnostics", params));
      }) {}

void Server::send(const nlohmann::json& message) { write_message(out_, message); }

void Server::log(const std::string& line) {
    if (options_.log) *options_.log << "sphdeck lsp: " << line << '\n' << std::flush;
}

int Server::run() {
    while (!exited_) {
        // Whatever is already waiting, read before anything is handled (cancellation, one re-check).
        std::vector<ReadResult> batch;
        bool ended = false;
        std::size_t held = 0;  // bodies read ahead: at most about one message's bound
        do {
            ReadResult read = reader_.next();
            if (read.status == ReadStatus::end) {
                if (!read.error.empty()) log(read.error);
                ended = true;
                break;
            }
            held += read.bytes;
            batch.push_back(std::move(read));
        } while (batch.size() < options_.max_batch && held < options_.max_body && reader_.more_available());
        for (const ReadResult& read : batch)
            if (is_cancel(read)) {
                const nlohmann::json params = read.message.value("params", nlohmann::json());
                const nlohmann::json* id = member(params, "id");
                if (id && valid_id(*id)) cancelled_.insert(id->dump());
            }
        for (ReadResult& read : batch) {
            handle(read);
            if (exited_) break;
        }
        cancelled_.clear();  // a cancel only concerns requests read with it
        if (exited_) break;
        try {
            workspace_.flush();
        } catch (const std::exception& e) {
            log(std::string("re-check failed: ") + e.what());
        }
        if (ended) break;
    }
    return shut_down_ ? 0 : 1;
}

void Server::handle(ReadResult& read) {
    switch (read.status) {
        case ReadStatus::parse_error:
            log(read.error);
            send(error_response(nullptr, error_code::parse_error, "Parse error: " + read.error));
            return;
        case ReadStatus::too_large:
            // No id to answer, and it may have been a didOpen: say so where the user looks.
            log(read.error);
            send(notification("window/showMessage",
                              {{"type", 1},
                               {"message", "sphdeck: " + read.error +
                                               "; a deck this big is not checked in the editor: run "
                                               "`sphdeck check` on it"}}));
            return;
        case ReadStatus::bad_header:
            log(read.error);  // no id to answer: skipped
            return;
        case ReadStatus::end: return;
        case ReadStatus::message: break;
    }
    const nlohmann::json& message = read.message;
    if (!message.is_object()) {
        send(error_response(nullptr, error_code::invalid_request, "Invalid Request: not a JSON object"));
        return;
    }
    const nlohmann::json* id = member(message, "id");
    const nlohmann::json* method = member(message, "method");
    if (!method) {
        if (id && (message.contains("result") || message.contains("error"))) return;  // a response: we ask nothing
        send(error_response(id && valid_id(*id) ? *id : nlohmann::json(nullptr), error_code::invalid_request,
                            "Invalid Request: no method"));
        return;
    }
    if (!method->is_string() || (id && !valid_id(*id))) {
        send(error_response(id && valid_id(*id) ? *id : nlohmann::json(nullptr), error_code::invalid_request,
                            "Invalid Request: bad method or id"));
        return;
    }
    // Moved out, not copied: a didOpen's params hold the whole document (100 MB for a big deck).
    nlohmann::json params;
    if (auto found = read.message.find("params"); found != read.message.end()) params = std::move(*found);
    if (id)
        handle_request(*id, method->get<std::string>(), params);
    else
        handle_notification(method->get<std::string>(), params);
}

void Server::handle_request(const nlohmann::json& id, const std::string& method, const nlohmann::json& params) {
    try {
        if (cancelled_.erase(id.dump()) > 0) throw RpcError{error_code::request_cancelled, "Request cancelled"};
        nlohmann::json result;
        if (method == "initialize") {
            if (initialized_) throw RpcError{error_code::invalid_request, "initialize was already received"};
            result = initialize(params);
            initialized_ = true;
        } else if (!initialized_) {
            throw RpcError{error_code::server_not_initialized, "the server is not initialized"};
        } else if (shut_down_) {
            throw RpcError{error_code::invalid_request, "the server is shut down"};
        } else if (method == "shutdown") {
            workspace_.flush();  // what the edits so far found is published before the end
            shut_down_ = true;
        } else if (method.rfind("textDocument/", 0) == 0) {
            result = document_request(method, params);
        } else if (method == "workspace/symbol") {
            workspace_.flush();  // answers read the buffers as they are now
            result = workspace_symbols(workspace_.checked_decks(), string_member(params, "query"));
        } else {
            throw RpcError{error_code::method_not_found, "Method not found: " + method};
        }
        send(response(id, std::move(result)));
    } catch (const RpcError& e) {
        send(error_response(id, e.code, e.message));
    } catch (const FeatureError& e) {
        send(error_response(id, e.code, e.what()));
    } catch (const std::exception& e) {
        log(method + ": " + e.what());
        send(error_response(id, error_code::internal_error, std::string("Internal error: ") + e.what()));
    } catch (...) {
        send(error_response(id, error_code::internal_error, "Internal error"));
    }
}

void Server::handle_notification(const std::string& method, nlohmann::json& params) {
    if (method == "exit") {
        exited_ = true;
        return;
    }
    if (!initialized_ || shut_down_) return;  // dropped, as LSP asks
    try {
        const nlohmann::json* document = member(params, "textDocument");
        const std::string uri = document ? string_member(*document, "uri") : std::string();
        bool understood = true;
        if (method == "textDocument/didOpen") {
            nlohmann::json* text = document && document->is_object() && document->contains("text")
                                       ? &params["textDocument"]["text"]
                                       : nullptr;
            understood = text && text->is_string() &&
                         workspace_.open(uri, std::move(text->get_ref<std::string&>()), version_of(*document));
        } else if (method == "textDocument/didChange") {
            const nlohmann::json* changes = member(params, "contentChanges");
            understood = document && changes && workspace_.change(uri, version_of(*document), *changes);
        } else if (method == "textDocument/didSave") {
            const nlohmann::json* text = member(params, "text");
            understood =
                workspace_.save(uri, text && text->is_string() ? std::optional<std::string>(text->get<std::string>())
                                                               : std::nullopt);
        } else if (method == "textDocument/didClose") {
            understood = workspace_.close(uri);
        } else if (method == "workspace/didChangeWatchedFiles") {
            const nlohmann::json* changes = member(params, "changes");
            understood = changes && changes->is_array();
            if (understood)
                for (const nlohmann::json& change : *changes) workspace_.changed_on_disk(string_member(change, "uri"));
        } else if (method == "workspace/didChangeConfiguration") {
            const nlohmann::json options = params.value("settings", nlohmann::json());
            if (const nlohmann::json* settings = inlay_settings_in(options)) inlay_settings_ = *settings;
        } else if (method == "initialized" && watch_dynamically_) {
            // Include files change on disk too (another editor, a generator): ask to hear of it.
            const nlohmann::json watcher = {{"globPattern", "**/*.{k,key,dyn,inc,rad}"}};
            send({{"jsonrpc", "2.0"},
                  {"id", "sphdeck-watch-includes"},
                  {"method", "client/registerCapability"},
                  {"params",
                   {{"registrations",
                     {{{"id", "sphdeck-watch-includes"},
                       {"method", "workspace/didChangeWatchedFiles"},
                       {"registerOptions", {{"watchers", {watcher}}}}}}}}}});
        }
        // initialized, $/cancelRequest (read ahead), $/setTrace and the rest: nothing to do.
        if (!understood) log(method + ": malformed parameters or a document that is not open, ignored");
    } catch (const std::exception& e) {
        log(method + ": " + e.what());
    }
}

nlohmann::json Server::initialize(const nlohmann::json& params) {
    std::vector<std::filesystem::path> roots;
    if (const nlohmann::json* folders = member(params, "workspaceFolders"); folders && folders->is_array())
        for (const nlohmann::json& folder : *folders)
            if (auto path = path_from_uri(string_member(folder, "uri")); !path.empty()) roots.push_back(path);
    if (roots.empty())
        if (auto path = path_from_uri(string_member(params, "rootUri")); !path.empty()) roots.push_back(path);
    if (roots.empty())
        if (auto path = string_member(params, "rootPath"); !path.empty()) roots.emplace_back(path);
    workspace_.set_roots(std::move(roots));
    const nlohmann::json options = params.value("initializationOptions", nlohmann::json());
    if (const nlohmann::json* settings = inlay_settings_in(options)) inlay_settings_ = *settings;
    if (const nlohmann::json* capabilities = member(params, "capabilities"))
        if (const nlohmann::json* ws = member(*capabilities, "workspace"))
            if (const nlohmann::json* watched = member(*ws, "didChangeWatchedFiles"))
                if (const nlohmann::json* dynamic = member(*watched, "dynamicRegistration"))
                    watch_dynamically_ = dynamic->is_boolean() && dynamic->get<bool>();

    nlohmann::json capabilities = feature_capabilities();
    capabilities["positionEncoding"] = "utf-16";
    capabilities["textDocumentSync"] = {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}};
    return {{"capabilities", std::move(capabilities)},
            {"serverInfo", {{"name", "sphdeck"}, {"version", SPHDECK_VERSION}}}};
}

nlohmann::json Server::document_request(const std::string& method, const nlohmann::json& params) {
    const nlohmann::json* document = member(params, "textDocument");
    const std::string uri = document ? string_member(*document, "uri") : std::string();
    if (uri.empty()) throw RpcError{error_code::invalid_params, "textDocument.uri is missing"};
    workspace_.flush();  // answers read the buffers as they are now
    const bool feature =
        std::find(kDocumentFeatures.begin(), kDocumentFeatures.end(), method) != kDocumentFeatures.end();
    const std::filesystem::path path = path_from_uri(uri);
    const auto located = path.empty() ? std::nullopt : workspace_.locate(path);
    if (located) {
        if (method == "textDocument/inlayHint" && params.is_object()) {
            nlohmann::json with_settings = params;
            with_settings["settings"] = inlay_settings_;
            FeatureAnswer answer = answer_feature(method, *located->deck, located->file, with_settings);
            if (answer.handled) return std::move(answer.result);
        }
        FeatureAnswer answer = answer_feature(method, *located->deck, located->file, params);
        if (answer.handled) return std::move(answer.result);
    } else if (feature) {
        return nullptr;  // no deck reads this file: nothing to say about it
    }
    throw RpcError{error_code::method_not_found, "Method not found: " + method};
}

}  // namespace sphdeck::lsp
