#include "mcp/roots.hpp"

#include <algorithm>

#include "lsp/uri.hpp"

namespace sphdeck::mcp {
namespace fs = std::filesystem;

namespace {
fs::path normal(const fs::path& path) {
    std::error_code ec;
    fs::path out = fs::weakly_canonical(path, ec);
    return ec ? path.lexically_normal() : out;
}

// Whether `path` is `folder` or below it, compared by whole components ("/a/bc" is not below "/a/b").
bool below(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty()) continue;  // a trailing separator
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}
}  // namespace

Roots Roots::working_directory() {
    Roots roots;
    std::error_code ec;
    roots.folders_.push_back(normal(fs::current_path(ec)));
    return roots;
}

Roots Roots::from_list(const nlohmann::json& result) {
    Roots roots;
    if (!result.is_object() || !result.contains("roots") || !result["roots"].is_array()) return roots;
    for (const auto& root : result["roots"]) {
        if (!root.is_object() || !root.contains("uri") || !root["uri"].is_string()) continue;
        const fs::path path = lsp::path_from_uri(root["uri"].get<std::string>());
        if (!path.empty() && path.is_absolute()) roots.folders_.push_back(normal(path));
    }
    return roots;
}

fs::path Roots::base() const {
    if (!folders_.empty()) return folders_.front();
    std::error_code ec;
    return fs::current_path(ec);
}

bool Roots::contains(const fs::path& absolute) const {
    const fs::path p = normal(absolute);
    return std::any_of(folders_.begin(), folders_.end(), [&](const fs::path& f) { return below(p, f); });
}

std::optional<fs::path> Roots::resolve(const std::string& path) const {
    if (path.empty() || path.find('\0') != std::string::npos) return std::nullopt;
    fs::path p(path);
    if (p.is_relative()) p = base() / p;
    p = normal(p);
    if (!contains(p)) return std::nullopt;
    return p;
}

std::string Roots::describe() const {
    if (folders_.empty()) return "(none)";
    std::string out;
    for (const fs::path& f : folders_) out += (out.empty() ? "" : ", ") + f.string();
    return out;
}

}  // namespace sphdeck::mcp
