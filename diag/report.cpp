#include "diag/report.hpp"

#include <filesystem>

namespace sphdeck::diag {

std::string tool_path(const grammar::SourceFile& file) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::absolute(fs::path(file.path), ec).lexically_normal();
    if (ec) return fs::path(file.path).generic_string();
    const fs::path cwd = fs::current_path(ec);
    if (!ec) {
        const fs::path relative = absolute.lexically_relative(cwd);
        if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    }
    return absolute.generic_string();
}

}  // namespace sphdeck::diag
