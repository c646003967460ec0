#include "model/model_builder.hpp"

#include "model/extract.hpp"

namespace sphdeck::model {

namespace {
// One block's lines are known before its cards are decoded: grow the arrays once, not by doubling.
void reserve_more(Nodes& n, std::size_t more) {
    const std::size_t size = n.id.size() + more;
    n.id.reserve(size), n.x.reserve(size), n.y.reserve(size), n.z.reserve(size);
}
void reserve_more(Particles& p, std::size_t more) {
    const std::size_t size = p.node.size() + more;
    p.node.reserve(size), p.part.reserve(size), p.mass.reserve(size), p.volume.reserve(size), p.line.reserve(size);
}
}  // namespace

ModelBuilder::ModelBuilder(const grammar::RawDeck& deck) : deck_(deck) {
    model_.memory2_given = !deck.keyword_arguments.memory2.empty();
}

void ModelBuilder::add_node(const std::vector<FieldValue>& v) {
    if (v.size() < 4 || !v[0].valid) return;  // a node without a usable id is already reported
    Nodes& n = model_.nodes;
    n.id.push_back(static_cast<long long>(v[0].number));
    n.x.push_back(v[1].number);
    n.y.push_back(v[2].number);
    n.z.push_back(v[3].number);
}

void ModelBuilder::add_particles(const grammar::Block& block, const std::vector<FieldValue>& v,
                                 const grammar::CardLine& line) {
    if (v.size() < 3 || !v[0].valid) return;
    Particles& p = model_.particles;
    const long long first = static_cast<long long>(v[0].number);
    long long last = first;
    // NEND > NID generates NID..NEND with the same part and mass (lsdyna-sph-cards.md §3).
    if (v.size() >= 4 && v[3].valid && v[3].explicit_value && v[3].number > v[0].number)
        last = static_cast<long long>(v[3].number);
    const long long part = v[1].valid ? static_cast<long long>(v[1].number) : -1;
    const bool volume = block.keyword.find("_VOLUME") != std::string::npos;
    const auto index = static_cast<std::uint32_t>(&line - deck_.lines.data());
    for (long long id = first; id <= last; ++id) {
        p.node.push_back(id);
        p.part.push_back(part);
        p.mass.push_back(v[2].valid ? v[2].number : 0.0);
        p.volume.push_back(volume);
        p.line.push_back(index);
    }
}

void ModelBuilder::on_card(const grammar::Block& block, const keywords::KeywordMatch& match,
                           const keywords::CardSpec&, const grammar::CardLine& line,
                           const std::vector<FieldValue>& values) {
    const std::string_view name = match.schema->name;
    const bool new_block = current_block_ != &block;
    current_block_ = &block;
    if (name == "*NODE") {
        if (new_block) reserve_more(model_.nodes, block.line_count);
        return add_node(values);
    }
    if (name == "*ELEMENT_SPH") {
        if (new_block) reserve_more(model_.particles, block.line_count);
        return add_particles(block, values, line);
    }
    if (new_block) {
        current_block_ = &block;
        KeywordRecord record;
        record.schema = match.schema;
        record.keyword = block.keyword;
        for (const auto* option : match.options) record.options.push_back(option->suffix);
        record.span = block.span;
        model_.records.push_back(std::move(record));
    }
    std::vector<FieldRecord> row;
    row.reserve(values.size());
    for (const FieldValue& v : values) {
        if (v.spec->type == keywords::FieldType::Unused) continue;
        row.push_back(FieldRecord{v.spec->name, v.spec->type, v.number, std::string(v.text), v.explicit_value,
                                  v.valid, v.span});
    }
    model_.records.back().rows.push_back(std::move(row));
}

Model ModelBuilder::finish(std::vector<diag::Diagnostic>& out) {
    extract_typed(deck_, model_, out);
    return std::move(model_);
}

Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary) {
    ModelBuilder builder(deck);
    DeckSummary s = check_deck(deck, out, [&](const grammar::Block& b, const keywords::KeywordMatch& m,
                                              const keywords::CardSpec& c, const grammar::CardLine& l,
                                              const std::vector<FieldValue>& v) { builder.on_card(b, m, c, l, v); });
    if (summary) *summary = s;
    return builder.finish(out);
}

}  // namespace sphdeck::model
