#include "python/calls.hpp"

#include <filesystem>

#include "diag/diagnostic.hpp"
#include "engine/check_named.hpp"
#include "engine/config_file.hpp"
#include "lint/config.hpp"
#include "lint/registry.hpp"
#include "lint/rule_pages.hpp"
#include "lsp/uri.hpp"
#include "mcp/deck_input.hpp"
#include "mcp/tool.hpp"

namespace sphdeck::python {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

// The settings `sphdeck check` would use for a deck at `deck`, with the caller's rule choice.
lint::Config config_for(const CheckRequest& request, const std::string& deck) {
    for (const std::string& selector : request.select.value_or(std::vector<std::string>{}))
        if (auto problem = lint::check_selector(selector)) throw Failure("select: " + *problem);
    for (const std::string& selector : request.ignore)
        if (auto problem = lint::check_selector(selector)) throw Failure("ignore: " + *problem);
    std::string path;
    if (request.config.kind == ConfigChoice::Kind::File) path = request.config.file;
    if (request.config.kind == ConfigChoice::Kind::Search)
        if (auto found = engine::find_config(deck)) path = found->string();
    lint::Config config;
    if (!path.empty())
        if (auto error = engine::load_config(path, config)) throw Failure(error->to_string());
    lint::ConfigOverrides overrides;
    overrides.select = request.select;
    overrides.ignore = request.ignore;
    lint::apply_overrides(overrides, config);
    return config;
}

std::optional<grammar::DeckFormat> format_of(const std::string& name) {
    if (name.empty()) return std::nullopt;
    if (name == "lsdyna") return grammar::DeckFormat::LsDyna;
    if (name == "radioss") return grammar::DeckFormat::Radioss;
    throw Failure("format must be 'lsdyna' or 'radioss', not '" + name + "'");
}

// The MCP tools' roots for a Python caller: relative paths from the working directory, every file
// readable (the process's own permissions are the only bound, as for the command line).
mcp::Roots unconfined_roots() {
    std::error_code ec;
    const json list = {
        {"roots", {{{"uri", lsp::uri_from_path(fs::current_path(ec))}}, {{"uri", lsp::uri_from_path("/")}}}}};
    return mcp::Roots::from_list(list);
}

// Runs an MCP tool (mcp/tool_*.cpp) and gives its structured result; its errors become Failures.
json run_tool(std::string_view name, const json& arguments) {
    const mcp::Tool* tool = mcp::find_tool(name);
    if (!tool) throw Failure("no tool " + std::string(name));
    const mcp::Roots roots = unconfined_roots();
    try {
        return tool->run(mcp::Arguments(arguments, tool->input_schema), mcp::ToolContext{roots}).structured;
    } catch (const mcp::InvalidParams& e) {
        throw Failure(e.what());
    } catch (const mcp::ToolFailure& e) {
        throw Failure(e.what());
    }
}

json deck_arguments(const DeckSource& deck) {
    if (deck.text) return {{"text", *deck.text}, {"name", deck.path}};
    return {{"path", deck.path}};
}
}  // namespace

json check(const CheckRequest& request) {
    const DeckSource& deck = request.deck;
    const lint::Config config = config_for(request, deck.path);
    const engine::CheckOptions options = engine::options_for(config);
    std::vector<engine::CheckResult> checked;
    if (deck.text) {
        // As `sphdeck check - --stdin-filename NAME` reads standard input.
        const std::string folder = fs::path(deck.path).parent_path().string();
        checked.push_back(engine::check_buffer(*deck.text, deck.path, options, format_of(deck.format),
                                               folder.empty() ? "." : folder));
    } else {
        if (!deck.format.empty())
            throw Failure("format applies to a deck given as text; a file is read as its content and name say");
        checked = engine::check_named_file(deck.path, options).checked;
    }
    std::vector<const engine::CheckResult*> results;
    for (const engine::CheckResult& r : checked) results.push_back(&r);
    return mcp::findings_json(results);
}

std::string fix(const std::string& text, const std::string& name, bool unsafe) {
    return run_tool("fix_deck", {{"text", text}, {"name", name}, {"unsafe", unsafe}})["text"].get<std::string>();
}

std::string format(const std::string& text, const std::string& name) {
    return run_tool("format_deck", {{"text", text}, {"name", name}})["text"].get<std::string>();
}

json keyword(const std::string& name, const std::string& card_format) {
    return run_tool("keyword_layout", {{"name", name}, {"format", card_format}});
}

json smooth(const DeckSource& deck, std::optional<int> ini) {
    json arguments = deck_arguments(deck);
    if (ini) arguments["ini"] = *ini;
    return run_tool("smoothing_preview", arguments)["parts"];
}

json rules() {
    json out = json::array();
    for (const lint::RuleInfo& rule : lint::all_rules())
        out.push_back({{"code", rule.code},
                       {"name", rule.name},
                       {"severity", diag::to_string(rule.severity)},
                       {"since", rule.since},
                       {"source", rule.source},
                       {"summary", rule.summary},
                       {"fixable", lint::to_string(rule.fix)},
                       {"url", lint::rule_url(rule)}});
    return out;
}

}  // namespace sphdeck::python
