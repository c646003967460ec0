// All schema tables in one list, and keyword lookup: names, aliases, options, "did you mean".
#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords {

namespace {

struct Registry {
    std::vector<KeywordSchema> schemas;
    // Canonical names and aliases (upper case, with '*'), sorted for binary search.
    std::vector<std::pair<std::string_view, const KeywordSchema*>> names;
};

Registry build() {
    Registry r;
    for (auto family : {tables::deck_keywords, tables::control_keywords, tables::parameter_include_keywords,
                        tables::part_keywords, tables::section_keywords, tables::element_node_keywords,
                        tables::material_keywords, tables::eos_keywords, tables::boundary_keywords,
                        tables::define_keywords, tables::set_keywords, tables::load_initial_keywords}) {
        for (KeywordSchema& k : family()) r.schemas.push_back(std::move(k));
    }
    for (const KeywordSchema& k : r.schemas) {
        r.names.emplace_back(k.name, &k);
        for (std::string_view a : k.aliases) r.names.emplace_back(a, &k);
    }
    std::sort(r.names.begin(), r.names.end());
    return r;
}

const Registry& registry() {
    static const Registry r = build();
    return r;
}

const KeywordSchema* lookup_exact(std::string_view upper_name) {
    const auto& names = registry().names;
    auto it = std::lower_bound(names.begin(), names.end(), upper_name,
                               [](const auto& entry, std::string_view n) { return entry.first < n; });
    if (it != names.end() && it->first == upper_name) return it->second;
    return nullptr;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// The keyword name proper: surrounding blanks, anything after the first blank (arguments, a
// separated format suffix) and a glued format suffix ('+', '-', '%') removed.
std::string_view name_part(std::string_view s) {
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    std::size_t end = 0;
    while (end < s.size() && !is_blank(s[end])) ++end;
    s = s.substr(0, end);
    if (!s.empty() && (s.back() == '+' || s.back() == '-' || s.back() == '%')) s.remove_suffix(1);
    return s;
}

// "*" + upper-cased name without its '*'. `core` receives the name without '*' as a view into
// the input, so that key[i + 1] corresponds to core[i].
std::string normalized_key(std::string_view full_name, std::string_view* core) {
    std::string_view s = name_part(full_name);
    if (!s.empty() && s.front() == '*') s.remove_prefix(1);
    if (core) *core = s;
    std::string key(1, '*');
    key.reserve(s.size() + 1);
    for (char c : s) key.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    return key;
}

// Edit distance with adjacent transpositions (optimal string alignment).
std::size_t edit_distance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
    for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                cur[j] = std::min(cur[j], prev2[j - 2] + 1);
        }
        std::swap(prev2, prev);
        std::swap(prev, cur);
    }
    return prev[m];
}

// The first `tokens` '_'-separated tokens of `s`.
std::string_view first_tokens(std::string_view s, std::size_t tokens) {
    std::size_t pos = 0;
    for (std::size_t t = 0; t < tokens; ++t) {
        pos = s.find('_', pos == 0 ? 0 : pos + 1);
        if (pos == std::string_view::npos) return s;
    }
    return s.substr(0, pos);
}

std::optional<KeywordMatch> find_hand_written(const std::string& key, std::string_view core);

}  // namespace

std::span<const KeywordSchema> all_keywords() { return registry().schemas; }

std::optional<KeywordMatch> find_keyword(std::string_view full_name) {
    std::string_view core;
    const std::string key = normalized_key(full_name, &core);
    if (key.size() < 2) return std::nullopt;
    // The hand-written tables win; the generated layouts cover every other LS-DYNA keyword.
    std::optional<KeywordMatch> hand = find_hand_written(key, core);
    if (hand && hand->unknown_options.empty()) return hand;
    if (auto generated = generated::find_generated(key)) return generated;
    return hand;
}

namespace {

std::optional<KeywordMatch> find_hand_written(const std::string& key, std::string_view core) {

    // Longest base name first: the whole name, then without its last token, and so on.
    std::size_t base_end = key.size();
    const KeywordSchema* schema = nullptr;
    while (true) {
        schema = lookup_exact(std::string_view(key).substr(0, base_end));
        if (schema) break;
        const std::size_t us = std::string_view(key).substr(0, base_end).rfind('_');
        if (us == std::string_view::npos || us < 2) return std::nullopt;
        base_end = us;
    }

    KeywordMatch match;
    match.schema = schema;
    // Option tokens after the base name, as [begin, end) offsets into key.
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    for (std::size_t pos = base_end; pos < key.size();) {
        const std::size_t begin = pos + 1;  // skip '_'
        std::size_t end = key.find('_', begin);
        if (end == std::string::npos) end = key.size();
        if (end > begin) tokens.emplace_back(begin, end);
        pos = end;
    }
    for (std::size_t i = 0; i < tokens.size();) {
        // Longest run of tokens that names an option (options may contain '_').
        std::size_t taken = 0;
        const OptionSpec* found = nullptr;
        for (std::size_t j = tokens.size(); j > i && !found; --j) {
            const auto text = std::string_view(key).substr(tokens[i].first, tokens[j - 1].second - tokens[i].first);
            found = schema->option(text);
            if (found) taken = j - i;
        }
        const bool duplicate =
            found && std::find(match.options.begin(), match.options.end(), found) != match.options.end();
        if (found && !duplicate) {
            match.options.push_back(found);
            i += taken;
        } else {
            const auto [b, e] = tokens[i];
            match.unknown_options.push_back(core.substr(b - 1, e - b));
            i += 1;
        }
    }
    return match;
}

}  // namespace

std::vector<std::string_view> similar_keywords(std::string_view name, std::size_t max) {
    const std::string key = normalized_key(name, nullptr);
    struct Candidate {
        std::size_t distance;
        std::string_view name;
        const KeywordSchema* schema;
    };
    std::vector<Candidate> candidates;
    for (const auto& [known, schema] : registry().names) {
        const std::size_t tokens = static_cast<std::size_t>(std::count(known.begin(), known.end(), '_')) + 1;
        const std::size_t limit = std::max<std::size_t>(2, known.size() / 4);
        // Compare with the whole name and with as many leading tokens as the known name has,
        // so that options (*SECTON_SPH_TITLE) do not hide a close base name. Names whose lengths
        // differ by more than the limit are farther than it (each edit changes the length by at
        // most one): skipping them spares most of the distances, for every unknown keyword.
        const std::string_view head = first_tokens(key, tokens);
        std::size_t d = limit + 1;
        for (const std::string_view written : {head, std::string_view(key)}) {
            const std::size_t length_gap = written.size() > known.size() ? written.size() - known.size()
                                                                           : known.size() - written.size();
            if (length_gap <= limit) d = std::min(d, edit_distance(written, known));
            if (head.size() == key.size()) break;  // the same text: one distance is enough
        }
        if (d <= limit) candidates.push_back({d, known, schema});
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.distance != b.distance ? a.distance < b.distance : a.name < b.name;
    });
    std::vector<std::string_view> out;
    std::vector<const KeywordSchema*> seen;
    for (const Candidate& c : candidates) {
        if (out.size() >= max) break;
        if (std::find(seen.begin(), seen.end(), c.schema) != seen.end()) continue;
        seen.push_back(c.schema);
        out.push_back(c.name);
    }
    return out;
}

std::vector<const CardSpec*> cards_for(const KeywordMatch& match) {
    std::vector<const CardSpec*> cards;
    if (!match.schema) return cards;
    std::size_t replaced = 0;
    for (const OptionSpec* o : match.options) {
        for (const CardSpec& c : o->cards_before) cards.push_back(&c);
        replaced += o->replaces_last;
    }
    const auto& base = match.schema->cards;
    const std::size_t keep = base.size() > replaced ? base.size() - replaced : 0;
    for (std::size_t i = 0; i < keep; ++i) cards.push_back(&base[i]);
    for (const OptionSpec* o : match.options)
        for (const CardSpec& c : o->cards_after) cards.push_back(&c);
    return cards;
}

std::size_t repeat_group_size(const KeywordMatch& match) {
    if (!match.schema || match.schema->repeat_group == 0) return 0;
    std::size_t size = match.schema->repeat_group;
    for (const OptionSpec* o : match.options) {
        size += o->cards_after.size();
        size -= std::min<std::size_t>(size, o->replaces_last);
    }
    return size;
}

}  // namespace sphdeck::keywords
