// One MCP tool: its name, description and declared input schema, and the function that runs it. The
// schema is the one source of truth for the arguments: Arguments checks a call against it (unknown
// names, missing required ones, wrong types) before the tool runs.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "mcp/roots.hpp"

namespace sphdeck::mcp {

// Arguments that do not fit the tool (a wrong type, a path outside the roots): a JSON-RPC error
// -32602, as the MCP specification asks for invalid arguments and unknown tools.
struct InvalidParams : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The tool ran and failed on what it was given (a deck that cannot be read, an unknown rule): a
// result with isError true, whose text the model reads and can act on.
struct ToolFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Arguments {
public:
    // Checks `arguments` (the call's "arguments", absent = {}) against `schema`; throws InvalidParams.
    Arguments(const nlohmann::json& arguments, const nlohmann::json& schema);

    bool has(std::string_view name) const;
    std::optional<std::string> string(std::string_view name) const;
    bool boolean(std::string_view name, bool otherwise = false) const;
    std::optional<double> number(std::string_view name) const;
    std::vector<std::string> strings(std::string_view name) const;

private:
    nlohmann::json values_;
};

struct ToolContext {
    const Roots& roots;
};

struct ToolResult {
    nlohmann::json structured;  // structuredContent
    std::string text;           // the text content (the JSON of `structured` when empty)
};

struct Tool {
    std::string_view name;
    std::string_view title;
    std::string_view description;
    nlohmann::json input_schema;
    std::function<ToolResult(const Arguments&, const ToolContext&)> run;
    bool reads_files = true;  // needs the roots (a tool that reads none never waits for the client's)
};

// Every tool, in the order tools/list gives them.
const std::vector<Tool>& tools();
const Tool* find_tool(std::string_view name);

// The tools, one file each (mcp/tool_*.cpp).
Tool check_deck_tool();
Tool fix_deck_tool();
Tool format_deck_tool();
Tool explain_rule_tool();
Tool keyword_layout_tool();
Tool smoothing_preview_tool();
Tool diff_decks_tool();

}  // namespace sphdeck::mcp
