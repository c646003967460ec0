// sphdeck.toml: parsing with toml++, validation, and applying the rule settings (engine/config_file finds and reads the
// file).
#include "lint/config.hpp"

#include <toml++/toml.h>

#include <algorithm>

#include "lint/registry.hpp"
#include "lint/rule_pages.hpp"

namespace sphdeck::lint {
namespace fs = std::filesystem;

namespace {

char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

bool istarts_with(std::string_view text, std::string_view prefix) {
    return text.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) { return upper(a) == upper(b); });
}

std::string join(const std::vector<std::string_view>& items) {
    std::string out;
    for (std::string_view item : items) out += (out.empty() ? "" : "', '") + std::string(item);
    return out;
}

ConfigError error_at(const std::string& file, const toml::source_region& where, std::string message) {
    return ConfigError{file, where.begin.line, where.begin.column, std::move(message)};
}

// An array of strings, or an error naming the key.
std::optional<ConfigError> read_strings(const std::string& file, std::string_view key, const toml::node& node,
                                        std::vector<std::string>& out) {
    const toml::array* array = node.as_array();
    if (!array) return error_at(file, node.source(), "'" + std::string(key) + "' must be an array of strings");
    for (const toml::node& item : *array) {
        auto text = item.value<std::string>();
        if (!item.is_string() || !text)
            return error_at(file, item.source(), "'" + std::string(key) + "' must be an array of strings");
        out.push_back(*text);
    }
    return std::nullopt;
}

std::optional<ConfigError> read_selectors(const std::string& file, std::string_view key, const toml::node& node,
                                          std::vector<std::string>& out) {
    if (auto e = read_strings(file, key, node, out)) return e;
    const toml::array& array = *node.as_array();
    for (std::size_t i = 0; i < out.size(); ++i)
        if (auto problem = check_selector(out[i])) return error_at(file, array[i].source(), *problem);
    return std::nullopt;
}

std::optional<ConfigError> read_severity_table(const std::string& file, const toml::node& node, Config& out) {
    const toml::table* table = node.as_table();
    if (!table)
        return error_at(file, node.source(), "'severity' must be a table such as [severity] SPH032 = \"error\"");
    for (auto&& [key, value] : *table) {
        const RuleInfo* rule = find_rule(key.str());
        if (!rule) {
            auto unknown = check_selector(key.str());  // a valid prefix still names no single rule
            return error_at(file, key.source(),
                            unknown ? *unknown
                                    : "'" + std::string(key.str()) + "' is not one rule: give a code or name");
        }
        diag::Severity severity{};
        auto word = value.value<std::string>();
        if (!value.is_string() || !word || *word == "note" || !diag::parse_severity(*word, severity))
            return error_at(file, value.source(),
                            "severity of " + std::string(rule->code) + " must be \"error\", \"warning\" or \"info\"");
        out.severity[std::string(rule->code)] = severity;
    }
    return std::nullopt;
}

// A string from a fixed set of words, or an error listing them.
std::optional<ConfigError> read_word(const std::string& file, std::string_view key, const toml::node& node,
                                     std::vector<std::string_view> allowed, std::string& out) {
    auto word = node.value<std::string>();
    if (!node.is_string() || !word || std::find(allowed.begin(), allowed.end(), *word) == allowed.end())
        return error_at(file, node.source(), "'" + std::string(key) + "' must be one of '" + join(allowed) + "'");
    out = *word;
    return std::nullopt;
}

}  // namespace

std::string ConfigError::to_string() const {
    if (line == 0) return file + ": error: " + message;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: " + message;
}

std::optional<ConfigError> parse_config(std::string_view text, const std::string& path, Config& out) {
    out = Config{};
    out.path = path;
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        return error_at(path, e.source(), "invalid TOML: " + std::string(e.description()));
    }
    const fs::path folder = fs::path(path).parent_path();
    for (auto&& [key, node] : root) {
        const std::string_view name = key.str();
        std::optional<ConfigError> problem;
        if (name == "select") {
            problem = read_selectors(path, name, node, out.select);
        } else if (name == "ignore") {
            problem = read_selectors(path, name, node, out.ignore);
        } else if (name == "severity") {
            problem = read_severity_table(path, node, out);
        } else if (name == "solver") {
            std::string word;
            problem = read_word(path, name, node, {"smp", "mpp"}, word);
            out.solver = word;
        } else if (name == "fail-on") {
            std::string word;
            problem = read_word(path, name, node, {"error", "warning", "info", "never"}, word);
            FailOn level{};
            if (!problem && parse_fail_on(word, level)) out.fail_on = level;
        } else if (name == "include-paths") {
            std::vector<std::string> paths;
            problem = read_strings(path, name, node, paths);
            for (const std::string& p : paths) out.include_paths.push_back((folder / p).lexically_normal().string());
        } else if (name == "roots") {
            std::vector<std::string> paths;
            problem = read_strings(path, name, node, paths);
            for (const std::string& p : paths) out.roots.push_back((folder / p).lexically_normal().string());
        } else {
            problem = error_at(path, key.source(),
                               "unknown key '" + std::string(name) +
                                   "'; expected select, ignore, severity, solver, fail-on, include-paths or roots");
        }
        if (problem) return problem;
    }
    return std::nullopt;
}

void apply_overrides(const ConfigOverrides& overrides, Config& config) {
    if (overrides.select) config.select = *overrides.select;
    config.ignore.insert(config.ignore.end(), overrides.ignore.begin(), overrides.ignore.end());
    if (overrides.solver) config.solver = overrides.solver;
    if (overrides.fail_on) config.fail_on = overrides.fail_on;
    config.include_paths.insert(config.include_paths.begin(), overrides.include_paths.begin(),
                                overrides.include_paths.end());
}

bool selector_matches(std::string_view selector, std::string_view code) {
    if (selector.empty()) return false;
    if (istarts_with(code, selector)) return true;  // the code itself or a prefix of it
    const RuleInfo* rule = find_rule(code);
    return rule && rule->name == selector;
}

std::optional<std::string> check_selector(std::string_view selector) {
    for (const RuleInfo& rule : all_rules())
        if (selector_matches(selector, rule.code)) return std::nullopt;
    return "unknown rule '" + std::string(selector) + "'" + did_you_mean_rule(selector);
}

bool parse_fail_on(std::string_view word, FailOn& out) {
    if (word == "error")
        out = FailOn::Error;
    else if (word == "warning")
        out = FailOn::Warning;
    else if (word == "info")
        out = FailOn::Info;
    else if (word == "never")
        out = FailOn::Never;
    else
        return false;
    return true;
}

void apply_rule_settings(const Config& config, std::vector<diag::Diagnostic>& diagnostics) {
    auto any_match = [](const std::vector<std::string>& selectors, std::string_view code) {
        return std::any_of(selectors.begin(), selectors.end(),
                           [&](const std::string& s) { return selector_matches(s, code); });
    };
    std::erase_if(diagnostics, [&](const diag::Diagnostic& d) {
        return (!config.select.empty() && !any_match(config.select, d.code)) || any_match(config.ignore, d.code);
    });
    if (config.severity.empty()) return;
    for (diag::Diagnostic& d : diagnostics)
        if (auto it = config.severity.find(d.code); it != config.severity.end()) d.severity = it->second;
}

bool fails(const Config& config, const std::vector<diag::Diagnostic>& diagnostics) {
    const FailOn level = config.fail_on.value_or(FailOn::Error);
    if (level == FailOn::Never) return false;
    return std::any_of(diagnostics.begin(), diagnostics.end(), [&](const diag::Diagnostic& d) {
        switch (level) {
            case FailOn::Info: return true;
            case FailOn::Warning: return d.severity != diag::Severity::Info;
            default: return d.severity == diag::Severity::Error;
        }
    });
}

}  // namespace sphdeck::lint
