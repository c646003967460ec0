#include "model/flood_guard.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace sphdeck::model {
namespace {

constexpr std::size_t kLinesNamed = 5;

}  // namespace

void FloodBound::trim(std::vector<diag::Diagnostic>& out) {
    if (checked_ >= out.size()) return;
    std::size_t write = checked_;
    for (std::size_t i = checked_; i < out.size(); ++i) {
        diag::Diagnostic& d = out[i];
        auto seen = seen_.find(d.code);
        if (seen == seen_.end()) seen = seen_.emplace(d.code, 0).first;
        if (++seen->second <= kept_) {
            if (write != i) out[write] = std::move(d);
            ++write;
            continue;
        }
        Dropped& r = dropped_[d.code];
        ++r.count;
        if (r.lines.size() < kLinesNamed) r.lines.push_back(d.span.line);
    }
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(write), out.end());
    checked_ = out.size();
}

void FloodBound::merge(const FloodBound& other) {
    for (const auto& [code, r] : other.dropped_) {
        Dropped& mine = dropped_[code];
        mine.count += r.count;
        mine.lines.insert(mine.lines.end(), r.lines.begin(), r.lines.end());
        std::sort(mine.lines.begin(), mine.lines.end());
        if (mine.lines.size() > kLinesNamed) mine.lines.resize(kLinesNamed);
    }
}

std::size_t FloodBound::dropped() const {
    std::size_t n = 0;
    for (const auto& [code, r] : dropped_) n += r.count;
    return n;
}

void FloodBound::annotate(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword) {
    trim(out);
    for (auto& [code, r] : dropped_) {
        std::sort(r.lines.begin(), r.lines.end());
        if (r.lines.size() > kLinesNamed) r.lines.resize(kLinesNamed);
        if (r.count == 0) continue;
        std::size_t last = out.size();
        for (std::size_t i = out.size(); i-- > from;)
            if (out[i].code == code) {
                last = i;
                break;
            }
        if (last == out.size()) continue;
        std::string lines;
        for (std::size_t k = 0; k < r.lines.size(); ++k) lines += (k ? ", " : "") + std::to_string(r.lines[k]);
        if (r.count > r.lines.size()) lines += ", ...";
        out[last].message += fmt::format(
            " (and {} more {} finding(s) on the lines of this {} block, dropped: at most {} of one code per block "
            "are kept; lines {})",
            r.count, code, keyword, kept_, lines);
    }
}

void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t kept) {
    if (out.size() - from <= kept) return;  // no code can pass the bound
    FloodBound bound(from, kept);
    bound.annotate(out, from, keyword);
}

}  // namespace sphdeck::model
