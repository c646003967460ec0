// All schema tables in one list, and keyword lookup: names, aliases, options, "did you mean".
#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/keywords/keyword_names.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords {

namespace {

struct Registry {
    std::vector<KeywordSchema> schemas;
    // Canonical names and aliases (upper case, with '*'), sorted for binary search.
    std::vector<std::pair<std::string_view, const KeywordSchema*>> names;
};

Registry build_index() {
    Registry r;
    for (auto family :
         {tables::deck_keywords, tables::control_keywords, tables::parameter_include_keywords, tables::part_keywords,
          tables::section_keywords, tables::element_node_keywords, tables::material_keywords, tables::eos_keywords,
          tables::boundary_keywords, tables::define_keywords, tables::set_keywords, tables::load_initial_keywords}) {
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
    static const Registry r = build_index();
    return r;
}

const KeywordSchema* lookup_exact(std::string_view upper_name) {
    const auto& names = registry().names;
    auto it = std::lower_bound(names.begin(), names.end(), upper_name,
                               [](const auto& entry, std::string_view n) { return entry.first < n; });
    if (it != names.end() && it->first == upper_name) return it->second;
    return nullptr;
}

bool is_name_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// The keyword name proper: surrounding blanks, anything after the first blank (arguments, a
// separated format suffix) and a glued format suffix ('+', '-', '%') removed.
std::string_view name_part(std::string_view s) {
    while (!s.empty() && is_name_blank(s.front())) s.remove_prefix(1);
    std::size_t end = 0;
    while (end < s.size() && !is_name_blank(s[end])) ++end;
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
    // Another spelling LS-DYNA reads as a laid-out keyword (a legacy name, _ID before other options).
    for (const std::string& other : respellings(key)) {
        if (auto same = find_hand_written(other, std::string_view(other).substr(1));
            same && same->unknown_options.empty())
            return same;
        if (auto generated = generated::find_generated(other)) return generated;
    }
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
