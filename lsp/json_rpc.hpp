// The LSP base protocol (JSON-RPC 2.0 framed by HTTP-like headers) on nlohmann-json: messages read
// from an input stream and written to an output stream. No Debian package offers a C++ LSP library,
// and the protocol's framing is a page of code.
//
// Reading never trusts the peer: header lines and header counts are bounded, a body above the size
// bound is read and discarded in chunks (never allocated), JSON nesting is bounded before parsing,
// and after garbage the reader resynchronises on the next "Content-Length:" line. Nothing it reads
// makes it crash, and it never waits for bytes a valid stream would not send.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sphdeck::lsp {

// JSON-RPC and LSP error codes.
namespace error_code {
inline constexpr int parse_error = -32700;
inline constexpr int invalid_request = -32600;
inline constexpr int method_not_found = -32601;
inline constexpr int invalid_params = -32602;
inline constexpr int internal_error = -32603;
inline constexpr int server_not_initialized = -32002;
inline constexpr int request_cancelled = -32800;
inline constexpr int request_failed = -32803;  // a valid request the server cannot carry out (a refused rename)
}  // namespace error_code

// 1 GiB: the didOpen of a 10-million-particle deck (about 1 GB of text) still fits; beyond, the
// message is skipped and the user told (window/showMessage).
inline constexpr std::size_t default_max_body = std::size_t{1} << 30;

// What one read gives.
enum class ReadStatus {
    message,      // `message` holds a JSON object
    parse_error,  // the body is not JSON (answer -32700, id null)
    too_large,    // the body was above the bound and was skipped
    bad_header,   // a header block without a usable Content-Length (skipped)
    end,          // the stream ended (possibly inside a message)
};

struct ReadResult {
    ReadStatus status = ReadStatus::end;
    nlohmann::json message;
    std::string error;      // what was wrong, for the log
    std::size_t bytes = 0;  // the body's length (what holding the message costs)
};

class MessageReader {
public:
    explicit MessageReader(std::istream& in, std::size_t max_body = default_max_body) : in_(in), max_body_(max_body) {}

    // The next message, or what went wrong with it; blocks until a whole message is read or the
    // stream ends.
    ReadResult next();

    // Whether bytes are waiting that can be read without blocking (the rest of a message may not be).
    bool more_available();

private:
    int get();  // the next byte (pushed-back bytes first), or -1 at the end
    // One header line without its "\r\n" (longer lines are cut at the bound, the rest skipped);
    // nullopt at the end of the stream before any byte.
    std::optional<std::string> read_line();
    // Reads `length` bytes into `out`; false when the stream ends first.
    bool read_body(std::size_t length, std::string& out);
    void discard(std::size_t length);
    // Bad JSON that holds a header further on most likely swallowed the next message (the body
    // of a truncated message): read again from that header.
    void resync_inside(const std::string& body);

    std::istream& in_;
    std::size_t max_body_;
    std::string pending_;  // bytes given back to be read again, consumed from pending_pos_
    std::size_t pending_pos_ = 0;
};

// Parses a body; nullopt when it is not JSON or nests deeper than the bound.
std::optional<nlohmann::json> parse_body(std::string_view body);
// The same for a body the caller gives up: a long string (a didOpen's document) is decoded into the
// body's own buffer, so a 100 MB text is not held twice; `body` is left empty then. When nullopt,
// `body` is unchanged.
std::optional<nlohmann::json> parse_body_taking(std::string& body);

// Writes one message with its Content-Length header and flushes. Text that is not UTF-8 (deck bytes
// in a diagnostic message) is replaced, never an exception.
void write_message(std::ostream& out, const nlohmann::json& message);

// Message builders.
nlohmann::json response(const nlohmann::json& id, nlohmann::json result);
nlohmann::json error_response(const nlohmann::json& id, int code, std::string_view message);
nlohmann::json notification(std::string_view method, nlohmann::json params);

}  // namespace sphdeck::lsp
