// Decodes a generated layout string into a KeywordSchema for the options a deck writes, once per
// spelling (cached): the tables are looked up once per keyword block, never per line.
#include <algorithm>
#include <charconv>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "grammar/keywords/generated_layouts.hpp"

namespace sphdeck::keywords::generated {

namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    while (true) {
        const std::size_t at = s.find(sep);
        out.push_back(s.substr(0, at));
        if (at == std::string_view::npos) return out;
        s.remove_prefix(at + 1);
    }
}

double number(std::string_view s) {
    double v = 0.0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return v;
}

std::uint16_t small(std::string_view s) {
    unsigned v = 0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return static_cast<std::uint16_t>(std::min(v, 60000u));
}

FieldSpec field_of(std::string_view text) {
    const auto parts = split(text, ':');
    FieldSpec f;
    f.name = parts[0];
    const char t = parts.size() > 1 && !parts[1].empty() ? parts[1][0] : 'A';
    // pydyna types some fields int that the manual types F (*SECTION_SHELL PROPT, *MAT_THERMAL_ISOTROPIC
    // TGRLC, contact SBOPT) and its layouts differ between versions (*FREQUENCY_DOMAIN_FRF): its integer
    // fields are checked as numbers only, so no DK002/DK004 comes from a generated layout.
    f.type = t == 'I' || t == 'F' ? FieldType::Real : t == 'U' ? FieldType::Unused : FieldType::Text;
    if (parts.size() > 3) {
        f.column = static_cast<std::uint16_t>(small(parts[2]) + 1);
        f.width = small(parts[3]);
    }
    if (parts.size() > 4 && !parts[4].empty()) f.default_value = number(parts[4]);
    // pydyna links a few real fields to ids (*DEFINE_SPH_DE_COUPLING PFACT to a section,
    // *EM_CONTROL_SOLUTION ANG to a node): only its integer fields are taken as ids.
    if (parts.size() > 5 && t == 'I') f.refers_to = parts[5];
    f.pydyna_integer = t == 'I';
    if (t == 'I')
        f.doc = f.refers_to.empty() ? "integer in pydyna's layout, checked as a number"
                                    : "integer in pydyna's layout, checked as a number; an id";
    return f;
}

// One test, "FIELD OP V1;V2..." (the generator's docstring).
std::optional<CardCondition> test_of(std::string_view text) {
    const auto parts = split(text, ' ');
    if (parts.size() != 3 || parts[0].empty()) return std::nullopt;
    CardCondition c;
    c.field = parts[0];
    const std::string_view op = parts[1];
    if (op == "in") {
        for (std::string_view v : split(parts[2], ';')) c.any_of.push_back(number(v));
        return c;
    }
    c.value = number(parts[2]);
    c.compare = op == "=="   ? Compare::Equal
                : op == "!=" ? Compare::NotEqual
                : op == "<"  ? Compare::Less
                : op == "<=" ? Compare::LessEqual
                : op == ">"  ? Compare::Greater
                             : Compare::GreaterEqual;
    return c;
}

// Tests joined by " and " (binding first) and " or ": the first clause's first test carries the rest.
std::vector<std::string_view> split_words(std::string_view s, std::string_view sep) {
    std::vector<std::string_view> out;
    for (std::size_t at; (at = s.find(sep)) != std::string_view::npos; s.remove_prefix(at + sep.size()))
        out.push_back(s.substr(0, at));
    out.push_back(s);
    return out;
}

std::optional<CardCondition> clause_of(std::string_view text) {
    std::optional<CardCondition> first;
    for (std::string_view t : split_words(text, " and ")) {
        auto test = test_of(t);
        if (!test) return std::nullopt;
        if (!first)
            first = std::move(test);
        else
            first->all_of.push_back(std::move(*test));
    }
    return first;
}

std::optional<CardCondition> condition_of(std::string_view text) {
    if (text.empty()) return std::nullopt;
    std::optional<CardCondition> first;
    for (std::string_view clause : split_words(text, " or ")) {
        auto c = clause_of(clause);
        if (!c) return std::nullopt;
        if (!first)
            first = std::move(c);
        else
            first->or_else.push_back(std::move(*c));
    }
    return first;
}

bool written(const std::vector<std::string_view>& options, std::string_view o) {
    return std::find(options.begin(), options.end(), o) != options.end();
}

// The schema of `entry` with the options `on` (the entry's own spellings).
std::unique_ptr<KeywordSchema> build(const LayoutEntry& entry, const std::vector<std::string_view>& on) {
    auto k = std::make_unique<KeywordSchema>();
    k->name = entry.name;
    k->generated = true;
    k->doc = "layout generated from pydyna's keyword classes (not checked by hand)";
    const auto lines = split(entry.body, '\n');
    for (std::string_view o : split(lines[0], ' '))
        if (!o.empty()) k->options.push_back({.suffix = o});
    if (written(on, "TITLE") && !k->option("TITLE")) {
        // A _TITLE pydyna does not list (see option_named): the manual's title line, A80.
        k->options.push_back({.suffix = "TITLE"});
        k->cards.push_back(
            {.name = "Title", .fields = {{.name = "TITLE", .column = 1, .width = 80, .type = FieldType::Text}}});
    }
    std::size_t group_start = 0;
    bool group = false;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto parts = split(lines[i], '|');
        if (parts.size() != 4 || parts[0].empty()) continue;
        const std::string_view option = parts[1];
        if (option != "-" && option != "*" && !written(on, option)) continue;
        CardSpec card;
        card.name = "Card";
        if (parts[0] == "x") {
            card.unknown_layout = true;
            card.repeat = CardRepeat::Optional;
            k->cards.push_back(std::move(card));
            break;  // nothing past a card whose layout is not known
        }
        card.repeat = parts[0] == "r" ? CardRepeat::Repeated : CardRepeat::Optional;
        if (parts[0][0] == 'g') {
            group = true;
            group_start = k->cards.size();
        }
        card.present_if = condition_of(parts[2]);
        if (!parts[3].empty())
            for (std::string_view f : split(parts[3], ',')) card.fields.push_back(field_of(f));
        k->cards.push_back(std::move(card));
    }
    if (group) k->repeat_group = static_cast<std::uint8_t>(std::min<std::size_t>(k->cards.size() - group_start, 255));
    return k;
}

const LayoutEntry* entry_named(std::string_view name) {
    const auto all = layouts();
    auto it = std::lower_bound(all.begin(), all.end(), name,
                               [](const LayoutEntry& e, std::string_view n) { return e.name < n; });
    return it != all.end() && it->name == name ? &*it : nullptr;
}

// The option of `entry` that `token` names; "TITLE" stands for ID when the keyword has no TITLE
// option (pydyna's rule, kept in its code rather than in the data).
std::string_view option_named(std::string_view keyword, const std::vector<std::string_view>& options,
                              std::string_view token) {
    for (std::string_view o : options)
        if (o == token) return o;
    if (token == "TITLE" && written(options, "ID")) return "ID";
    // Every *SECTION_ keyword takes _TITLE in the manual (an A80 title card before card 1), but pydyna
    // lists it for some only (*SECTION_SHELL yes, *SECTION_SOLID and *SECTION_BEAM no).
    if (token == "TITLE" && keyword.starts_with("*SECTION_")) return "TITLE";
    return {};
}

// *CASE_BEGIN_n and *CASE_END_n: the name ends with the case id n (manual, *CASE), no option.
bool case_id_token(std::string_view keyword, std::string_view token, bool last) {
    return last && (keyword == "*CASE_BEGIN" || keyword == "*CASE_END") && !token.empty() &&
           std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::optional<KeywordMatch> find_generated(std::string_view key) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<KeywordSchema>, std::less<>> cache;
    for (std::size_t base_end = key.size(); base_end >= 2;) {
        if (const LayoutEntry* entry = entry_named(key.substr(0, base_end))) {
            const auto options = split(split(entry->body, '\n')[0], ' ');
            std::vector<std::string_view> on;
            bool all_known = true;
            for (std::size_t pos = base_end; pos < key.size() && all_known;) {
                std::size_t end = key.find('_', pos + 1);
                if (end == std::string_view::npos) end = key.size();
                const std::string_view token = key.substr(pos + 1, end - pos - 1);
                const std::string_view o = option_named(entry->name, options, token);
                if (case_id_token(entry->name, token, end == key.size())) {
                } else if (o.empty() || written(on, o))
                    all_known = end == pos + 1;  // "__" is no option
                else
                    on.push_back(o);
                pos = end;
            }
            if (all_known) {
                std::vector<std::string_view> sorted = on;
                std::sort(sorted.begin(), sorted.end());
                std::string cache_key(entry->name);
                for (std::string_view o : sorted) (cache_key += '_') += o;
                const std::lock_guard lock(mutex);
                auto& schema = cache[cache_key];
                if (!schema) schema = build(*entry, on);
                KeywordMatch match;
                match.schema = schema.get();
                for (std::string_view o : on) match.options.push_back(schema->option(o));
                return match;
            }
        }
        const std::size_t us = key.substr(0, base_end).rfind('_');
        if (us == std::string_view::npos || us < 2) break;
        base_end = us;
    }
    return std::nullopt;
}

}  // namespace sphdeck::keywords::generated
