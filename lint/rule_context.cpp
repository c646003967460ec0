#include "lint/rule_context.hpp"

#include "lint/registry.hpp"

#include "grammar/fields.hpp"
#include "grammar/value.hpp"

namespace sphdeck::lint {

diag::Diagnostic& RuleContext::report(std::string_view code, grammar::Span span, std::string message) {
    const RuleInfo* rule = find_rule(code);
    return report(code, rule ? rule->severity : diag::Severity::Warning, span, std::move(message));
}

diag::Diagnostic& RuleContext::report(std::string_view code, diag::Severity severity, grammar::Span span,
                                      std::string message) {
    out_.push_back(diag::Diagnostic{std::string(code), severity, std::move(message), span, {}});
    return out_.back();
}

const model::IdIndex& RuleContext::node_index() const {
    if (!node_index_) node_index_ = std::make_shared<const model::IdIndex>(model.nodes.id);
    return *node_index_;
}

const model::IdIndex& RuleContext::particle_index() const {
    if (!particle_index_) particle_index_ = std::make_shared<const model::IdIndex>(model.particles.node);
    return *particle_index_;
}

const ParticleNodes& RuleContext::particle_nodes() const {
    if (!particle_nodes_) particle_nodes_ = std::make_shared<const ParticleNodes>(model, &node_index());
    return *particle_nodes_;
}

const model::PartDefinitions& RuleContext::definitions() const {
    if (!definitions_) definitions_ = std::make_unique<model::PartDefinitions>(model, deck);
    return *definitions_;
}

BulkFacts& RuleContext::bulk_facts() const {
    if (!bulk_facts_) bulk_facts_ = std::make_shared<BulkFacts>();
    return *bulk_facts_;
}

namespace {
const model::IdSet* find_set(std::unique_ptr<std::unordered_map<model::Id, const model::IdSet*>>& index,
                             const std::vector<model::IdSet>& sets, const model::Id& id) {
    if (!index) {
        index = std::make_unique<std::unordered_map<model::Id, const model::IdSet*>>();
        index->reserve(sets.size());
        for (const model::IdSet& s : sets) index->emplace(s.id, &s);  // emplace keeps the first
    }
    const auto it = index->find(id);
    return it == index->end() ? nullptr : it->second;
}
}  // namespace

const model::IdSet* RuleContext::node_set(const model::Id& id) const {
    return find_set(node_sets_, model.node_sets, id);
}
const model::IdSet* RuleContext::part_set(const model::Id& id) const {
    return find_set(part_sets_, model.part_sets, id);
}

namespace {
grammar::Span whole_line(const grammar::RawDeck& deck, std::uint32_t index) {
    if (index >= deck.lines.size()) return {};
    const grammar::CardLine& l = deck.lines[index];
    return grammar::Span{l.file, l.line, 1, deck.length(l) + 1};
}
}  // namespace

grammar::Span RuleContext::particle_span(std::size_t particle) const {
    return whole_line(deck, model.particles.line.at(particle));
}

std::map<long long, std::vector<grammar::Span>> RuleContext::node_lines(const std::set<long long>& ids) const {
    std::map<long long, std::vector<grammar::Span>> found;
    if (ids.empty()) return found;
    for (const grammar::Block& b : deck.blocks) {
        if (b.keyword != "*NODE") continue;
        const std::uint32_t width = b.format == grammar::CardFormat::Long  ? 20
                                    : b.format == grammar::CardFormat::I10 ? 10
                                                                           : 8;
        for (grammar::CardLinePtr l = deck.begin_lines(b); l != deck.end_lines(b); ++l) {
            std::string_view text = deck.text(*l);
            std::string_view first = grammar::is_free_format(text)
                                         ? text.substr(0, text.find(','))
                                         : text.substr(0, std::min<std::size_t>(text.size(), width));
            grammar::IntegerValue id = grammar::parse_integer(first);
            if (id.status == grammar::NumberStatus::Ok && ids.count(id.value))
                found[id.value].push_back(
                    grammar::Span{l->file, l->line, 1, static_cast<std::uint32_t>(text.size()) + 1});
        }
    }
    return found;
}

}  // namespace sphdeck::lint
