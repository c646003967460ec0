#include "model/model_json.hpp"

#include <map>
#include <optional>

#include "grammar/number_cast.hpp"
#include "model/id_index.hpp"

namespace sphdeck::model {
namespace {

using json = nlohmann::ordered_json;

json json_value_of(const FieldRecord& f) {
    using keywords::FieldType;
    if (!f.valid && f.explicit_value) return f.text;  // undecodable text, kept as written
    switch (f.type) {
        case FieldType::Text: return f.text;
        case FieldType::Label:
            if (!f.valid) return f.explicit_value ? json(f.text) : json(nullptr);
            [[fallthrough]];
        case FieldType::Integer:
            if (!f.valid) return nullptr;
            return grammar::saturating_integer<long long>(f.number);
        case FieldType::Real: return f.valid ? json(f.number) : json(nullptr);
        case FieldType::Unused: return nullptr;
    }
    return nullptr;
}

json field_json(const FieldRecord& f) {
    return {{"value", json_value_of(f)},
            {"explicit", f.explicit_value},
            {"line", f.span.line},
            {"column", f.span.column}};
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
double record_condition_value(const KeywordRecord& r, std::string_view name) {
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
        if (card.present_if &&
            !card.present_if->holds_with([&](std::string_view field) { return record_condition_value(r, field); }))
            continue;
        for (const keywords::FieldSpec& f : card.fields) {
            const std::string name(f.name);
            if (f.type == keywords::FieldType::Unused || out.contains(name)) continue;
            if (written.contains(name))
                out[name] = std::move(written[name]);
            else
                out[name] = {{"value", default_of(f)}, {"explicit", false}, {"line", nullptr}, {"column", nullptr}};
        }
    }
    for (auto& item : written.items())
        if (!out.contains(item.key())) out[item.key()] = std::move(item.value());
    return out;
}

json keyword_record_json(const KeywordRecord& r, const grammar::RawDeck& deck) {
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

// A block written without a single card line (*CONTROL_SPH followed by the next keyword) has no
// record, yet it has settings: every one a default. Blocks the reader acts on (*INCLUDE...),
// free text and the particle arrays stay out, as for written blocks.
std::optional<KeywordRecord> unwritten_record(const grammar::Block& b) {
    if (b.line_count != 0) return std::nullopt;
    auto match = keywords::find_keyword(b.keyword);
    if (!match || !match->unknown_options.empty() || match->schema->free_text || match->schema->generated)
        return std::nullopt;
    const std::string_view name = match->schema->name;
    if (name == "*NODE" || name == "*ELEMENT_SPH" || name == "*END" || name.starts_with("*INCLUDE") ||
        name.starts_with("*PARAMETER"))
        return std::nullopt;
    bool has_fields = false;
    for (const keywords::CardSpec* card : keywords::cards_for(*match))
        for (const keywords::FieldSpec& f : card->fields)
            has_fields =
                has_fields || (card->repeat != keywords::CardRepeat::Repeated && f.type != keywords::FieldType::Unused);
    if (!has_fields) return std::nullopt;  // *KEYWORD, *END: nothing to show
    KeywordRecord r;
    r.schema = match->schema;
    r.keyword = b.keyword;
    for (const auto* option : match->options) r.options.push_back(option->suffix);
    r.span = b.span;
    return r;
}

}  // namespace

nlohmann::ordered_json particles_json(const Model& model, bool list_each) {
    std::map<std::string, std::size_t> per_part;
    for (long long part : model.particles.part) ++per_part[std::to_string(part)];
    json particles = {{"count", model.particles.size()}, {"parts", per_part}};
    if (list_each) {
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
    return particles;
}

nlohmann::ordered_json to_json(const Model& model, const grammar::RawDeck& deck, const DumpOptions& options) {
    // Records follow the blocks in deck order; blocks without card lines slot in between.
    json keywords = json::array();
    std::size_t next = 0;
    for (const grammar::Block& b : deck.blocks) {
        const KeywordRecord* r = next < model.records.size() ? &model.records[next] : nullptr;
        if (r && r->span.file == b.span.file && r->span.line == b.span.line) {
            keywords.push_back(keyword_record_json(*r, deck));
            ++next;
        } else if (auto unwritten = unwritten_record(b)) {
            keywords.push_back(keyword_record_json(*unwritten, deck));
        }
    }
    for (; next < model.records.size(); ++next) keywords.push_back(keyword_record_json(model.records[next], deck));

    json particles = particles_json(model, options.particles);
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
