// sphdeck rule CODE|NAME: one rule's documentation; sphdeck rules: all of them, as a table or as
// the Markdown of docs/rules.md.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "lint/rule_pages.hpp"

namespace sphdeck::cli {

std::function<int()> setup_rule(CLI::App& app) {
    auto query = std::make_shared<std::string>();
    app.add_option("rule", *query, "rule code (SPH030) or name (iavis-solid-in-2d)")->required();
    return [query] {
        if (const lint::RuleInfo* rule = lint::find_rule(*query)) {
            fmt::print("{}", lint::render_rule_page(*rule));
            return exit_clean;
        }
        fmt::print(stderr, "sphdeck: unknown rule '{}'{}\nrun 'sphdeck rules' for the list\n", *query,
                   lint::did_you_mean_rule(*query));
        return exit_usage;
    };
}

std::function<int()> setup_rules(CLI::App& app) {
    auto format = std::make_shared<std::string>("table");
    app.add_option("--format", *format, "table, or markdown (the text of docs/rules.md)")
        ->check(CLI::IsMember({"table", "markdown"}))
        ->capture_default_str();
    return [format] {
        fmt::print("{}", *format == "markdown" ? lint::render_rules_markdown() : lint::render_rules_table());
        return exit_clean;
    };
}

}  // namespace sphdeck::cli
