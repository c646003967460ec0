#include "model/flood_guard.hpp"

#include <map>
#include <string>

#include <fmt/format.h>

namespace sphdeck::model {

void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t shown) {
    std::map<std::string, std::size_t> count;
    for (std::size_t i = from; i < out.size(); ++i) ++count[out[i].code];
    bool flood = false;
    for (const auto& [code, n] : count) flood = flood || n > shown + 1;
    if (!flood) return;
    struct Rest {
        std::size_t summary = 0;  // index in `kept` of the finding that stands for the rest
        std::size_t more = 0;     // findings it stands for besides itself
        std::vector<std::uint32_t> lines;
    };
    std::map<std::string, Rest> rest;
    std::map<std::string, std::size_t> seen;
    std::vector<diag::Diagnostic> kept;
    for (std::size_t i = from; i < out.size(); ++i) {
        diag::Diagnostic& d = out[i];
        const std::size_t k = ++seen[d.code];
        if (count[d.code] <= shown + 1 || k <= shown) {
            kept.push_back(std::move(d));
            continue;
        }
        auto [it, first] = rest.try_emplace(d.code);
        if (first) {
            it->second.summary = kept.size();
            kept.push_back(std::move(d));  // the summary is the first finding it stands for
            continue;
        }
        diag::Diagnostic& summary = kept[it->second.summary];
        if (d.severity > summary.severity) summary.severity = d.severity;
        ++it->second.more;
        if (it->second.lines.size() < shown) it->second.lines.push_back(d.span.line);
    }
    for (auto& [code, r] : rest) {
        diag::Diagnostic& s = kept[r.summary];
        std::string lines;
        for (std::size_t k = 0; k < r.lines.size(); ++k) lines += (k ? ", " : "") + std::to_string(r.lines[k]);
        if (r.more > r.lines.size()) lines += ", ...";
        s.message += fmt::format(" (and {} more {} finding(s) on the lines of this {} block: lines {})", r.more, code,
                                 keyword, lines);
        s.notes.clear();
    }
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    for (auto& d : kept) out.push_back(std::move(d));
}

}  // namespace sphdeck::model
