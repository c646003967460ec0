#include "diag/report.hpp"

#include <algorithm>
#include <filesystem>

namespace sphdeck::diag {

std::string tool_path(const text::SourceFile& file) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path absolute = fs::absolute(fs::path(file.path), ec).lexically_normal();
    if (ec) return fs::path(file.path).generic_string();
    // `link/..` is not the folder holding `link` when it is a symbolic link: where folding a path that
    // climbs lexically names another file, it is named by its canonical form (as grammar::normal_path).
    const fs::path given(file.path);
    if (std::find(given.begin(), given.end(), fs::path("..")) != given.end()) {
        std::error_code failed;
        const fs::path canonical = fs::weakly_canonical(fs::absolute(given, failed), failed);
        const fs::path folded = failed ? fs::path() : fs::weakly_canonical(absolute, failed);
        if (!failed && folded != canonical) absolute = canonical;
    }
    const fs::path cwd = fs::current_path(ec);
    if (!ec) {
        const fs::path relative = absolute.lexically_relative(cwd);
        if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    }
    return absolute.generic_string();
}

}  // namespace sphdeck::diag
