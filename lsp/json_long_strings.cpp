#include "lsp/json_long_strings.hpp"

#include <cstring>

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

// Appends the bytes of `raw` (no escapes in it) when JSON allows them in a string: no control
// character, well-formed UTF-8 (RFC 3629, as nlohmann-json checks it).
bool append_checked(std::string_view raw, std::string& out) {
    const auto* p = reinterpret_cast<const unsigned char*>(raw.data());
    const auto* end = p + raw.size();
    while (p < end) {
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
    out.append(raw);
    return true;
}

// The JSON string body `raw` (between its quotes) decoded; false for what is left to nlohmann-json.
bool decode(std::string_view raw, std::string& out) {
    out.reserve(raw.size());
    std::size_t at = 0;
    while (at < raw.size()) {
        const void* found = std::memchr(raw.data() + at, '\\', raw.size() - at);
        const std::size_t escape =
            found ? static_cast<std::size_t>(static_cast<const char*>(found) - raw.data()) : raw.size();
        if (!append_checked(raw.substr(at, escape - at), out)) return false;
        if (escape == raw.size()) break;
        if (escape + 1 >= raw.size()) return false;
        switch (raw[escape + 1]) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            default: return false;  // \u (surrogates...) and bad escapes: nlohmann-json decides
        }
        at = escape + 2;
    }
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

std::optional<LiftedStrings> lift_long_strings(std::string_view body, std::size_t min_length) {
    if (body.size() < min_length) return std::nullopt;
    LiftedStrings out;
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
        std::string decoded;
        if (!decode(body.substr(open + 1, end - open - 2), decoded)) return std::nullopt;
        out.rest.append(body.substr(copied, open - copied));
        out.rest += '"';
        out.rest.append(kPlaceholder);
        out.rest += std::to_string(out.strings.size());
        out.rest += '"';
        copied = end;
        out.strings.push_back(std::move(decoded));
    }
    if (out.strings.empty()) return std::nullopt;
    out.rest.append(body.substr(copied));
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
