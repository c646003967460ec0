// sphdeck diff A B: what the solver reads differently in two decks (engine/deck_diff.hpp). Exit 0 when
// nothing differs, 1 when something does, 2 on an error, as diff(1).
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/deck_input.hpp"
#include "engine/check.hpp"
#include "engine/deck_diff.hpp"

namespace sphdeck::cli {
namespace {

struct DiffArgs {
    std::string before, after;
    std::string stdin_filename;
    std::string format = "text";
    double rtol = 1e-12;
    std::vector<std::string> include_paths;
};

std::string shown_json(const nlohmann::ordered_json& value) {
    if (value.is_null()) return "(none)";
    if (value.is_string()) return value.get<std::string>();
    return value.dump();
}

std::string diff_location(const engine::DiffLocation& at) {
    if (at.line == 0) return at.file.empty() ? "default" : at.file + " (default)";
    return at.column > 0 ? fmt::format("{}:{}:{}", at.file, at.line, at.column)
                         : fmt::format("{}:{}", at.file, at.line);
}

std::string id_list(const std::vector<long long>& list, std::size_t count) {
    std::string out;
    for (long long id : list) out += fmt::format("{}{}", out.empty() ? "" : ", ", id);
    if (count > list.size()) out += fmt::format(", ... {} more", count - list.size());
    return out;
}

void print_bulk(std::string_view what, std::string_view changed_word, const engine::BulkChange& b, bool nodes) {
    if (b.equal()) return;
    std::string line = fmt::format("{}: {} -> {}", what, b.before_count, b.after_count);
    if (b.added) line += fmt::format("; {} added ({})", b.added, id_list(b.added_ids, b.added));
    if (b.removed) line += fmt::format("; {} removed ({})", b.removed, id_list(b.removed_ids, b.removed));
    if (b.changed) line += fmt::format("; {} {} ({})", b.changed, changed_word, id_list(b.changed_ids, b.changed));
    if (nodes && b.changed)
        line +=
            fmt::format("; largest displacement {:.6g} at node {}", b.largest_displacement, b.largest_displacement_id);
    fmt::print("{}\n", line);
}

void print_diff(const engine::DeckDiff& diff) {
    using Kind = engine::KeywordChange::Kind;
    for (const auto& k : diff.keywords) {
        const std::string name = k.id.empty() ? k.name : k.name + " " + k.id;
        if (k.kind == Kind::Added) {
            fmt::print("added {} ({})\n", name, diff_location(k.after_at));
        } else if (k.kind == Kind::Removed) {
            fmt::print("removed {} ({})\n", name, diff_location(k.before_at));
        } else {
            fmt::print("{} ({} -> {})\n", name, diff_location(k.before_at), diff_location(k.after_at));
            for (const auto& f : k.fields)
                fmt::print("  {}: {} -> {}  ({} -> {})\n", f.field, shown_json(f.before), shown_json(f.after),
                           diff_location(f.before_at), diff_location(f.after_at));
        }
    }
    print_bulk("nodes", "moved", diff.nodes, true);
    print_bulk("particles", "with another part or mass", diff.particles, false);
    if (diff.equal()) fmt::print("no difference in what the solver reads\n");
}

int run_diff(const DiffArgs& args) {
    if (args.before == "-" && args.after == "-") {
        fmt::print(stderr, "sphdeck diff: error: only one of the two decks can be read from standard input (-)\n");
        return exit_usage;
    }
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    options.rules.geometry = false;  // the values are what count, not the neighbour rules
    engine::CheckResult before, after;
    try {
        before = check_deck_input(args.before, args.stdin_filename, options);
        after = check_deck_input(args.after, args.stdin_filename, options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "sphdeck: error: {}\n", e.what());
        return exit_usage;
    }
    const engine::DeckDiff diff = engine::diff_decks(before, after, args.rtol);
    if (args.format == "json") {
        fmt::print("{}\n", engine::to_json(diff).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
    } else {
        print_diff(diff);
    }
    return diff.equal() ? exit_clean : exit_findings;
}

}  // namespace

std::function<int()> setup_diff(CLI::App& app) {
    auto args = std::make_shared<DiffArgs>();
    app.add_option("before", args->before, "the first deck (LS-DYNA or OpenRadioss starter), or - for standard input")
        ->required();
    app.add_option("after", args->after, "the second deck, or - for standard input")->required();
    app.add_option("--stdin-filename", args->stdin_filename, stdin_help);
    app.add_option("--format", args->format, "output format")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    app.add_option("--rtol", args->rtol, "numbers closer than this relative tolerance are equal")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files")
        ->allow_extra_args(false);
    return [args] { return run_diff(*args); };
}

}  // namespace sphdeck::cli
