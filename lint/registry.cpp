// The rule registry: the rows joined with their documentation pages, sorted by code, and look-ups.
#include "lint/registry.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>

#include "grammar/similar_names.hpp"
#include "lint/rule_docs.hpp"

namespace sphdeck::lint {
namespace {

char to_lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

std::string lowered(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), to_lower);
    return out;
}

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return to_lower(x) == to_lower(y); });
}

}  // namespace

std::string_view to_string(Fixable f) {
    switch (f) {
        case Fixable::Safe: return "safe";
        case Fixable::Unsafe: return "unsafe";
        case Fixable::Mixed: return "safe or unsafe";
        case Fixable::None: break;
    }
    return "none";
}

namespace {

// The rows with their documentation pages; a row without a page keeps an empty doc (a test fails).
std::vector<RuleInfo> build_table() {
    std::vector<RuleInfo> rows(detail::rule_rows().begin(), detail::rule_rows().end());
    for (RuleInfo& row : rows)
        if (const RuleDocPage* page = find_rule_doc_page(row.code)) row.doc = page->doc();
    std::sort(rows.begin(), rows.end(), [](const RuleInfo& a, const RuleInfo& b) { return a.code < b.code; });
    return rows;
}

const std::vector<RuleInfo>& registry_table() {
    static const std::vector<RuleInfo> rows = build_table();
    return rows;
}

// How well `query` (lower case) matches `candidate`: (kind, distance), smaller is better.
// kind 0 = prefix, 1 = substring, 2 = edit distance; kind 3 = no match.
std::tuple<int, std::size_t> match_code(const std::string& query, std::string_view candidate) {
    std::string cand = lowered(candidate);
    std::size_t dist = grammar::edit_distance(query, cand, grammar::SwapCost::OneEdit);
    if (query.size() >= 2 && cand.starts_with(query)) return {0, dist};
    if (query.size() >= 3 && cand.find(query) != std::string::npos) return {1, dist};
    std::size_t limit = std::max<std::size_t>(2, query.size() / 3);
    if (dist <= limit) return {2, dist};
    return {3, dist};
}

}  // namespace

std::span<const RuleInfo> all_rules() { return registry_table(); }

std::string rule_page_path(const RuleInfo& rule) { return "docs/rules/" + std::string(rule.code) + ".md"; }

const RuleInfo* find_rule(std::string_view code_or_name) {
    for (const RuleInfo& rule : registry_table())
        if (iequals(rule.code, code_or_name) || rule.name == code_or_name) return &rule;
    return nullptr;
}

std::vector<std::string_view> similar_rules(std::string_view query, std::size_t max) {
    struct Hit {
        int kind;
        std::size_t distance;
        std::string_view code;
        std::string_view text;
    };
    const std::string q = lowered(query);
    std::vector<Hit> hits;
    if (q.empty() || max == 0) return {};
    for (const RuleInfo& rule : registry_table()) {
        auto [code_kind, code_dist] = match_code(q, rule.code);
        auto [name_kind, name_dist] = match_code(q, rule.name);
        bool by_name = std::tie(name_kind, name_dist) < std::tie(code_kind, code_dist);
        int kind = by_name ? name_kind : code_kind;
        if (kind == 3) continue;
        hits.push_back({kind, by_name ? name_dist : code_dist, rule.code, by_name ? rule.name : rule.code});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
        return std::tie(a.kind, a.distance, a.code) < std::tie(b.kind, b.distance, b.code);
    });
    std::vector<std::string_view> out;
    for (const Hit& hit : hits) {
        if (out.size() == max) break;
        out.push_back(hit.text);
    }
    return out;
}

}  // namespace sphdeck::lint
