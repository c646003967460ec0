// "Did you mean" for keyword names: every name the tables know (hand-written schemas and their
// aliases, pydyna's generated layouts, the keywords known without a layout), each also with each of
// its options, compared with what was written by typing distance (grammar/similar_names.hpp).
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/similar_names.hpp"

namespace sphdeck::keywords {

namespace {

struct KnownName {
    std::string name;       // upper case with '*', options joined with '_'
    std::string_view base;  // the keyword it belongs to (its canonical name)
    int tier;               // 0 hand-written, 1 generated, 2 known without layout: ties go to the first
    std::size_t tokens;     // '_'-separated tokens in `name`
    std::uint64_t letters;  // letters_in(name)
};

// Which of 64 letter buckets (grammar::typing_distance's: the character's low 6 bits) occur in `s`. A
// bucket in one name and not the other is at least one letter to insert, delete or substitute, so
// popcount(a ^ b) never exceeds the letters' lower bound of the distance: a test of one instruction that
// rejects most of the names tried before the distance is computed.
std::uint64_t letters_in(std::string_view s) {
    std::uint64_t mask = 0;
    for (char c : s) mask |= std::uint64_t{1} << (static_cast<unsigned char>(c) & 63);
    return mask;
}

std::size_t token_count(std::string_view s) {
    return static_cast<std::size_t>(std::count(s.begin(), s.end(), '_')) + 1;
}

void add_suggestion(std::vector<KnownName>& out, std::string name, std::string_view base, int tier) {
    const std::size_t tokens = token_count(name);
    const std::uint64_t letters = letters_in(name);
    out.push_back({std::move(name), base, tier, tokens, letters});
}

std::vector<KnownName> build_names() {
    std::vector<KnownName> out;
    for (const KeywordSchema& k : all_keywords()) {
        for (std::string_view spelling : [&] {
                 std::vector<std::string_view> s{k.name};
                 s.insert(s.end(), k.aliases.begin(), k.aliases.end());
                 return s;
             }()) {
            add_suggestion(out, std::string(spelling), k.name, 0);
            for (const OptionSpec& o : k.options)
                add_suggestion(out, std::string(spelling) + "_" + std::string(o.suffix), k.name, 0);
        }
    }
    for (const generated::LayoutEntry& e : generated::layouts()) {
        add_suggestion(out, std::string(e.name), e.name, 1);
        std::string_view options = e.body.substr(0, e.body.find('\n'));
        while (!options.empty()) {
            const std::size_t end = std::min(options.find(' '), options.size());
            if (end > 0)
                add_suggestion(out, std::string(e.name) + "_" + std::string(options.substr(0, end)), e.name, 1);
            options.remove_prefix(std::min(end + 1, options.size()));
        }
    }
    for (std::string_view n : known_without_layout()) add_suggestion(out, std::string(n), n, 2);
    return out;
}

const std::vector<KnownName>& known_names() {
    static const std::vector<KnownName> names = build_names();
    return names;
}

// The known names by token count and length, each list in the order of known_names(): a name written
// L long is only weighed against names whose length can be within their close_enough of L (each
// insertion or deletion costs a whole edit), a few hundred of the tens of thousands.
struct NameIndex {
    // by_length[n]: every known name n long; by_tokens[t][n]: those of them with t tokens.
    std::vector<std::vector<std::size_t>> by_length;
    std::vector<std::vector<std::vector<std::size_t>>> by_tokens;
};

const NameIndex& name_index() {
    static const NameIndex index = [] {
        NameIndex x;
        const std::vector<KnownName>& names = known_names();
        for (std::size_t i = 0; i < names.size(); ++i) {
            const std::size_t n = names[i].name.size(), t = names[i].tokens;
            if (x.by_length.size() <= n) x.by_length.resize(n + 1);
            if (x.by_tokens.size() <= t) x.by_tokens.resize(t + 1);
            if (x.by_tokens[t].size() <= n) x.by_tokens[t].resize(n + 1);
            x.by_length[n].push_back(i);
            x.by_tokens[t][n].push_back(i);
        }
        return x;
    }();
    return index;
}

// Whether a known name `known_length` long may lie within its close_enough of a name `written_length` long.
bool length_within_reach(std::size_t written_length, std::size_t known_length) {
    const std::size_t gap =
        written_length > known_length ? written_length - known_length : known_length - written_length;
    return 2 * gap <= grammar::close_enough_for_length(known_length);
}

// "*" + upper-cased name proper: blanks, arguments and a glued format suffix removed.
std::string key_of(std::string_view written) {
    while (!written.empty() && (written.front() == ' ' || written.front() == '\t')) written.remove_prefix(1);
    written = written.substr(0, std::min(written.find_first_of(" \t\r\n"), written.size()));
    if (!written.empty() && (written.back() == '+' || written.back() == '-' || written.back() == '%'))
        written.remove_suffix(1);
    if (!written.empty() && written.front() == '*') written.remove_prefix(1);
    std::string key(1, '*');
    for (char c : written) key.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    return key;
}

// The first `tokens` '_'-separated tokens of `s`.
std::string_view head_of(std::string_view s, std::size_t tokens) {
    std::size_t pos = 0;
    for (std::size_t t = 0; t < tokens; ++t) {
        pos = s.find('_', t == 0 ? 0 : pos + 1);
        if (pos == std::string_view::npos) return s;
    }
    return s.substr(0, pos);
}

struct Candidate {
    std::size_t distance;
    int tier;
    std::string text;  // the suggestion: a known name, or a known base name with the written options
    const KnownName* known;
};

bool before(const Candidate& a, const Candidate& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.tier != b.tier) return a.tier < b.tier;
    if (a.text.size() != b.text.size()) return a.text.size() < b.text.size();
    if (a.text != b.text) return a.text < b.text;
    return a.known->name < b.known->name;  // the same suggestion from a base name and from base + option
}

// No token replaced wholesale: where `written` and `known` have the same '_'-separated tokens, each token
// differs from its counterpart by at most half its letters (a swap, a dropped or doubled letter pass; *INITIAL_SPH
// is not *INITIAL_CPG, two of SPH's three letters replaced). Names of other token counts are left to the
// distance alone (a dropped '_').
bool no_token_replaced(std::string_view written, std::string_view known) {
    if (std::count(written.begin(), written.end(), '_') != std::count(known.begin(), known.end(), '_')) return true;
    while (!written.empty()) {
        const std::size_t a = std::min(written.find('_'), written.size()), b = std::min(known.find('_'), known.size());
        const std::string_view x = written.substr(0, a), y = known.substr(0, b);
        if (x != y && grammar::typing_distance(x, y, false, x.size() + 1) > x.size()) return false;  // half edits
        written.remove_prefix(std::min(a + 1, written.size()));
        known.remove_prefix(std::min(b + 1, known.size()));
    }
    return true;
}

// Every known name close to `key`: compared as a whole, and with as many leading tokens of `key` as
// it has, the rest of `key` (the author's options) kept in the suggestion (*SECTON_SPH_TITLE).
std::vector<Candidate> candidates_for(const std::string& key) {
    std::vector<Candidate> out;
    const auto distance_within = [](std::string_view written, std::uint64_t written_letters,
                                    const KnownName& known) -> std::optional<std::size_t> {
        const std::size_t limit = grammar::close_enough(known.name);
        const std::size_t gap = written.size() > known.name.size() ? written.size() - known.name.size()
                                                                   : known.name.size() - written.size();
        if (2 * gap > limit) return std::nullopt;  // each insertion or deletion costs 2
        if (static_cast<std::size_t>(std::popcount(written_letters ^ known.letters)) > limit) return std::nullopt;
        const std::size_t d = grammar::typing_distance(written, known.name, false, limit);
        if (d > limit || !no_token_replaced(written, known.name)) return std::nullopt;
        return d;
    };
    // Each name is weighed as a whole, and for its token count against as many tokens of `key`, in the
    // order of known_names() (whole first): the list sorted is the one a walk over every name would give.
    const std::vector<KnownName>& names = known_names();
    const NameIndex& index = name_index();
    std::vector<std::pair<std::size_t, Candidate>> found;  // (2 * name index + 1 for a head, candidate)
    const std::uint64_t key_letters = letters_in(key);
    for (std::size_t n = 0; n < index.by_length.size(); ++n) {
        if (!length_within_reach(key.size(), n)) continue;
        for (std::size_t i : index.by_length[n])
            if (auto d = distance_within(key, key_letters, names[i]); d && *d > 0)
                found.push_back({2 * i, {*d, names[i].tier, names[i].name, &names[i]}});
    }
    for (std::size_t t = 0; t < index.by_tokens.size(); ++t) {
        const std::string_view head = head_of(key, t);
        if (head.size() == key.size()) continue;
        const std::uint64_t head_letters = letters_in(head);
        for (std::size_t n = 0; n < index.by_tokens[t].size(); ++n) {
            if (!length_within_reach(head.size(), n)) continue;
            for (std::size_t i : index.by_tokens[t][n])
                if (auto d = distance_within(head, head_letters, names[i]); d && *d > 0)
                    found.push_back(
                        {2 * i + 1, {*d, names[i].tier, names[i].name + key.substr(head.size()), &names[i]}});
        }
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [order, c] : found) out.push_back(std::move(c));
    std::sort(out.begin(), out.end(), before);
    return out;
}

// A name the tables know as a whole: every option token is an option of its keyword.
bool known_as_written(const std::string& name) {
    if (is_known_without_layout(name)) return true;
    auto match = find_keyword(name);
    return match && match->unknown_options.empty();
}

}  // namespace

std::vector<std::string_view> similar_keywords(std::string_view name, std::size_t max) {
    std::vector<std::string_view> out;
    std::vector<std::string_view> bases;
    const std::string key = key_of(name);
    const std::vector<Candidate> candidates = candidates_for(key);
    for (const Candidate& c : candidates) {
        if (out.size() >= max) break;
        // Names farther than the best by more than a swap are noise beside it.
        if (c.distance > candidates.front().distance + 1) break;
        // One name per keyword, the stored spelling (the views outlive the call).
        if (std::find(bases.begin(), bases.end(), c.known->base) != bases.end()) continue;
        bases.push_back(c.known->base);
        out.push_back(c.known->name);
    }
    return out;
}

std::optional<std::string> suggest_keyword(std::string_view name) {
    const std::string key = key_of(name);
    if (key.size() < 2) return std::nullopt;
    // The answers of this thread, by key: a deck checked again (the editor at each keystroke, a fuzzer
    // mutating one byte) asks again for the same unknown names, and each answer weighs the name
    // against every known one. Bounded: emptied when full.
    constexpr std::size_t max_remembered = 4096;
    thread_local std::unordered_map<std::string, std::optional<std::string>> remembered;
    if (const auto it = remembered.find(key); it != remembered.end()) return it->second;
    std::optional<std::string> answer;
    std::size_t checked = 0;
    for (const Candidate& c : candidates_for(key)) {
        if (++checked > 50) break;  // the closest few decide; the rest are farther anyway
        if (known_as_written(c.text)) {
            answer = c.text;
            break;
        }
    }
    if (remembered.size() >= max_remembered) remembered.clear();
    remembered.emplace(key, answer);
    return answer;
}

std::string keyword_replacement(std::string_view written_name, std::string_view suggestion) {
    // The author's '*' and case: all lower case stays lower case, anything else is written upper case.
    std::string_view core = written_name;
    if (!core.empty() && core.front() == '*') core.remove_prefix(1);
    const bool lower =
        std::none_of(core.begin(), core.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); }) &&
        std::any_of(core.begin(), core.end(), [](char c) { return std::islower(static_cast<unsigned char>(c)); });
    std::string out(suggestion);
    if (lower)
        for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace sphdeck::keywords
