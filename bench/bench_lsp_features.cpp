// bench_lsp_features: how long the editor server's request features take on a checked deck
// (hover, definition, references, completion, outline, folding, semantic tokens, inlay hints,
// rename, document links, code lens),
// medians of several runs.
//
//   bench_lsp_features DECK [RUNS]      (RUNS defaults to 5)
//
// With the 1M-particle deck of gen_big_deck (bench/README.md): a request that is about one line
// must not scan the particles; references of the particles' part scan the particle arrays once.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "lsp/features.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median_ms(int runs, const std::function<void()>& run) {
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        const auto start = Clock::now();
        run();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

// 0-based line of the first line of `file` starting with `prefix`, after line `from`.
std::uint32_t line_of(const sphdeck::grammar::SourceMap& sources, std::string_view prefix, std::uint32_t from = 0) {
    const std::uint32_t lines = sources.line_count(0);
    for (std::uint32_t l = from + 1; l <= lines; ++l)
        if (sources.line_text(0, l).substr(0, prefix.size()) == prefix) return l - 1;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_lsp_features DECK [RUNS]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    sphdeck::lsp::CheckedDeck deck;
    deck.main = argv[1];
    const auto start = Clock::now();
    try {
        deck.result = sphdeck::engine::check_file(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_lsp_features: %s\n", e.what());
        return 2;
    }
    std::printf("check: %.0f ms, %zu particles, %zu lines\n",
                std::chrono::duration<double, std::milli>(Clock::now() - start).count(),
                deck.result.model.particles.size(), deck.result.deck.lines.size());
    const auto& sources = deck.result.deck.sources;
    const std::uint32_t part = line_of(sources, "*PART");
    const std::uint32_t part_card = line_of(sources, "         1", part + 2);  // after the heading line
    const std::uint32_t elements = line_of(sources, "*ELEMENT_SPH");
    const std::uint32_t middle = elements + static_cast<std::uint32_t>(deck.result.model.particles.size() / 2);
    auto at = [](std::uint32_t line, std::uint32_t character) {
        return nlohmann::json{{"position", {{"line", line}, {"character", character}}},
                              {"context", {{"includeDeclaration", true}}}};
    };
    auto lines = [](std::uint32_t first, std::uint32_t last) {
        return nlohmann::json{
            {"range", {{"start", {{"line", first}, {"character", 0}}}, {"end", {{"line", last}, {"character", 0}}}}}};
    };
    auto bulk = [&](std::uint32_t first, std::uint32_t last) {
        nlohmann::json params = lines(first, last);
        params["settings"] = {{"bulkBlocks", true}};
        return params;
    };
    auto renamed = [](nlohmann::json params, const char* name) {
        params["newName"] = name;
        return params;
    };
    struct Request {
        const char* what;
        const char* method;
        nlohmann::json params;
    };
    const std::vector<Request> requests{
        {"hover, a particle's PID (mid *ELEMENT_SPH)", "textDocument/hover", at(middle, 15)},
        {"hover, the part's SECID", "textDocument/hover", at(part_card, 19)},
        {"definition, a particle's PID", "textDocument/definition", at(middle, 15)},
        {"definition, the part's MID", "textDocument/definition", at(part_card, 29)},
        {"definition, a particle's NID (its *NODE line)", "textDocument/definition", at(middle, 7)},
        {"references, a node (*NODE line, mid block)", "textDocument/references", at(middle - 1000000, 7)},
        {"references, the part (<= 10000 particles)", "textDocument/references", at(part_card, 9)},
        {"completion, the part's SECID", "textDocument/completion", at(part_card, 19)},
        {"documentSymbol", "textDocument/documentSymbol", nlohmann::json::object()},
        {"foldingRange", "textDocument/foldingRange", nlohmann::json::object()},
        // Issue 29: a screenful (60 lines) mid particles, the head of the deck, the whole file (capped).
        {"semanticTokens/range, 60 lines mid particles", "textDocument/semanticTokens/range",
         lines(middle, middle + 60)},
        {"semanticTokens/range, first 200 lines", "textDocument/semanticTokens/range", lines(0, 200)},
        {"semanticTokens/full (capped: bulk values left out)", "textDocument/semanticTokens/full",
         nlohmann::json::object()},
        {"inlayHint, 60 lines mid particles (off there)", "textDocument/inlayHint", lines(middle, middle + 60)},
        {"inlayHint, 60 lines mid particles, bulkBlocks", "textDocument/inlayHint", bulk(middle, middle + 60)},
        {"inlayHint, first 200 lines", "textDocument/inlayHint", lines(0, 200)},
        // Issue 45: rename the part (its *PART line and every particle's PID), the section (two fields).
        {"rename, the part (every particle's PID)", "textDocument/rename", renamed(at(part_card, 9), "9")},
        {"rename, the part's SECID", "textDocument/rename", renamed(at(part_card, 19), "99")},
        {"prepareRename, a particle's PID", "textDocument/prepareRename", at(middle, 15)},
        {"documentLink", "textDocument/documentLink", nlohmann::json::object()},
        {"codeLens (particles counted)", "textDocument/codeLens", nlohmann::json::object()},
    };
    std::printf("%-45s %10s  %s\n", "request", "median ms", "answer");
    for (const auto& r : requests) {
        nlohmann::json result;
        const double ms = median_ms(runs, [&] {
            try {
                result = sphdeck::lsp::answer_feature(r.method, deck, 0, r.params).result;
            } catch (const sphdeck::lsp::FeatureError& e) {  // a refused rename: its reason is the answer
                result = nlohmann::json::array({e.what()});
            }
        });
        std::string answer = result.is_array()  ? std::to_string(result.size()) + " items"
                             : result.is_null() ? "null"
                             : result.contains("changes") && !result["changes"].empty()
                                 ? std::to_string(result["changes"].begin()->size()) + " edits"
                             : result.contains("data") ? std::to_string(result["data"].size() / 5) + " tokens"
                                                       : "object";
        std::printf("%-45s %10.2f  %s\n", r.what, ms, answer.c_str());
        if (std::getenv("BENCH_SHOW")) std::printf("%s\n", result.dump().substr(0, 600).c_str());
    }
    return 0;
}
