#include "model/radioss_json.hpp"

#include <map>
#include <string>

#include "grammar/number_cast.hpp"
#include "model/model_json.hpp"

namespace sphdeck::model {
namespace {

using json = nlohmann::ordered_json;

// The value as read: a number for Int and Real cells, text for the others; null when blank or
// unreadable. The Radioss card tables carry no defaults (the starter's defaults depend on the
// field and the version: model/radioss_build_*.cpp), so a blank stays null.
json radioss_json_value_of(const RadiossField& f) {
    if (!f.valid) return f.explicit_value ? json(f.text) : json(nullptr);
    if (!f.number) return f.text;
    if (f.integer) return grammar::saturating_integer<long long>(f.value);
    return f.value;
}

json radioss_record_json(const RadiossRecord& r, const grammar::RawDeck& deck) {
    json fields = json::object();
    for (const RadiossField& f : r.fields) {
        const std::string name(f.name);
        if (fields.contains(name)) continue;  // first occurrence, as for LS-DYNA
        fields[name] = {{"value", radioss_json_value_of(f)},
                        {"explicit", f.explicit_value},
                        {"line", f.span.line},
                        {"column", f.span.column}};
    }
    json out = {{"name", r.header},           {"keyword", r.keyword},
                {"title", r.title},           {"file", deck.sources.file(r.span.file).display_name},
                {"line", r.span.line},        {"card_format", r.format},
                {"fields", std::move(fields)}};
    if (r.repeated_lines > 0) out["records"] = r.repeated_lines;  // nodes, particles, ids, rows
    return out;
}

}  // namespace

nlohmann::ordered_json radioss_to_json(const RadiossReading& reading, const Model& model, const grammar::RawDeck& deck,
                                       bool list_particles) {
    json keywords = json::array();
    for (const RadiossRecord& r : reading.records) keywords.push_back(radioss_record_json(r, deck));
    return {{"format", "radioss"},
            {"version", radioss_version(deck)},
            {"keywords", std::move(keywords)},
            {"unknown_keywords", reading.unknown},
            {"nodes", {{"count", model.nodes.id.size()}}},
            {"particles", particles_json(model, list_particles)}};
}

}  // namespace sphdeck::model
