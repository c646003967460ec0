#include "mcp/deck_input.hpp"

#include <filesystem>

#include "diag/render_json.hpp"
#include "engine/config_file.hpp"
#include "lint/rule_catalog.hpp"

namespace sphdeck::mcp {
namespace fs = std::filesystem;
using json = nlohmann::json;

json deck_schema_properties(std::string_view what) {
    const std::string w(what);
    return {{"path",
             {{"type", "string"},
              {"description", "path of the " + w +
                                  " (LS-DYNA .k .key .dyn .inc, OpenRadioss _0000.rad), relative to the first root; "
                                  "give path or text"}}},
            {"text", {{"type", "string"}, {"description", "the " + w + "'s text, instead of a path"}}},
            {"name",
             {{"type", "string"},
              {"description",
               "with text: the file name it stands for, in the first root (default deck.k; "
               "name_0000.rad for an OpenRadioss starter deck); relative includes are found from there"}}}};
}

namespace {
// The path handed to the engine: relative paths stay as given when the first root is the working
// directory, so findings name files as `sphdeck check` run there does.
std::string engine_path(const std::string& given, const fs::path& resolved, const ToolContext& context) {
    std::error_code ec;
    if (fs::path(given).is_relative() && context.roots.base() == fs::weakly_canonical(fs::current_path(ec), ec))
        return given;
    return resolved.string();
}
}  // namespace

DeckInput deck_input(const Arguments& args, const ToolContext& context, std::string_view path_key) {
    const auto path = args.string(path_key);
    const auto text = args.string("text");
    if (path.has_value() == text.has_value())
        throw InvalidParams("give either '" + std::string(path_key) + "' or 'text'");
    DeckInput out;
    if (path) {
        const auto resolved = context.roots.resolve(*path);
        if (!resolved)
            throw InvalidParams("'" + *path + "' lies outside the roots the client named (" + context.roots.describe() +
                                ")");
        out.path = engine_path(*path, *resolved, context);
        return out;
    }
    const std::string name = args.string("name").value_or("deck.k");
    const fs::path relative(name);
    if (name.empty() || relative.is_absolute() || relative.filename() != relative || name == "." || name == "..")
        throw InvalidParams("'name' must be a plain file name (no folder), such as deck.k");
    const auto resolved = context.roots.resolve(name);
    if (!resolved) throw InvalidParams("no root to place '" + name + "' in (" + context.roots.describe() + ")");
    out.path = engine_path(name, *resolved, context);
    out.documents.set(*resolved, *text);
    out.from_text = true;
    return out;
}

engine::CheckOptions check_options(const DeckInput& deck, const ToolContext& context,
                                   const lint::ConfigOverrides& overrides) {
    lint::Config config;
    if (auto found = engine::find_config(deck.path); found && context.roots.contains(fs::absolute(*found))) {
        if (auto error = engine::load_config(found->string(), config)) throw ToolFailure(error->to_string());
    }
    lint::apply_overrides(overrides, config);
    engine::CheckOptions options;
    options.reader.include_paths = config.include_paths;
    options.config = config;
    if (config.solver) {
        options.rules.solver = *config.solver == "mpp" ? lint::Solver::Mpp : lint::Solver::Smp;
        options.rules.solver_source = config.path;
    }
    return options;
}

namespace {
// The first file the deck read outside the roots, or empty.
std::string first_outside(const engine::CheckResult& result, const ToolContext& context) {
    const grammar::SourceMap& sources = result.deck.sources;
    for (std::size_t id = 0; id < sources.size(); ++id) {
        const std::string& path = sources.file(static_cast<grammar::FileId>(id)).path;
        std::error_code ec;
        if (!path.empty() && !context.roots.contains(fs::absolute(path, ec))) return path;
    }
    return {};
}
}  // namespace

bool reads_inside_roots(const engine::CheckResult& result, const ToolContext& context) {
    return first_outside(result, context).empty();
}

void confine_reads(const engine::CheckResult& result, const ToolContext& context) {
    if (const std::string path = first_outside(result, context); !path.empty())
        throw ToolFailure("the deck reads '" + path + "', which lies outside the roots the client named (" +
                          context.roots.describe() + ")");
}

json findings_json(const std::vector<const engine::CheckResult*>& results) {
    auto report = diag::make_json_report(lint::rule_catalog());
    for (const engine::CheckResult* r : results) report->add(r->deck.sources, r->diagnostics);
    json document = json::parse(report->finish({}), nullptr, false);
    return document.is_object() ? document["diagnostics"] : json::array();
}

json counts_json(const std::vector<diag::Diagnostic>& diagnostics) {
    const diag::Counts c = diag::count(diagnostics);
    return {{"errors", c.errors}, {"warnings", c.warnings}, {"infos", c.infos}};
}

}  // namespace sphdeck::mcp
