#include "mcp/transport.hpp"

#include <string_view>

#include "lsp/json_rpc.hpp"

namespace sphdeck::mcp {

LineResult LineReader::next() {
    for (;;) {
        std::streambuf* buf = in_.rdbuf();
        if (!buf) return {LineStatus::end, nullptr, {}};
        std::string line;
        bool any = false, dropped = false;
        std::size_t length = 0;
        for (;;) {
            const auto c = buf->sbumpc();
            if (std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof())) break;
            any = true;
            const char ch = std::char_traits<char>::to_char_type(c);
            if (ch == '\n') break;
            ++length;
            if (length > max_line_) {  // keep counting, stop holding
                dropped = true;
                line.clear();
                line.shrink_to_fit();
                continue;
            }
            line += ch;
        }
        if (!any) return {LineStatus::end, nullptr, {}};
        if (dropped)
            return {LineStatus::too_large, nullptr,
                    "message of " + std::to_string(length) + " bytes dropped (bound " + std::to_string(max_line_) +
                        ")"};
        if (!line.empty() && line.back() == '\r') line.pop_back();  // a client on Windows
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        auto parsed = lsp::parse_body(line);
        if (!parsed) return {LineStatus::parse_error, nullptr, "the line is not JSON"};
        return {LineStatus::message, std::move(*parsed), {}};
    }
}

void write_line(std::ostream& out, const nlohmann::json& message) {
    out << message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    out.flush();
}

}  // namespace sphdeck::mcp
