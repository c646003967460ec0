#include "engine/deck_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

#include "grammar/keywords/schema.hpp"
#include "grammar/read_deck.hpp"
#include "model/model_json.hpp"
#include "model/radioss_json.hpp"

namespace sphdeck::engine {
namespace {

using json = nlohmann::ordered_json;

json values_of(const CheckResult& r) {
    if (grammar::format_of(r.deck) == grammar::DeckFormat::Radioss)
        return model::radioss_to_json(model::read_radioss_records(r.deck), r.model, r.deck, false);
    return model::to_json(r.model, r.deck, {false});
}

// A member that is a number, or 0 (a dump writes null for a position a default has not got).
std::uint32_t number_or_zero(const json& object, const char* key) {
    const auto it = object.find(key);
    return it != object.end() && it->is_number_unsigned() ? it->get<std::uint32_t>() : 0;
}

std::string string_or_empty(const json& object, const char* key) {
    const auto it = object.find(key);
    return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// "SECID 1" from the first field that is not a title, when it names an id and has a value.
std::string id_of(const json& keyword) {
    const auto fields = keyword.find("fields");
    if (fields == keyword.end() || !fields->is_object()) return {};
    for (const auto& [name, field] : fields->items()) {
        if (keywords::is_title_field(name)) continue;
        if (!field.is_object() || !field.contains("value")) return {};
        const json& value = field["value"];
        const bool names_id = name.size() >= 2 && (name.ends_with("ID") || name.ends_with("id") || name == "ID");
        if (!names_id || value.is_null() || (value.is_number() && value.get<double>() == 0.0)) return {};
        return name + " " + (value.is_string() ? value.get<std::string>() : value.dump());
    }
    return {};
}

std::string name_of(const json& keyword) { return string_or_empty(keyword, "name"); }

DiffLocation diff_at(const json& keyword) {
    DiffLocation out;
    out.file = string_or_empty(keyword, "file");
    out.line = number_or_zero(keyword, "line");
    return out;
}

DiffLocation at_field(const json& keyword, const json& field) {
    DiffLocation out = diff_at(keyword);
    out.line = number_or_zero(field, "line");
    out.column = number_or_zero(field, "column");
    return out;
}

bool same_value(const json& a, const json& b, double rtol) {
    if (a.is_number() && b.is_number()) {
        const double x = a.get<double>(), y = b.get<double>();
        return x == y || std::abs(x - y) <= rtol * std::max(std::abs(x), std::abs(y));
    }
    return a == b;
}

// The fields of one card (or of the keyword's single cards) compared by name.
void compare_fields(const json& before_kw, const json& after_kw, const json& before, const json& after,
                    const std::string& prefix, double rtol, std::vector<FieldChange>& out) {
    static const json none;
    const auto value_in = [](const json& fields, const std::string& name) -> const json& {
        const auto it = fields.find(name);
        return it == fields.end() ? none : *it;
    };
    std::vector<std::string> names;
    for (const auto& [name, field] : after.items()) names.push_back(name);
    for (const auto& [name, field] : before.items())
        if (!after.contains(name)) names.push_back(name);
    for (const std::string& name : names) {
        const json& b = value_in(before, name);
        const json& a = value_in(after, name);
        const json& bv = b.is_object() ? b["value"] : none;
        const json& av = a.is_object() ? a["value"] : none;
        if (same_value(bv, av, rtol)) continue;
        FieldChange change;
        change.field = prefix + name;
        change.before = bv;
        change.after = av;
        if (b.is_object()) change.before_at = at_field(before_kw, b);
        if (a.is_object()) change.after_at = at_field(after_kw, a);
        out.push_back(std::move(change));
    }
}

std::vector<FieldChange> compare_keyword(const json& before, const json& after, double rtol) {
    std::vector<FieldChange> out;
    static const json empty = json::object();
    const bool cards = before.contains("cards") || after.contains("cards");
    if (!cards) {
        compare_fields(before, after, before.value("fields", empty), after.value("fields", empty), "", rtol, out);
        return out;
    }
    const json& bc = before.contains("cards") ? before["cards"] : json::array({before.value("fields", empty)});
    const json& ac = after.contains("cards") ? after["cards"] : json::array({after.value("fields", empty)});
    const std::size_t n = std::max(bc.size(), ac.size());
    for (std::size_t i = 0; i < n; ++i) {
        const json& b = i < bc.size() ? bc[i] : empty;
        const json& a = i < ac.size() ? ac[i] : empty;
        compare_fields(before, after, b, a, n > 1 ? "card " + std::to_string(i + 1) + " " : "", rtol, out);
    }
    return out;
}

// The blocks of a deck by file (as the dump names it) and keyword line, to reach the text of the lines
// no field was decoded from (a card the layouts do not describe, an OpenRadioss card past the first).
using BlockIndex = std::map<std::pair<std::string, std::uint32_t>, const grammar::Block*>;

BlockIndex index_blocks(const grammar::RawDeck& deck) {
    BlockIndex index;
    for (const grammar::Block& b : deck.blocks)
        if (b.span.valid()) index.emplace(std::make_pair(deck.sources.file(b.span.file).display_name, b.span.line), &b);
    return index;
}

void decoded_lines(const json& fields, std::set<std::uint32_t>& out) {
    for (const auto& [name, field] : fields.items())
        if (field.is_object() && number_or_zero(field, "line") > 0) out.insert(number_or_zero(field, "line"));
}

struct RawLine {
    std::uint32_t line = 0;
    std::string text;                 // trimmed
    std::vector<std::string> tokens;  // blank-separated: what is compared, formatting aside
};

// The data lines of a keyword's block that hold no decoded field, comments left out.
std::vector<RawLine> undecoded_lines(const json& keyword, const grammar::RawDeck& deck, const BlockIndex& index) {
    const auto found = index.find({string_or_empty(keyword, "file"), number_or_zero(keyword, "line")});
    if (found == index.end()) return {};
    std::set<std::uint32_t> decoded;
    if (keyword.contains("fields")) decoded_lines(keyword["fields"], decoded);
    if (keyword.contains("cards"))
        for (const json& card : keyword["cards"]) decoded_lines(card, decoded);
    std::vector<RawLine> out;
    for (grammar::CardLinePtr l = deck.begin_lines(*found->second); l != deck.end_lines(*found->second); ++l) {
        if (decoded.count(l->line)) continue;
        std::string_view text = deck.text(*l);
        const auto first = text.find_first_not_of(" \t");
        if (first == std::string_view::npos || text[first] == '$' || text[first] == '#') continue;
        RawLine raw{l->line, std::string(text.substr(first)), {}};
        while (!raw.text.empty() && std::isspace(static_cast<unsigned char>(raw.text.back()))) raw.text.pop_back();
        std::istringstream words(raw.text);
        for (std::string word; words >> word;) raw.tokens.push_back(word);
        out.push_back(std::move(raw));
    }
    return out;
}

void compare_undecoded(const json& before_kw, const json& after_kw, const CheckResult& before, const CheckResult& after,
                       const BlockIndex& before_index, const BlockIndex& after_index, std::vector<FieldChange>& out) {
    const auto b = undecoded_lines(before_kw, before.deck, before_index);
    const auto a = undecoded_lines(after_kw, after.deck, after_index);
    for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
        if (i < a.size() && i < b.size() && a[i].tokens == b[i].tokens) continue;
        FieldChange change;
        change.field = "line " + std::to_string(i + 1) + " not decoded";
        if (i < b.size()) {
            change.before = b[i].text;
            change.before_at = diff_at(before_kw);
            change.before_at.line = b[i].line;
        }
        if (i < a.size()) {
            change.after = a[i].text;
            change.after_at = diff_at(after_kw);
            change.after_at.line = a[i].line;
        }
        out.push_back(std::move(change));
    }
}

// Keys that match keywords across the decks: name and id, or name and order among those without one.
std::vector<std::string> keys_of(const json& keywords) {
    std::vector<std::string> keys;
    std::map<std::string, int> seen;
    for (const json& k : keywords) {
        const std::string id = id_of(k);
        const std::string base = name_of(k) + (id.empty() ? "" : " " + id);
        const int occurrence = seen[base]++;
        keys.push_back(base + (occurrence == 0 ? "" : " #" + std::to_string(occurrence + 1)));
    }
    return keys;
}

void note_id(std::vector<long long>& ids, long long id) {
    if (ids.size() < kMostIdsListed) ids.push_back(id);
}

// Where each id occurs, in order: a deck may repeat an id (a duplicate is another rule's finding), and the
// n-th occurrence on one side is matched with the n-th on the other.
class IdOccurrences {
public:
    explicit IdOccurrences(const model::IdColumn& ids) {
        where_.reserve(ids.size());
        for (std::size_t i = 0; i < ids.size(); ++i) where_[ids[i]].push_back(i);
    }
    std::optional<std::size_t> take(long long id) {
        const auto it = where_.find(id);
        if (it == where_.end() || it->second.empty()) return std::nullopt;
        const std::size_t i = it->second.front();
        it->second.erase(it->second.begin());
        return i;
    }

private:
    std::unordered_map<long long, std::vector<std::size_t>> where_;
};

BulkChange diff_nodes(const model::Nodes& before, const model::Nodes& after, double rtol) {
    BulkChange out;
    out.before_count = before.id.size();
    out.after_count = after.id.size();
    double extent = 0.0;  // the larger extent of the meshes: the scale of a coordinate near 0
    for (const model::Nodes* n : {&before, &after})
        for (const auto* c : {&n->x, &n->y, &n->z})
            if (!c->empty()) {
                const auto [lo, hi] = std::minmax_element(c->begin(), c->end());
                extent = std::max(extent, *hi - *lo);
            }
    IdOccurrences index(before.id);
    std::vector<bool> matched(before.id.size(), false);
    std::vector<long long> added, moved;
    for (std::size_t j = 0; j < after.id.size(); ++j) {
        const auto found = index.take(after.id[j]);
        if (!found) {
            added.push_back(after.id[j]);
            continue;
        }
        const std::size_t i = *found;
        matched[i] = true;
        const double dx = after.x[j] - before.x[i], dy = after.y[j] - before.y[i], dz = after.z[j] - before.z[i];
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (d > rtol * extent) {
            moved.push_back(after.id[j]);
            if (d > out.largest_displacement) {
                out.largest_displacement = d;
                out.largest_displacement_id = after.id[j];
            }
        }
    }
    std::vector<long long> removed;
    for (std::size_t i = 0; i < before.id.size(); ++i)
        if (!matched[i]) removed.push_back(before.id[i]);
    for (auto* list : {&added, &moved, &removed}) std::sort(list->begin(), list->end());
    out.added = added.size(), out.removed = removed.size(), out.changed = moved.size();
    for (long long id : added) note_id(out.added_ids, id);
    for (long long id : removed) note_id(out.removed_ids, id);
    for (long long id : moved) note_id(out.changed_ids, id);
    return out;
}

BulkChange diff_particles(const model::Particles& before, const model::Particles& after, double rtol) {
    BulkChange out;
    out.before_count = before.size();
    out.after_count = after.size();
    IdOccurrences index(before.node);
    std::vector<bool> matched(before.size(), false);
    std::vector<long long> added, changed, removed;
    for (std::size_t j = 0; j < after.size(); ++j) {
        const auto found = index.take(after.node[j]);
        if (!found) {
            added.push_back(after.node[j]);
            continue;
        }
        const std::size_t i = *found;
        matched[i] = true;
        const double m0 = before.mass[i], m1 = after.mass[j];
        const bool same_mass = m0 == m1 || std::abs(m0 - m1) <= rtol * std::max(std::abs(m0), std::abs(m1));
        if (before.part[i] != after.part[j] || !same_mass || before.volume[i] != after.volume[j])
            changed.push_back(after.node[j]);
    }
    for (std::size_t i = 0; i < before.size(); ++i)
        if (!matched[i]) removed.push_back(before.node[i]);
    for (auto* list : {&added, &changed, &removed}) std::sort(list->begin(), list->end());
    out.added = added.size(), out.removed = removed.size(), out.changed = changed.size();
    for (long long id : added) note_id(out.added_ids, id);
    for (long long id : removed) note_id(out.removed_ids, id);
    for (long long id : changed) note_id(out.changed_ids, id);
    return out;
}

json location_json(const DiffLocation& diff_at) {
    json out = {{"file", diff_at.file}, {"line", diff_at.line}};
    if (diff_at.column > 0) out["column"] = diff_at.column;
    return out;
}

json bulk_json(const BulkChange& b, bool nodes) {
    json out = {{"before", b.before_count},
                {"after", b.after_count},
                {"added", b.added},
                {"removed", b.removed},
                {nodes ? "moved" : "changed", b.changed},
                {"added_ids", b.added_ids},
                {"removed_ids", b.removed_ids},
                {nodes ? "moved_ids" : "changed_ids", b.changed_ids}};
    if (nodes && b.changed > 0)
        out["largest_displacement"] = {{"node", b.largest_displacement_id}, {"distance", b.largest_displacement}};
    return out;
}

}  // namespace

DeckDiff diff_decks(const CheckResult& before, const CheckResult& after, double rtol) {
    DeckDiff diff;
    const json bj = values_of(before), aj = values_of(after);
    static const json no_keywords = json::array();
    const json& bk = bj.contains("keywords") ? bj["keywords"] : no_keywords;
    const json& ak = aj.contains("keywords") ? aj["keywords"] : no_keywords;
    const auto before_keys = keys_of(bk), after_keys = keys_of(ak);
    const BlockIndex before_blocks = index_blocks(before.deck), after_blocks = index_blocks(after.deck);
    std::map<std::string, std::size_t> before_index;
    for (std::size_t i = 0; i < before_keys.size(); ++i) before_index.emplace(before_keys[i], i);
    std::vector<bool> matched(bk.size(), false);
    for (std::size_t j = 0; j < ak.size(); ++j) {
        const auto it = before_index.find(after_keys[j]);
        const std::string id = id_of(ak[j]);
        KeywordChange change;
        change.name = name_of(ak[j]);
        change.id = id;
        change.after_at = diff_at(ak[j]);
        if (it == before_index.end()) {
            change.kind = KeywordChange::Kind::Added;
            diff.keywords.push_back(std::move(change));
            continue;
        }
        matched[it->second] = true;
        change.fields = compare_keyword(bk[it->second], ak[j], rtol);
        compare_undecoded(bk[it->second], ak[j], before, after, before_blocks, after_blocks, change.fields);
        change.before_at = diff_at(bk[it->second]);
        if (!change.fields.empty()) diff.keywords.push_back(std::move(change));
    }
    for (std::size_t i = 0; i < bk.size(); ++i) {
        if (matched[i]) continue;
        KeywordChange change;
        change.kind = KeywordChange::Kind::Removed;
        change.name = name_of(bk[i]);
        change.id = id_of(bk[i]);
        change.before_at = diff_at(bk[i]);
        diff.keywords.push_back(std::move(change));
    }
    diff.nodes = diff_nodes(before.model.nodes, after.model.nodes, rtol);
    diff.particles = diff_particles(before.model.particles, after.model.particles, rtol);
    return diff;
}

nlohmann::ordered_json to_json(const DeckDiff& diff) {
    json keywords = json::array();
    for (const KeywordChange& k : diff.keywords) {
        json entry = {{"change", k.kind == KeywordChange::Kind::Added     ? "added"
                                 : k.kind == KeywordChange::Kind::Removed ? "removed"
                                                                          : "changed"},
                      {"keyword", k.name},
                      {"id", k.id}};
        if (k.kind != KeywordChange::Kind::Added) entry["before"] = location_json(k.before_at);
        if (k.kind != KeywordChange::Kind::Removed) entry["after"] = location_json(k.after_at);
        if (k.kind == KeywordChange::Kind::Changed) {
            json fields = json::array();
            for (const FieldChange& f : k.fields)
                fields.push_back({{"field", f.field},
                                  {"before", f.before},
                                  {"after", f.after},
                                  {"before_at", location_json(f.before_at)},
                                  {"after_at", location_json(f.after_at)}});
            entry["fields"] = std::move(fields);
        }
        keywords.push_back(std::move(entry));
    }
    return {{"equal", diff.equal()},
            {"keywords", std::move(keywords)},
            {"nodes", bulk_json(diff.nodes, true)},
            {"particles", bulk_json(diff.particles, false)}};
}

}  // namespace sphdeck::engine
