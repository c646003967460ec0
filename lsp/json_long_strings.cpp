#include "lsp/json_long_strings.hpp"

#include <cstdint>
#include <cstring>
#include <utility>

namespace sphdeck::lsp {
namespace {
// "\u0000" starts it: no document text an editor sends begins with NUL and that name.
constexpr std::string_view kPlaceholder = "\\u0000sphdeck-long-string:";
constexpr std::string_view kParsedPlaceholder{"\0sphdeck-long-string:", 21};

// The index just past the closing quote of the string whose opening quote is at `open`, or npos.
std::size_t string_end(std::string_view body, std::size_t open) {
    std::size_t from = open + 1;
    while (true) {
        const void* found = std::memchr(body.data() + from, '"', body.size() - from);
        if (!found) return std::string_view::npos;
        const std::size_t quote = static_cast<std::size_t>(static_cast<const char*>(found) - body.data());
        std::size_t backslashes = 0;
        while (quote - backslashes > open + 1 && body[quote - backslashes - 1] == '\\') ++backslashes;
        if (backslashes % 2 == 0) return quote + 1;
        from = quote + 1;
    }
}

// Whether some byte of the 8 in `word` is a control character (below 0x20) or not ASCII (0x80 and
// above): exact for "some", which is all the fast path asks (Hacker's Delight, "has less than").
bool word_needs_a_look(std::uint64_t word) {
    constexpr std::uint64_t ones = 0x0101010101010101ULL, highs = 0x8080808080808080ULL;
    return (((word - ones * 0x20) & ~word) | word) & highs;
}

// Whether JSON allows the bytes of `raw` (no escapes in it) in a string: no control character,
// well-formed UTF-8 (RFC 3629, as nlohmann-json checks it). Printable ASCII is passed 8 bytes at a time.
bool plain_bytes_allowed(std::string_view raw) {
    const auto* p = reinterpret_cast<const unsigned char*>(raw.data());
    const auto* end = p + raw.size();
    while (p < end) {
        if (end - p >= 8) {
            std::uint64_t word;
            std::memcpy(&word, p, 8);
            if (!word_needs_a_look(word)) {
                p += 8;
                continue;
            }
        }
        const unsigned char c = *p;
        if (c >= 0x20 && c < 0x80) {
            ++p;
            continue;
        }
        if (c < 0x20) return false;
        const auto continuation = [&](std::size_t i, unsigned char low = 0x80, unsigned char high = 0xBF) {
            return p + i < end && p[i] >= low && p[i] <= high;
        };
        std::size_t length = 0;
        if (c >= 0xC2 && c <= 0xDF)
            length = continuation(1) ? 2 : 0;
        else if (c == 0xE0)
            length = continuation(1, 0xA0) && continuation(2) ? 3 : 0;
        else if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF)
            length = continuation(1) && continuation(2) ? 3 : 0;
        else if (c == 0xED)
            length = continuation(1, 0x80, 0x9F) && continuation(2) ? 3 : 0;
        else if (c == 0xF0)
            length = continuation(1, 0x90) && continuation(2) && continuation(3) ? 4 : 0;
        else if (c >= 0xF1 && c <= 0xF3)
            length = continuation(1) && continuation(2) && continuation(3) ? 4 : 0;
        else if (c == 0xF4)
            length = continuation(1, 0x80, 0x8F) && continuation(2) && continuation(3) ? 4 : 0;
        if (length == 0) return false;
        p += length;
    }
    return true;
}

// What the escape `\c` stands for; 0 for what is left to nlohmann-json (\u: surrogates...) and bad escapes.
char unescaped(char c) {
    switch (c) {
        case '"': return '"';
        case '\\': return '\\';
        case '/': return '/';
        case 'b': return '\b';
        case 'f': return '\f';
        case 'n': return '\n';
        case 'r': return '\r';
        case 't': return '\t';
        default: return 0;
    }
}

// Whether decode() takes the JSON string body `raw` (between its quotes): allowed bytes, and only
// the escapes unescaped() knows.
bool decodable(std::string_view raw) {
    std::size_t at = 0;
    while (at < raw.size()) {
        const void* found = std::memchr(raw.data() + at, '\\', raw.size() - at);
        const std::size_t escape =
            found ? static_cast<std::size_t>(static_cast<const char*>(found) - raw.data()) : raw.size();
        if (!plain_bytes_allowed(raw.substr(at, escape - at))) return false;
        if (escape == raw.size()) break;
        if (escape + 1 >= raw.size() || unescaped(raw[escape + 1]) == 0) return false;
        at = escape + 2;
    }
    return true;
}

// Decodes the decodable() string body at [begin, end) of `buffer` into `buffer` from `to` on (to <=
// begin: the text only shrinks, so it never overtakes what is still to read); returns its end.
std::size_t decode_into(char* buffer, std::size_t begin, std::size_t end, std::size_t to) {
    std::size_t at = begin;
    while (at < end) {
        const void* found = std::memchr(buffer + at, '\\', end - at);
        const std::size_t escape = found ? static_cast<std::size_t>(static_cast<const char*>(found) - buffer) : end;
        if (to != at) std::memmove(buffer + to, buffer + at, escape - at);
        to += escape - at;
        if (escape == end) break;
        buffer[to++] = unescaped(buffer[escape + 1]);
        at = escape + 2;
    }
    return to;
}

// The JSON string body `raw` (between its quotes) decoded; false for what is left to nlohmann-json.
bool decode(std::string_view raw, std::string& out) {
    if (!decodable(raw)) return false;
    out.assign(raw);
    out.resize(decode_into(out.data(), 0, out.size(), 0));
    return true;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

void restore(nlohmann::json& value, std::vector<std::string>& strings, std::vector<bool>& restored, bool& ok) {
    if (value.is_string()) {
        const std::string& text = value.get_ref<const std::string&>();
        if (text.size() <= kParsedPlaceholder.size() ||
            text.compare(0, kParsedPlaceholder.size(), kParsedPlaceholder) != 0)
            return;
        std::size_t index = 0;
        for (std::size_t i = kParsedPlaceholder.size(); i < text.size(); ++i) {
            if (text[i] < '0' || text[i] > '9' || index > strings.size()) {
                ok = false;
                return;
            }
            index = index * 10 + static_cast<std::size_t>(text[i] - '0');
        }
        if (index >= strings.size() || restored[index]) {
            ok = false;
            return;
        }
        restored[index] = true;
        value = std::move(strings[index]);
    } else if (value.is_structured()) {
        for (auto& item : value) restore(item, strings, restored, ok);
    }
}
}  // namespace

std::optional<LongStrings> find_long_strings(std::string_view body, std::size_t min_length) {
    if (body.size() < min_length) return std::nullopt;
    LongStrings out;
    std::size_t copied = 0, at = 0;
    while (true) {
        const void* found = std::memchr(body.data() + at, '"', body.size() - at);
        if (!found) break;
        const std::size_t open = static_cast<std::size_t>(static_cast<const char*>(found) - body.data());
        const std::size_t end = string_end(body, open);
        if (end == std::string_view::npos) return std::nullopt;
        at = end;
        if (end - open - 2 < min_length) continue;
        std::size_t next = end;
        while (next < body.size() && is_space(body[next])) ++next;
        if (next < body.size() && body[next] == ':') continue;  // an object's key
        if (!decodable(body.substr(open + 1, end - open - 2))) return std::nullopt;
        out.rest.append(body.substr(copied, open - copied));
        out.rest += '"';
        out.rest.append(kPlaceholder);
        out.rest += std::to_string(out.ranges.size());
        out.rest += '"';
        copied = end;
        out.ranges.emplace_back(open + 1, end - 1);
    }
    if (out.ranges.empty()) return std::nullopt;
    out.rest.append(body.substr(copied));
    return out;
}

std::optional<LiftedStrings> lift_long_strings(std::string_view body, std::size_t min_length) {
    auto found = find_long_strings(body, min_length);
    if (!found) return std::nullopt;
    LiftedStrings out{std::move(found->rest), {}};
    for (const auto& [begin, end] : found->ranges) {
        std::string decoded;
        decode(body.substr(begin, end - begin), decoded);  // decodable: find_long_strings checked it
        out.strings.push_back(std::move(decoded));
    }
    return out;
}

bool only_placeholders_escape_u(const LongStrings& found) {
    std::size_t escapes = 0;
    for (std::size_t at = found.rest.find("\\u"); at != std::string::npos; at = found.rest.find("\\u", at + 2))
        ++escapes;
    return escapes == found.ranges.size();
}

std::vector<std::string> take_long_strings(std::string& body, const LongStrings& found) {
    std::vector<std::string> out(found.ranges.size());
    std::size_t longest = 0;
    for (std::size_t i = 0; i < found.ranges.size(); ++i)
        if (found.ranges[i].second - found.ranges[i].first > found.ranges[longest].second - found.ranges[longest].first)
            longest = i;
    for (std::size_t i = 0; i < found.ranges.size(); ++i)  // while the body is whole
        if (i != longest) {
            const auto [begin, end] = found.ranges[i];
            decode(std::string_view(body).substr(begin, end - begin), out[i]);
        }
    const auto [begin, end] = found.ranges[longest];
    body.resize(decode_into(body.data(), begin, end, 0));
    out[longest] = std::move(body);
    body = std::string();
    return out;
}

bool restore_long_strings(nlohmann::json& parsed, std::vector<std::string>& strings) {
    std::vector<bool> restored(strings.size(), false);
    bool ok = true;
    restore(parsed, strings, restored, ok);
    for (bool r : restored) ok = ok && r;
    return ok;
}

}  // namespace sphdeck::lsp
