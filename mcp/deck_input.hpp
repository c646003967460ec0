// What the tools that read a deck share: the deck named by a path or given as text (with the name it
// stands under, in the first root), its settings (sphdeck.toml, as `sphdeck check` finds it, when it
// lies inside the roots), the confinement of every file the deck read to the roots, and its findings
// as `sphdeck check --format json` writes them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/check.hpp"
#include "lint/config.hpp"
#include "mcp/tool.hpp"

namespace sphdeck::mcp {

// The schema properties "path", "text" and "name" (give one of path and text).
nlohmann::json deck_schema_properties(std::string_view what);

struct DeckInput {
    std::string path;             // what the engine reads: as given when relative to the working directory
    engine::Documents documents;  // the text, when the deck came as text
    bool from_text = false;
};

// Throws InvalidParams when neither or both of path and text are given, or the path lies outside the roots.
DeckInput deck_input(const Arguments& args, const ToolContext& context, std::string_view path_key = "path");

// The settings `sphdeck check` would use for the deck (sphdeck.toml inside the roots), with `overrides`.
// Throws ToolFailure on a bad sphdeck.toml (its message as the CLI prints it).
engine::CheckOptions check_options(const DeckInput& deck, const ToolContext& context,
                                   const lint::ConfigOverrides& overrides = {});

// Throws ToolFailure when the deck read a file outside the roots (an include named by an absolute path
// or climbing out): nothing of it is returned.
void confine_reads(const engine::CheckResult& result, const ToolContext& context);
bool reads_inside_roots(const engine::CheckResult& result, const ToolContext& context);

// The findings of the checks as the "diagnostics" of `sphdeck check --format json` (docs/json.md).
nlohmann::json findings_json(const std::vector<const engine::CheckResult*>& results);

// Errors, warnings and infos of the findings.
nlohmann::json counts_json(const std::vector<diag::Diagnostic>& diagnostics);

}  // namespace sphdeck::mcp
