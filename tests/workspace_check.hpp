// What the language server publishes for a deck it checks from scratch: the reference the tests of
// incremental re-checks compare every spliced result with.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"

namespace sphdeck::test {

// The diagnostics a workspace holding only `text` at `path` publishes for it: a full check.
inline nlohmann::json published_by_full_check(const std::filesystem::path& path, const std::string& text) {
    nlohmann::json published;
    lsp::Workspace workspace([&](const nlohmann::json& params) {
        if (params["uri"] == lsp::uri_from_path(path)) published = params["diagnostics"];
    });
    workspace.open(lsp::uri_from_path(path), text, 1);
    workspace.flush();
    return published;
}

}  // namespace sphdeck::test
