// The MCP stdio transport: JSON-RPC 2.0 messages, one per line (newline-delimited JSON, no header), as
// the MCP specification's "stdio" transport lays out. The JSON itself is parsed as the editor server
// parses it (lsp/json_rpc.hpp: nesting bounded, long strings decoded apart); only the framing differs.
//
// Reading never trusts the peer: a line above the size bound is read and dropped in chunks, never
// held, and reported as such; blank lines are skipped; a line that is not JSON is reported, and the
// next line is read as the next message.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

namespace sphdeck::mcp {

// 256 MiB: a deck sent as text in a tools/call (a 2-million-particle deck) still fits.
inline constexpr std::size_t default_max_line = std::size_t{256} << 20;

enum class LineStatus {
    message,      // `message` holds the parsed JSON value (any value: the server judges its shape)
    parse_error,  // the line is not JSON (answer -32700, id null)
    too_large,    // the line was above the bound and was dropped
    end,          // the stream ended
};

struct LineResult {
    LineStatus status = LineStatus::end;
    nlohmann::json message;
    std::string error;  // what was wrong, for the log and the error answer
};

class LineReader {
public:
    explicit LineReader(std::istream& in, std::size_t max_line = default_max_line) : in_(in), max_line_(max_line) {}
    // The next non-blank line as JSON, or what went wrong with it; blocks until a line is read.
    LineResult next();

private:
    std::istream& in_;
    std::size_t max_line_;
};

// Writes one message on one line and flushes. Text that is not UTF-8 (deck bytes in a finding's
// message) is replaced, never an exception; JSON escapes every newline, so a message is one line.
void write_line(std::ostream& out, const nlohmann::json& message);

}  // namespace sphdeck::mcp
