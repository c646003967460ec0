#include "lsp/json_rpc.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

#include "lsp/json_long_strings.hpp"

namespace sphdeck::lsp {
namespace {
constexpr std::size_t max_header_line = 8192;  // a real header line is ~30 bytes
constexpr std::size_t max_header_lines = 32;
constexpr std::size_t read_chunk = 65536;
constexpr int max_depth = 256;  // LSP messages nest a few levels; bounds the parser's work on "[[[["

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

// An RFC 7230 token: what a header name is made of.
bool is_token(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    });
}

std::optional<std::size_t> parse_length(std::string_view value) {
    value = trim(value);
    if (value.empty() || value.size() > 18) return std::nullopt;  // 18 digits cannot overflow
    std::size_t n = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (error != std::errc() || end != value.data() + value.size()) return std::nullopt;
    return n;
}

// The deepest nesting of arrays and objects outside strings; stops counting past the bound.
bool nesting_within(std::string_view text, int bound) {
    int depth = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > bound) return false;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}
}  // namespace

int MessageReader::get() {
    if (pending_pos_ < pending_.size()) return static_cast<unsigned char>(pending_[pending_pos_++]);
    std::streambuf* buf = in_.rdbuf();
    if (!buf) return -1;
    const auto c = buf->sbumpc();
    return std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof())
               ? -1
               : std::char_traits<char>::to_int_type(static_cast<char>(c));
}

bool MessageReader::more_available() {
    if (pending_pos_ < pending_.size()) return true;
    std::streambuf* buf = in_.rdbuf();
    return buf && buf->in_avail() > 0;
}

std::optional<std::string> MessageReader::read_line() {
    std::string line;
    bool any = false;
    for (int c = get(); c >= 0; c = get()) {
        any = true;
        if (c == '\n') break;
        if (line.size() < max_header_line) line += static_cast<char>(c);
    }
    if (!any) return std::nullopt;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

bool MessageReader::read_body(std::size_t length, std::string& out) {
    out.clear();
    // Room for the whole body at once: a 100 MB didOpen grown by doubling was copied about once more
    // and held 1.5 times over at its last growth. The pages are touched only as bytes arrive, so a
    // header that lies about a length (within the bound) costs address space, not memory.
    out.reserve(length);
    while (out.size() < length) {
        if (pending_pos_ < pending_.size()) {
            const std::size_t take = std::min(length - out.size(), pending_.size() - pending_pos_);
            out.append(pending_, pending_pos_, take);
            pending_pos_ += take;
            continue;
        }
        std::streambuf* buf = in_.rdbuf();
        if (!buf) return false;
        std::array<char, read_chunk> block;
        const auto want = static_cast<std::streamsize>(std::min(length - out.size(), read_chunk));
        const std::streamsize got = buf->sgetn(block.data(), want);
        if (got <= 0) return false;
        out.append(block.data(), static_cast<std::size_t>(got));
    }
    return true;
}

void MessageReader::discard(std::size_t length) {
    std::size_t left = length;
    while (left > 0) {
        if (pending_pos_ < pending_.size()) {
            const std::size_t take = std::min(left, pending_.size() - pending_pos_);
            pending_pos_ += take;
            left -= take;
            continue;
        }
        std::streambuf* buf = in_.rdbuf();
        if (!buf) return;
        std::array<char, read_chunk> block;
        const std::streamsize got = buf->sgetn(block.data(), static_cast<std::streamsize>(std::min(left, read_chunk)));
        if (got <= 0) return;
        left -= static_cast<std::size_t>(got);
    }
}

void MessageReader::resync_inside(const std::string& body) {
    std::size_t at = std::string::npos;
    for (std::string_view name : {"Content-Length", "content-length"}) at = std::min(at, body.find(name, 1));
    if (at == std::string::npos) return;
    pending_ = body.substr(at) + pending_.substr(pending_pos_);
    pending_pos_ = 0;
}

ReadResult MessageReader::next() {
    for (;;) {
        std::optional<std::size_t> length;
        bool bad = false, any = false;
        std::size_t lines = 0;
        std::string problem;
        for (;;) {
            const auto line = read_line();
            if (!line) return {ReadStatus::end, nullptr, any ? "the stream ended inside a header" : ""};
            if (line->empty()) {
                if (!any) continue;  // blank lines between messages
                break;
            }
            any = true;
            std::string_view text = *line;
            // Out of step (a body shorter than its length said, glued to the next header): the
            // header is found inside the line, and the block starts there.
            for (std::string_view name : {"Content-Length:", "content-length:"})
                if (const auto at = text.find(name); at != std::string_view::npos && at > 0) text = text.substr(at);
            const auto colon = text.find(':');
            const std::string_view name = colon == std::string_view::npos ? text : text.substr(0, colon);
            if (colon != std::string_view::npos && equals_ignoring_case(trim(name), "Content-Length")) {
                // A Content-Length line starts a header block afresh: the way back after garbage.
                length = parse_length(text.substr(colon + 1));
                bad = !length;
                lines = 1;
                if (bad) problem = "bad Content-Length: " + std::string(text.substr(0, 80));
                continue;
            }
            if (++lines > max_header_lines || colon == std::string_view::npos || !is_token(trim(name))) {
                bad = true;
                if (problem.empty()) problem = "malformed header line: " + std::string(text.substr(0, 80));
            }
            // Content-Type and any other well-formed header: accepted and ignored.
        }
        if (bad || !length)
            return {ReadStatus::bad_header, nullptr, problem.empty() ? "header without Content-Length" : problem};
        if (*length > max_body_) {
            discard(*length);
            return {ReadStatus::too_large, nullptr,
                    "message of " + std::to_string(*length) + " bytes skipped (bound " + std::to_string(max_body_) +
                        ")"};
        }
        std::string body;
        if (!read_body(*length, body)) return {ReadStatus::end, nullptr, "the stream ended inside a message"};
        auto parsed = parse_body_taking(body);  // a document's text may take the body's buffer
        if (!parsed) {
            resync_inside(body);
            return {ReadStatus::parse_error, nullptr, "the body is not JSON"};
        }
        return {ReadStatus::message, std::move(*parsed), {}, *length};
    }
}

namespace {
std::optional<nlohmann::json> parse_whole(std::string_view body) {
    if (!nesting_within(body, max_depth)) return std::nullopt;
    nlohmann::json parsed = nlohmann::json::parse(body.begin(), body.end(), nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded()) return std::nullopt;
    return parsed;
}
}  // namespace

std::optional<nlohmann::json> parse_body(std::string_view body) {
    // A document's text (didOpen, a whole-text didChange) is decoded apart: lsp/json_long_strings.hpp.
    if (auto lifted = lift_long_strings(body)) {
        auto parsed = parse_whole(lifted->rest);
        if (!parsed) return std::nullopt;  // the rest is JSON exactly when the body is
        if (restore_long_strings(*parsed, lifted->strings)) return parsed;
    }
    return parse_whole(body);
}

std::optional<nlohmann::json> parse_body_taking(std::string& body) {
    // The rest is parsed before anything is decoded: a body that is not JSON stays whole for
    // MessageReader::resync_inside. Bodies whose envelope holds other \u escapes go the way above.
    if (auto found = find_long_strings(body); found && only_placeholders_escape_u(*found)) {
        auto parsed = parse_whole(found->rest);
        if (!parsed) return std::nullopt;  // the rest is JSON exactly when the body is
        std::vector<std::string> strings = take_long_strings(body, *found);
        restore_long_strings(*parsed, strings);  // false only for a repeated key's dropped value
        return parsed;
    }
    return parse_body(body);
}

void write_message(std::ostream& out, const nlohmann::json& message) {
    const std::string body = message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
    out.flush();
}

nlohmann::json response(const nlohmann::json& id, nlohmann::json result) {
    return {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
}

nlohmann::json error_response(const nlohmann::json& id, int code, std::string_view message) {
    return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", std::string(message)}}}};
}

nlohmann::json notification(std::string_view method, nlohmann::json params) {
    return {{"jsonrpc", "2.0"}, {"method", std::string(method)}, {"params", std::move(params)}};
}

}  // namespace sphdeck::lsp
