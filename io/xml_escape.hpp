// Text for XML attributes and elements (the SVG and VTK writers): markup characters escaped,
// control bytes replaced by '?' since XML 1.0 cannot carry them.
#pragma once

#include <string>
#include <string_view>

namespace sphdeck::io {

inline std::string xml_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
        }
    }
    return out;
}

}  // namespace sphdeck::io
