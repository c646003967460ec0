// sphdeck format DECK...: rewrite decks in their canonical layout (edit/format_deck.hpp), in place, or
// tell whether they would change (--check, for CI and pre-commit), or print the diff (--diff). The deck
// is read; it is checked too, its findings saying which lines to leave as written, unless its reading
// alone settles every line (a deck laid out already: edit::format_deck_without_findings).
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <unistd.h>

#include "cli/check_inputs.hpp"
#include "cli/commands.hpp"
#include "cli/deck_input.hpp"
#include "text/apply_edits.hpp"
#include "edit/format_deck.hpp"
#include "edit/unified_diff.hpp"
#include "engine/check.hpp"
#include "engine/config_file.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/read_deck.hpp"

namespace sphdeck::cli {
namespace {

struct FormatArgs {
    std::vector<std::string> decks;
    std::vector<std::string> exclude;
    std::string stdin_filename;
    bool check = false, diff = false, verbose = false;
    std::string to;
    edit::FormatOptions options;
    std::vector<std::string> include_paths;
};

struct Totals {
    std::size_t files = 0, changed = 0, kept = 0;
    std::array<std::size_t, edit::format_change_kinds> changes{};
};

// Writes `text` over `path` through a temporary file renamed into place (the deck may be mapped). `path` is
// the canonical path: renamed over a symbolic link, the file would replace the link and leave its target.
void write_file(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    const std::string temporary = path + ".sphdeck-format-" + std::to_string(::getpid());  // one per process
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!out) throw std::runtime_error("cannot write " + temporary);
    }
    std::error_code ignored;
    fs::permissions(temporary, fs::status(path).permissions(), ignored);
    fs::rename(temporary, path);
}

std::vector<std::string> include_paths_for(const std::string& deck, const FormatArgs& args) {
    std::vector<std::string> paths = args.include_paths;
    if (auto found = engine::find_config(deck)) {
        lint::Config config;
        if (!engine::load_config(found->string(), config))
            paths.insert(paths.end(), config.include_paths.begin(), config.include_paths.end());
    }
    return paths;
}

// How a deck is checked for its layout: read as grammar::read_deck with these include paths reads it.
engine::CheckOptions check_options(const std::vector<std::string>& include_paths) {
    engine::CheckOptions options;
    options.rules.geometry = false;  // the layout needs the reading's findings, not the particles' geometry
    options.reader.include_paths = include_paths;
    return options;
}

// A deck and its formatting. Most decks are laid out already, and then the layout needs only the reading
// (edit::format_deck_without_findings): the model and rules run only when a line may change or be kept.
struct FormattedDeck {
    std::optional<grammar::RawDeck> read;        // the reading alone, or
    std::optional<engine::CheckResult> checked;  // the check, with the findings
    std::vector<grammar::FileId> files;
    edit::FormatResult formatted;
    const grammar::RawDeck& deck() const { return read ? *read : checked->deck; }
};

FormattedDeck read_and_format(const CheckInput& input, const FormatArgs& args, const edit::FormatOptions& options) {
    std::string anchor = input.path;  // where the configuration is looked for
    if (input.path == "-") anchor = args.stdin_filename.empty() ? "." : deck_display_name("-", args.stdin_filename);
    const std::vector<std::string> include_paths = include_paths_for(anchor, args);
    const engine::CheckOptions check = check_options(include_paths);
    FormattedDeck out;
    if (input.path != "-") {  // standard input can be read once: it is checked at once
        out.read = grammar::read_deck(input.path, check.reader);  // as the check reads it
        out.files = edit::files_to_format(*out.read, options.includes);
        if (auto formatted = edit::format_deck_without_findings(*out.read, out.files, options)) {
            out.formatted = std::move(*formatted);
            return out;
        }
        // A line may change or be kept: the check takes the reading over, the deck is not read again.
        out.checked = engine::check_read_file(input.path, std::move(*out.read), check);
        out.read.reset();
    } else {
        out.checked = check_deck_input("-", args.stdin_filename, check);
    }
    out.files = edit::files_to_format(out.checked->deck, options.includes);
    out.formatted = edit::format_deck(out.checked->deck, out.checked->diagnostics, out.files, options);
    return out;
}

// Formats one deck (and its includes when asked, or when it was found in a folder: the folder's decks
// are formatted through the decks that include them); true when a file changed or would change. A deck
// read from standard input is written to standard output (with --check and --diff: nothing written).
bool format_one(const CheckInput& input, const FormatArgs& args, Totals& totals) {
    const bool from_stdin = input.path == "-";
    edit::FormatOptions format_options = args.options;
    format_options.includes = args.options.includes || input.found_in_folder;
    FormattedDeck read = read_and_format(input, args, format_options);
    const grammar::RawDeck& deck = read.deck();
    const std::vector<grammar::FileId>& files = read.files;
    edit::FormatResult& formatted = read.formatted;
    for (std::size_t k = 0; k < totals.changes.size(); ++k) totals.changes[k] += formatted.changes[k];
    totals.kept += formatted.kept;
    if (args.verbose)
        for (const auto& kept : formatted.kept_lines)
            fmt::print(stderr, "{}:{}: left as written: {}\n", deck.sources.file(kept.file).display_name, kept.line,
                       kept.reason);

    // The edits come in file order, one per changed line (a line's new text always differs from its old):
    // a file with an edit changes, and --check and --diff need not apply them.
    bool any = false;
    auto& all = formatted.edits;
    std::size_t at = 0;
    const std::size_t count = all.size();
    for (grammar::FileId id : files) {
        ++totals.files;
        while (at < count && all[at].span.file < id) ++at;
        std::size_t end = at;
        while (end < count && all[end].span.file == id) ++end;
        if (end == at) {
            if (from_stdin && !args.check && !args.diff) fmt::print("{}", deck.sources.file(id).text);
            continue;
        }
        std::vector<diag::TextEdit> edits;
        if (at == 0 && end == count)
            edits = std::move(all);  // one file: no copy (a 1M-particle deck may change every line)
        else
            edits.assign(std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(at)),
                         std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(end)));
        at = end;
        const grammar::SourceFile& file = deck.sources.file(id);
        any = true;
        ++totals.changed;
        if (args.diff)
            fmt::print("{}", edit::unified_diff(file.display_name, file.text, edits));
        else if (args.check)
            fmt::print("would reformat {}\n", file.display_name);
        else if (from_stdin)
            fmt::print("{}", text::apply_edits(file.text, edits).text);
        else
            write_file(grammar::canonical_path(file.path).string(),  // a link's target: the link stays
                       text::apply_edits(file.text, edits).text);
    }
    return any;
}

int run_format(FormatArgs& args) {
    args.options.to_fixed = args.to == "fixed";
    const ExpandedInputs expanded = expand_inputs(args.decks, args.exclude);
    if (expanded.error) {
        fmt::print(stderr, "sphdeck format: error: {}\n", *expanded.error);
        return exit_usage;
    }
    Totals totals;
    bool changed = false;
    for (const CheckInput& input : drop_included(expanded.inputs)) {
        try {
            changed = format_one(input, args, totals) || changed;
        } catch (const std::exception& e) {
            fmt::print(stderr, "sphdeck format: error: {}\n", e.what());
            return exit_usage;
        }
    }
    std::string how;
    for (std::size_t k = 0; k < totals.changes.size(); ++k)
        if (totals.changes[k] > 0)
            how += fmt::format("{}{} {}", how.empty() ? "" : ", ", totals.changes[k],
                               edit::to_string(static_cast<edit::FormatChange>(k)));
    const char* verb = args.check || args.diff ? "would reformat" : "reformatted";
    fmt::print(stderr, "{} {} of {} file{}{}{}\n", verb, totals.changed, totals.files, totals.files == 1 ? "" : "s",
               how.empty() ? "" : " (lines: " + how + ")",
               totals.kept == 0
                   ? ""
                   : fmt::format("; {} card line{} left as written{}", totals.kept, totals.kept == 1 ? "" : "s",
                                 args.verbose ? "" : " (--verbose lists them)"));
    // --check and --diff exit 1 when a file would change, as `check --diff` does.
    return (args.check || args.diff) && changed ? exit_findings : exit_clean;
}

}  // namespace

std::function<int()> setup_format(CLI::App& app) {
    auto args = std::make_shared<FormatArgs>();
    app.add_option("decks", args->decks,
                   "decks (LS-DYNA .k .key .dyn .inc, OpenRadioss _0000.rad), folders searched for them (each deck "
                   "with its includes), or - for standard input (the formatted deck goes to standard output)")
        ->required();
    app.add_option("--exclude", args->exclude,
                   "skip files and folders found in folders that match these patterns (a name, or a glob on the path)")
        ->allow_extra_args(false);
    app.add_option("--stdin-filename", args->stdin_filename, stdin_help);
    app.add_flag("--check", args->check, "write nothing; exit 1 when a file would change (CI, pre-commit)");
    app.add_flag("--diff", args->diff,
                 "write nothing; print a unified diff of the changes (exit 1 when a file would change)");
    app.add_flag("--includes", args->options.includes, "format the included files too (else only the named decks)");
    app.add_flag("--headers", args->options.headers, "write a `$#` line naming the fields above each card");
    app.add_option("--to", args->to, "rewrite free (comma) lines in fixed columns when every value fits")
        ->check(CLI::IsMember({"fixed"}));
    app.add_flag("-v,--verbose", args->verbose, "list the card lines left as written and why");
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files");
    return [args] { return run_format(*args); };
}

}  // namespace sphdeck::cli
