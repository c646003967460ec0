// bench_incremental: big decks in the editor (issue 29 item 5). Where the time of a check goes, and
// the editor server's four figures beside their goals, medians of several runs:
//   open   the 1M-particle deck opened -> first diagnostics (the didOpen body parsed as JSON, the
//          document opened and checked, its diagnostics turned into LSP JSON)       goal <= 1000 ms
//   edit   the *PART title edited -> diagnostics (outside the bulk blocks)          goal <=  100 ms
//   bulk   a coordinate mid *NODE edited -> diagnostics (inside a bulk block)       goal <=  300 ms
//   small  a coordinate of the 10,000-line deck edited -> diagnostics               goal <=   10 ms
//   burst  200 changes of the *PART title typed without a check between them, then one check:
//          each change's cost, and the last change -> diagnostics                  goal <= 1000 ms
//   (issue 45 goals: open <= 700 ms, edit <= 50 ms, bulk <= 100 ms; issue 29's were 1000/100/300/20)
//
//   bench_incremental BIG_DECK SMALL_DECK [RUNS]      (RUNS defaults to 5; decks: gen_big_deck)
//   BENCH_PROFILE_EDITS=N [BENCH_PROFILE_BULK=1] bench_incremental ...: one open, then N edits of the
//   title (or of a *NODE x) and nothing else, for a profiler (perf record -g); BENCH_PROFILE_SMALL=1:
//   N edits of the 10,000-line deck's *NODE x instead.
//
// It drives lsp::Workspace in-process (no pipe): bench/bench_lsp.py measures the same over stdio.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "engine/check.hpp"
#include "lint/fold_causes.hpp"
#include "lint/rules.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/document_text.hpp"
#include "lsp/json_rpc.hpp"
#include "lsp/text_change.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"
#include "model/model_builder.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using sphdeck::lsp::Workspace;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time of the process so far (every thread), in ms: on a loaded machine the steadier figure.
double cpu_ms() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// Wall and CPU ms of a step.
struct Timed {
    std::vector<double> wall, cpu;
};

double median(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    return times.empty() ? 0.0 : times[times.size() / 2];
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read " + path);
    return text.str();
}

// 0-based number of the first line starting with `prefix` (after line `after`), and the lines.
std::vector<std::string_view> split_lines(const std::string& text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.emplace_back(text.data() + start, end - start);
        start = end + 1;
    }
    return lines;
}
std::uint32_t line_of(const std::vector<std::string_view>& lines, std::string_view prefix, std::uint32_t after = 0) {
    for (std::uint32_t i = after; i < lines.size(); ++i)
        if (lines[i].substr(0, prefix.size()) == prefix) return i;
    throw std::runtime_error("no line starts with " + std::string(prefix));
}

nlohmann::json replace_change(std::uint32_t line, std::uint32_t from, std::uint32_t to, const std::string& text) {
    return nlohmann::json::array(
        {{{"range", {{"start", {{"line", line}, {"character", from}}}, {"end", {{"line", line}, {"character", to}}}}},
          {"text", text}}});
}

// A workspace holding one open deck; `published` counts the publishDiagnostics it sent.
struct Editor {
    std::size_t published = 0;
    Workspace workspace{[this](const nlohmann::json&) { ++published; }};
    std::string uri;
    std::int64_t version = 1;

    // The figures of an edit: `edits` changes of the same place, alternating two values.
    Timed edit(int edits, std::uint32_t line, std::uint32_t from, std::uint32_t to, const std::string& first,
               const std::string& second) {
        Timed times;
        for (int i = 0; i < edits; ++i) {
            const std::string& value = i % 2 ? first : second;
            const std::uint32_t end = i == 0 ? to : from + static_cast<std::uint32_t>(first.size());
            const auto start = Clock::now();
            const double cpu = cpu_ms();
            workspace.change(uri, ++version, replace_change(line, from, end, value));
            workspace.flush();
            times.wall.push_back(ms_since(start));
            times.cpu.push_back(cpu_ms() - cpu);
        }
        return times;
    }

    // A burst: `changes` one-character insertions typed into `line` at `column` (an editor sending
    // them without waiting), then the one check that covers them all. `per_change`: each change's
    // own cost; `after_last`: the last change -> diagnostics.
    void burst(int changes, std::uint32_t line, std::uint32_t column, Timed& per_change, Timed& after_last) {
        for (int i = 0; i < changes; ++i) {
            const auto start = Clock::now();
            const double cpu = cpu_ms();
            const std::uint32_t at = column + static_cast<std::uint32_t>(i);
            workspace.change(uri, ++version,
                             replace_change(line, at, at, std::string(1, static_cast<char>('a' + i % 26))));
            per_change.wall.push_back(ms_since(start));
            per_change.cpu.push_back(cpu_ms() - cpu);
        }
        const auto start = Clock::now();
        const double cpu = cpu_ms();
        const std::size_t before = published;
        workspace.flush();
        if (published == before) throw std::runtime_error("no diagnostics published after a burst");
        after_last.wall.push_back(ms_since(start));
        after_last.cpu.push_back(cpu_ms() - cpu);
    }
};

void figure(const char* what, const Timed& times, double goal_ms) {
    const double m = median(times.wall);
    std::printf("%-58s median %8.1f ms (min %8.1f max %8.1f, n=%zu; CPU median %8.1f ms)  goal %5.0f ms %s\n", what, m,
                *std::min_element(times.wall.begin(), times.wall.end()),
                *std::max_element(times.wall.begin(), times.wall.end()), times.wall.size(), median(times.cpu), goal_ms,
                m <= goal_ms ? "met" : "NOT MET");
}

// Where the time of one check of `text` goes, stage by stage (one run each).
void profile(const std::string& path, const std::string& text) {
    using namespace sphdeck;
    std::printf("profile of one check of %s (one run per stage):\n", path.c_str());
    const nlohmann::json open = {{"jsonrpc", "2.0"},
                                 {"method", "textDocument/didOpen"},
                                 {"params", {{"textDocument", {{"uri", lsp::uri_from_path(path)}, {"text", text}}}}}};
    std::string body = open.dump();  // as the server's reader holds it, and gives it up
    auto start = Clock::now();
    double cpu = cpu_ms();
    auto parsed = lsp::parse_body_taking(body);
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "didOpen body parsed (JSON)", ms_since(start), cpu_ms() - cpu);
    start = Clock::now(), cpu = cpu_ms();
    std::string copy = (*parsed)["params"]["textDocument"]["text"].get<std::string>();
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "text copied out of the JSON", ms_since(start), cpu_ms() - cpu);
    parsed.reset();
    start = Clock::now(), cpu = cpu_ms();
    {
        std::string again = copy;  // what each copy of the document costs (a check reads one from the overlay)
        std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "one more copy of the text", ms_since(start),
                    cpu_ms() - cpu);
    }
    engine::CheckOptions options;
    start = Clock::now(), cpu = cpu_ms();
    grammar::RawDeck deck = grammar::read_deck_buffer(copy, path, ".", options.reader);
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "deck read (grammar/)", ms_since(start), cpu_ms() - cpu);
    std::vector<diag::Diagnostic> findings = deck.diagnostics;
    start = Clock::now(), cpu = cpu_ms();
    model::Model model = model::build_model(deck, findings);
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "model decoded (model/)", ms_since(start), cpu_ms() - cpu);
    {
        lint::RuleOptions no_geometry;
        no_geometry.geometry = false;
        std::vector<diag::Diagnostic> out = findings;
        lint::RuleContext context(model, deck, no_geometry, out);
        start = Clock::now(), cpu = cpu_ms();
        lint::run_rules(context);
        std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "rules without the geometry (lint/)", ms_since(start),
                    cpu_ms() - cpu);
    }
    start = Clock::now(), cpu = cpu_ms();
    auto preview = lint::compute_rules_preview(model);
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "geometry preview (preproc/)", ms_since(start), cpu_ms() - cpu);
    preview.reset();
    start = Clock::now(), cpu = cpu_ms();
    engine::CheckResult result = engine::check_buffer(copy, path, options);
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "whole check (engine::check_buffer)", ms_since(start),
                cpu_ms() - cpu);
    // Issue 45 item 1: what one change of the document costs, held as one string (the way before:
    // lsp::changed_text builds the changed text in one pass) and as chunks of lines (lsp::DocumentText),
    // and joining the chunks for a check (once per check, not per change).
    {
        const auto lines = split_lines(copy);
        const std::uint32_t node = (line_of(lines, "*NODE") + line_of(lines, "*ELEMENT_SPH")) / 2;
        const nlohmann::json change = replace_change(node, 8, 9, "2")[0];
        start = Clock::now(), cpu = cpu_ms();
        auto changed = lsp::changed_text(copy, change);
        std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "a change mid *NODE, one string (before)", ms_since(start),
                    cpu_ms() - cpu);
        changed.reset();
        lsp::DocumentText chunked(std::make_shared<const std::string>(copy));
        start = Clock::now(), cpu = cpu_ms();
        chunked.apply(change);
        std::printf("  %-44s %9.3f ms wall %9.3f ms CPU\n", "the same change, chunks of lines (now)", ms_since(start),
                    cpu_ms() - cpu);
        start = Clock::now(), cpu = cpu_ms();
        const std::string joined = chunked.joined();
        std::printf("  %-44s %9.1f ms wall %9.1f ms CPU\n", "chunks joined for a check (once per check)",
                    ms_since(start), cpu_ms() - cpu);
    }
    start = Clock::now(), cpu = cpu_ms();
    auto json = lsp::findings_by_file(result, [](const auto&, const std::string& p) { return p; });
    std::printf("  %-44s %9.1f ms wall %9.1f ms CPU (%zu findings)\n", "findings as LSP JSON", ms_since(start),
                cpu_ms() - cpu, result.diagnostics.size());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_incremental BIG_DECK SMALL_DECK [RUNS]\n");
        return 2;
    }
    const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
    const std::string big_path = std::filesystem::absolute(argv[1]).string();
    const std::string small_path = std::filesystem::absolute(argv[2]).string();
    try {
        const std::string big = read_all(big_path), small = read_all(small_path);
        if (std::getenv("BENCH_PROFILE_EDITS") && std::getenv("BENCH_PROFILE_SMALL")) {
            Editor editor;
            editor.uri = sphdeck::lsp::uri_from_path(small_path);
            editor.workspace.open(editor.uri, small, 1);
            editor.workspace.flush();
            const std::uint32_t node = line_of(split_lines(small), "*NODE") + 1200;
            const int n = std::max(1, std::atoi(std::getenv("BENCH_PROFILE_EDITS")));
            const Timed times = editor.edit(n, node, 8, 24, " 1.00000000e-03", "-1.00000000e-03");
            std::printf("%d edits of the small deck: median %.2f ms wall, %.2f ms CPU\n", n, median(times.wall),
                        median(times.cpu));
            return 0;
        }
        if (!std::getenv("BENCH_NO_PROFILE")) profile(big_path, big);

        const auto big_lines = split_lines(big);
        const std::uint32_t title = line_of(big_lines, "*PART") + 2;
        const std::uint32_t node = (line_of(big_lines, "*NODE") + line_of(big_lines, "*ELEMENT_SPH")) / 2;
        Timed open_times, edit_times, bulk_times, burst_times, burst_changes;
        const std::string open_body =
            nlohmann::json{{"jsonrpc", "2.0"},
                           {"method", "textDocument/didOpen"},
                           {"params",
                            {{"textDocument",
                              {{"uri", sphdeck::lsp::uri_from_path(big_path)}, {"version", 1}, {"text", big}}}}}}
                .dump();
        for (int run = 0; run < runs; ++run) {
            Editor editor;
            editor.uri = sphdeck::lsp::uri_from_path(big_path);
            std::string body = open_body;  // the body as the server's reader holds it (it gives it up)
            const auto start = Clock::now();
            const double cpu = cpu_ms();
            {
                auto message = sphdeck::lsp::parse_body_taking(body);
                auto& text = (*message)["params"]["textDocument"]["text"].get_ref<std::string&>();
                editor.workspace.open(editor.uri, std::move(text), 1);
            }
            editor.workspace.flush();
            open_times.wall.push_back(ms_since(start));
            open_times.cpu.push_back(cpu_ms() - cpu);
            if (editor.published == 0) throw std::runtime_error("no diagnostics published on open");
            if (run == 0 && std::getenv("BENCH_PROFILE_EDITS")) {
                // For a profiler: many edits after one open, then nothing else (BENCH_PROFILE_EDITS=N).
                const int n = std::max(1, std::atoi(std::getenv("BENCH_PROFILE_EDITS")));
                const bool bulk = std::getenv("BENCH_PROFILE_BULK") != nullptr;
                if (bulk)
                    editor.edit(n, node, 8, 24, " 1.00000000e-03", "-1.00000000e-03");
                else
                    editor.edit(n, title, 0, static_cast<std::uint32_t>(big_lines[title].size()), "water block A",
                                "water block B");
                return 0;
            }
            if (run == 0) {
                edit_times = editor.edit(runs * 2 - 1, title, 0, static_cast<std::uint32_t>(big_lines[title].size()),
                                         "water block A", "water block B");
                bulk_times = editor.edit(runs * 2 - 1, node, 8, 24, " 1.00000000e-03", "-1.00000000e-03");
            }
            editor.burst(200, title, 0, burst_changes, burst_times);
        }
        Editor editor;
        editor.uri = sphdeck::lsp::uri_from_path(small_path);
        editor.workspace.open(editor.uri, small, 1);
        editor.workspace.flush();
        const auto small_lines = split_lines(small);
        const std::uint32_t small_node = line_of(small_lines, "*NODE") + 1200;
        const auto small_times = editor.edit(runs * 2 - 1, small_node, 8, 24, " 1.00000000e-03", "-1.00000000e-03");

        std::printf("\nbig deck %s: %zu lines; small deck %s: %zu lines\n", big_path.c_str(), big_lines.size() - 1,
                    small_path.c_str(), small_lines.size() - 1);
        figure("open -> first diagnostics (1M particles)", open_times, 700);
        figure("edit outside the bulk blocks (*PART title) -> diagnostics", edit_times, 50);
        figure("edit inside a bulk block (*NODE x) -> diagnostics", bulk_times, 100);
        figure("edit of the 10,000-line deck (*NODE x) -> diagnostics", small_times, 10);
        figure("one change of a burst, without its check (*PART title)", burst_changes, 5);
        figure("burst of 200 changes: the last -> diagnostics", burst_times, 1000);
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::printf("peak RSS of this process %.0f MiB (it also holds the deck and the didOpen body: %.0f MiB each)\n",
                    usage.ru_maxrss / 1024.0, big.size() / 1048576.0);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_incremental: %s\n", e.what());
        return 1;
    }
    return 0;
}
