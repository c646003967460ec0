// Project settings for `sphdeck check`: a `sphdeck.toml` found next to the deck or in a folder
// above it, overridden by command-line options. Rules read the parsed settings through
// CheckOptions::config (e.g. `config.solver` for the SMP/MPP rules).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::lint {

// The lowest severity that makes `sphdeck check` exit with 1; Never: findings never do.
enum class FailOn { Info, Warning, Error, Never };

struct Config {
    std::string path;  // the file the settings came from; empty when none was read
    // Rule selectors: a code ("SPH032"), a name ("form-not-recommended") or a code prefix ("SPH",
    // "SPH03"), codes case-insensitive. An empty `select` selects every rule; `ignore` wins over it.
    std::vector<std::string> select;
    std::vector<std::string> ignore;
    std::map<std::string, diag::Severity, std::less<>> severity;  // rule code -> replaced default
    std::optional<std::string> solver;       // "smp" or "mpp"; unset when the run type is not known
    std::optional<FailOn> fail_on;           // unset: error
    std::vector<std::string> include_paths;  // made absolute against the config file's folder
    // The main decks, or folders of them, in which an include file checked on its own is looked for
    // (engine/include_context.hpp); made absolute like include_paths. Empty: the folders around the file.
    std::vector<std::string> roots;
};

// A configuration problem, positioned in the file where possible (line 0: no position).
struct ConfigError {
    std::string file;
    std::uint32_t line = 0, column = 0;
    std::string message;

    std::string to_string() const;  // "file:line:column: error: message", as compilers write it
};

// Parses TOML text into `out`; `path` names the file in errors and anchors relative include paths.
// Finding and reading the file is engine/config_file.hpp's job: lint reads no files.
std::optional<ConfigError> parse_config(std::string_view text, const std::string& path, Config& out);

// Command-line settings; each overrides what the file says.
struct ConfigOverrides {
    std::optional<std::vector<std::string>> select;  // replaces the file's list
    std::vector<std::string> ignore;                 // added to the file's list
    std::optional<std::string> solver;
    std::optional<FailOn> fail_on;
    std::vector<std::string> include_paths;  // searched before the file's
};
void apply_overrides(const ConfigOverrides& overrides, Config& config);

// Whether a selector names at least one registered rule; the error message ("unknown rule 'X'; did
// you mean ...") otherwise.
std::optional<std::string> check_selector(std::string_view selector);
bool parse_fail_on(std::string_view word, FailOn& out);
bool selector_matches(std::string_view selector, std::string_view code);

// Re-levels diagnostics by `severity`, then drops the ones `select`/`ignore` leave out.
void apply_rule_settings(const Config& config, std::vector<diag::Diagnostic>& diagnostics);

// Whether these diagnostics make the run fail under `fail_on` (unset: error).
bool fails(const Config& config, const std::vector<diag::Diagnostic>& diagnostics);

}  // namespace sphdeck::lint
