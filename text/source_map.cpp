#include "text/source_map.hpp"

#include <algorithm>
#include <cstring>

namespace sphdeck::text {

FileId SourceMap::add(SourceFile file) {
    files_.push_back(std::move(file));
    return static_cast<FileId>(files_.size() - 1);
}

// Lines are indexed lazily and only as far as asked: a diagnostic on line 3 of a 100 MB deck
// must not scan (and index) the whole file.
void SourceMap::index_lines(const SourceFile& f, std::uint32_t up_to_line) const {
    if (f.line_starts.empty()) f.line_starts.push_back(0);
    const char* base = f.text.data();
    const char* end = base + f.text.size();
    const char* p = base + f.line_starts.back();
    while (f.line_starts.size() <= up_to_line && p < end) {
        const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
        if (!nl) break;
        p = static_cast<const char*>(nl) + 1;
        f.line_starts.push_back(static_cast<std::uint32_t>(p - base));
    }
}

std::uint32_t SourceMap::line_count(FileId id) const {
    if (id >= files_.size()) return 0;
    const SourceFile& f = files_[id];
    index_lines(f, UINT32_MAX);
    auto n = static_cast<std::uint32_t>(f.line_starts.size());
    return f.line_starts.back() == f.text.size() ? n - 1 : n;  // no phantom line after a final newline
}

std::string_view SourceMap::line_text(FileId id, std::uint32_t line) const {
    if (id >= files_.size() || line == 0) return {};
    const SourceFile& f = files_[id];
    index_lines(f, line);  // line_starts[line] (the next line's start) is wanted too
    if (line > f.line_starts.size()) return {};
    std::size_t begin = f.line_starts[line - 1];
    std::size_t stop = line < f.line_starts.size() ? f.line_starts[line] : f.text.size();
    std::string_view text(f.text.data() + begin, stop - begin);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

std::vector<FileId> SourceMap::include_chain(FileId id) const {
    std::vector<FileId> chain;
    for (FileId f = id; f != no_file && f < files_.size(); f = files_[f].parent) chain.push_back(f);
    std::reverse(chain.begin(), chain.end());
    return chain;
}

}  // namespace sphdeck::text
