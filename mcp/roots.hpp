// The folders a client lets the server read and write (MCP "roots"): what the client names through
// roots/list, or the server's working directory when it names none. Every path a tool is given, and
// every file a deck pulls in, must lie inside one of them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphdeck::mcp {

class Roots {
public:
    // The working directory alone.
    static Roots working_directory();
    // From a roots/list result ({"roots": [{"uri": "file:///...", "name": ...}]}); roots that are not
    // file URIs are left out. An empty list confines every path (nothing may be read).
    static Roots from_list(const nlohmann::json& result);

    const std::vector<std::filesystem::path>& folders() const { return folders_; }
    // The folder relative paths are taken from: the first root (the working directory by default).
    std::filesystem::path base() const;
    // `path` (relative to base()) made absolute and normal, symbolic links resolved where they exist;
    // nullopt when it lies outside every root.
    std::optional<std::filesystem::path> resolve(const std::string& path) const;
    bool contains(const std::filesystem::path& absolute) const;
    // "/work/a, /work/b": for error messages.
    std::string describe() const;

private:
    std::vector<std::filesystem::path> folders_;  // canonical
};

}  // namespace sphdeck::mcp
