// Small helpers shared by the tests: temporary folders with deck files, diagnostic queries.
#pragma once

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::test {

// A fresh folder under the system temp directory, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        std::random_device rd;
        path_ =
            std::filesystem::temp_directory_path() / ("sphdeck-test-" + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string write(const std::string& name, const std::string& text) const {
        auto p = path_ / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// Each finding as "CODE line:column message": two checks' findings compare as these lists.
inline std::vector<std::string> finding_lines(const std::vector<diag::Diagnostic>& ds) {
    std::vector<std::string> out;
    for (const auto& d : ds)
        out.push_back(d.code + " " + std::to_string(d.span.line) + ":" + std::to_string(d.span.column) + " " +
                      d.message);
    return out;
}

inline std::size_t count_code(const std::vector<diag::Diagnostic>& ds, const std::string& code) {
    std::size_t n = 0;
    for (const auto& d : ds) n += d.code == code;
    return n;
}

inline const diag::Diagnostic* find_code(const std::vector<diag::Diagnostic>& ds, const std::string& code) {
    for (const auto& d : ds)
        if (d.code == code) return &d;
    return nullptr;
}

}  // namespace sphdeck::test
