#include "model/flood_guard.hpp"

#include <map>
#include <string>

#include <fmt/format.h>

namespace sphdeck::model {

void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t kept) {
    if (out.size() - from <= kept) return;  // cheap exit: no code can pass the bound
    std::map<std::string, std::size_t> count;
    for (std::size_t i = from; i < out.size(); ++i) ++count[out[i].code];
    bool flood = false;
    for (const auto& [code, n] : count) flood = flood || n > kept;
    if (!flood) return;
    struct Dropped {
        std::size_t last = 0;  // index in `keep` of the last finding kept
        std::size_t count = 0;
        std::vector<std::uint32_t> lines;  // the first few dropped lines
    };
    std::map<std::string, Dropped> dropped;
    std::map<std::string, std::size_t> seen;
    std::vector<diag::Diagnostic> keep;
    for (std::size_t i = from; i < out.size(); ++i) {
        diag::Diagnostic& d = out[i];
        const std::size_t k = ++seen[d.code];
        if (k <= kept) {
            if (k == kept) dropped[d.code].last = keep.size();
            keep.push_back(std::move(d));
            continue;
        }
        Dropped& r = dropped[d.code];
        ++r.count;
        if (r.lines.size() < 5) r.lines.push_back(d.span.line);
    }
    for (auto& [code, r] : dropped) {
        if (r.count == 0) continue;
        diag::Diagnostic& last = keep[r.last];
        std::string lines;
        for (std::size_t k = 0; k < r.lines.size(); ++k) lines += (k ? ", " : "") + std::to_string(r.lines[k]);
        if (r.count > r.lines.size()) lines += ", ...";
        last.message += fmt::format(
            " (and {} more {} finding(s) on the lines of this {} block, dropped: at most {} of one code per block "
            "are kept; lines {})",
            r.count, code, keyword, kept, lines);
    }
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    for (auto& d : keep) out.push_back(std::move(d));
}

}  // namespace sphdeck::model
