#include "model/model_json.hpp"

#include <map>

#include "model/id_index.hpp"

namespace sphdeck::model {
namespace {

using json = nlohmann::ordered_json;

json value_of(const FieldRecord& f) {
    using keywords::FieldType;
    if (!f.valid && f.explicit_value) return f.text;  // undecodable text, kept as written
    switch (f.type) {
        case FieldType::Text: return f.text;
        case FieldType::Label:
            if (!f.valid) return f.explicit_value ? json(f.text) : json(nullptr);
            [[fallthrough]];
        case FieldType::Integer:
            if (!f.valid) return nullptr;
            return static_cast<long long>(f.number);
        case FieldType::Real: return f.valid ? json(f.number) : json(nullptr);
        case FieldType::Unused: return nullptr;
    }
    return nullptr;
}

json field_json(const FieldRecord& f) {
    return {{"value", value_of(f)}, {"explicit", f.explicit_value}, {"line", f.span.line}, {"column", f.span.column}};
}

json default_of(const keywords::FieldSpec& f) {
    using keywords::FieldType;
    if (f.type == FieldType::Text) return f.default_text.empty() ? json(nullptr) : json(std::string(f.default_text));
    if (!f.default_value) return nullptr;
    if (f.type == FieldType::Real) return *f.default_value;
    return static_cast<long long>(*f.default_value);
}

// The value a card condition compares, as the block walker saw it (model/deck_check.cpp): a
// number read or defaulted, else 0.
double condition_value(const KeywordRecord& r, std::string_view name) {
    const FieldRecord* f = r.field(name);
    return f && f->valid && f->type != keywords::FieldType::Text ? f->number : 0.0;
}

// Every field of the cards the keyword reads once, in schema order: as decoded when the deck
// wrote the card, else the default with "explicit": false and no position (*CONTROL_SPH without
// its optional cards 2 and 3 still runs with INI 0 and QL 0.01). Fields of repeated cards
// (`written`, in deck order) follow.
json all_fields(const KeywordRecord& r, json written) {
    auto match = keywords::find_keyword(r.keyword);
    if (!match || match->schema != r.schema) return written;
    const std::vector<const keywords::CardSpec*> cards = keywords::cards_for(*match);
    const std::size_t single = cards.size() - keywords::repeat_group_size(*match);
    json out = json::object();
    for (std::size_t i = 0; i < single; ++i) {
        const keywords::CardSpec& card = *cards[i];
        if (card.repeat == keywords::CardRepeat::Repeated) continue;
        if (card.present_if && !card.present_if->holds(condition_value(r, card.present_if->field))) continue;
        for (const keywords::FieldSpec& f : card.fields) {
            const std::string name(f.name);
            if (f.type == keywords::FieldType::Unused || out.contains(name)) continue;
            if (written.contains(name)) out[name] = std::move(written[name]);
            else out[name] = {{"value", default_of(f)}, {"explicit", false}, {"line", nullptr}, {"column", nullptr}};
        }
    }
    for (auto& item : written.items())
        if (!out.contains(item.key())) out[item.key()] = std::move(item.value());
    return out;
}

json record_json(const KeywordRecord& r, const grammar::RawDeck& deck) {
    json fields = json::object();
    json cards = json::array();
    for (const auto& row : r.rows) {
        json card = json::object();
        for (const auto& f : row) {
            json j = field_json(f);
            if (!fields.contains(f.name)) fields[std::string(f.name)] = j;
            card[std::string(f.name)] = std::move(j);
        }
        cards.push_back(std::move(card));
    }
    json out = {{"name", r.keyword},
                {"schema", r.schema->name},
                {"file", deck.sources.file(r.span.file).display_name},
                {"line", r.span.line},
                {"fields", all_fields(r, std::move(fields))}};
    if (r.rows.size() > 1) out["cards"] = std::move(cards);  // repeated cards: every line
    return out;
}

}  // namespace

nlohmann::ordered_json to_json(const Model& model, const grammar::RawDeck& deck, const DumpOptions& options) {
    json keywords = json::array();
    for (const auto& r : model.records) keywords.push_back(record_json(r, deck));

    std::map<std::string, std::size_t> per_part;
    for (long long part : model.particles.part) ++per_part[std::to_string(part)];
    json particles = {{"count", model.particles.size()}, {"parts", per_part}};
    if (options.particles) {
        json list = json::array();
        const Particles& p = model.particles;
        const IdIndex nodes(model.nodes.id);
        for (std::size_t i = 0; i < p.size(); ++i) {
            json item = {{"id", p.node[i]}, {"part", p.part[i]}, {"mass", p.mass[i]}, {"volume", p.volume[i] != 0}};
            if (auto n = nodes.find(p.node[i]))
                item["position"] = {model.nodes.x[*n], model.nodes.y[*n], model.nodes.z[*n]};
            list.push_back(std::move(item));
        }
        particles["list"] = std::move(list);
    }
    std::map<std::string, std::size_t> unknown;
    for (const auto& b : deck.blocks)
        if (!keywords::find_keyword(b.keyword) || !keywords::find_keyword(b.keyword)->unknown_options.empty())
            ++unknown[b.keyword];
    return {{"keywords", std::move(keywords)},
            {"unknown_keywords", unknown},
            {"nodes", {{"count", model.nodes.id.size()}}},
            {"particles", std::move(particles)}};
}

}  // namespace sphdeck::model
