// workspace/symbol: the definitions of every checked deck and its includes (parts, sections,
// materials, EOS, curves, sets... and *PARAMETER names) whose "KIND id title" matches the query the
// way clients filter: the query's characters in order, any case ("pt1" finds "PART 1 tank"); an
// empty query lists everything, up to a bound.
#include <cctype>
#include <set>
#include <string>
#include <tuple>

#include "engine/id_lookup.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {
namespace {

// Symbols answered at most: a client filters further as the user types.
constexpr std::size_t kMaxSymbols = 2000;

// LSP SymbolKind values.
constexpr int kClass = 5, kFunction = 12, kVariable = 13, kObjectKind = 19, kStructKind = 23;

int symbol_kind(std::string_view kind) {
    if (kind == "PART") return kObjectKind;
    if (kind == "MAT" || kind == "EOS") return kClass;
    if (kind == "DEFINE_CURVE" || kind == "FUNCT") return kFunction;
    return kStructKind;
}

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

}  // namespace

bool symbol_matches(std::string_view query, std::string_view name) {
    std::size_t at = 0;
    for (char c : query) {
        if (c == ' ') continue;
        while (at < name.size() && lower(name[at]) != lower(c)) ++at;
        if (at == name.size()) return false;
        ++at;
    }
    return true;
}

nlohmann::json workspace_symbols(const std::vector<const CheckedDeck*>& decks, std::string_view query) {
    nlohmann::json out = nlohmann::json::array();
    std::set<std::tuple<std::string, std::uint32_t, std::uint32_t>> seen;  // an include read by two decks: once
    auto add = [&](const grammar::SourceMap& sources, const grammar::Span& span, const std::string& name, int kind) {
        if (out.size() >= kMaxSymbols || !span.valid() || span.file >= sources.size() || !symbol_matches(query, name))
            return;
        const std::string uri = uri_from_path(sources.file(span.file).path);
        if (!seen.emplace(uri, span.line, span.column).second) return;
        out.push_back({{"name", name},
                       {"kind", kind},
                       {"location", {{"uri", uri}, {"range", range_json(sources, span)}}},
                       {"containerName", sources.file(span.file).display_name}});
    };
    for (const CheckedDeck* deck : decks) {
        const auto& sources = deck->result.deck.sources;
        for (const auto& use : engine::collect_ids(deck->result)) {
            if (!use.defines) continue;
            std::string name = use.kind + " " + use.id;
            if (!use.title.empty()) name += " " + use.title;
            add(sources, use.span, name, symbol_kind(use.kind));
        }
        for (const auto& p : deck->result.deck.parameters.definitions())
            add(sources, p.span, "PARAMETER " + p.name, kVariable);
    }
    return out;
}

}  // namespace sphdeck::lsp
