// What a lint rule sees: the model, the raw deck (for locations), the run's options, and a
// reporter that takes the rule's default severity from the registry.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "diag/diagnostic.hpp"
#include "lint/bulk_facts.hpp"
#include "grammar/raw_deck.hpp"
#include "model/id_index.hpp"
#include "model/model.hpp"
#include "model/particle_nodes.hpp"
#include "model/part_definitions.hpp"

namespace sphdeck::preproc {
struct Preview;
}

namespace sphdeck::lint {

using model::ParticleNodes;

enum class Solver { Unknown, Smp, Mpp };

struct RuleOptions {
    Solver solver = Solver::Unknown;
    std::string solver_source;  // who decided: "--solver", "sphdeck.toml", ...
    // The rules that need the particle geometry (neighbour grid, nearest neighbours: SPH090,
    // SPH113-SPH118) cost about as much as reading the deck; `check --no-geometry` skips them.
    bool geometry = true;
    // Keep the preview the geometry rules computed (RuleContext::preview): `sphdeck smooth` prints
    // it instead of computing the same preview a second time; the editor reuses it on the next re-check.
    bool keep_preview = false;
    // With its per-particle arrays (h, neighbour counts...), which `smooth` prints and the rules do not need.
    bool preview_arrays = false;
};

class RuleContext {
public:
    RuleContext(const model::Model& model, const grammar::RawDeck& deck, const RuleOptions& options,
                std::vector<diag::Diagnostic>& out)
        : model(model), deck(deck), options(options), out_(out) {}

    const model::Model& model;
    const grammar::RawDeck& deck;
    const RuleOptions& options;

    // Reports with the registry's default severity for `code`.
    diag::Diagnostic& report(std::string_view code, grammar::Span span, std::string message);
    // Reports with an explicit severity (rules whose severity depends on the case).
    diag::Diagnostic& report(std::string_view code, diag::Severity severity, grammar::Span span, std::string message);

    // Location of a particle's card line (its *ELEMENT_SPH line), whole line.
    grammar::Span particle_span(std::size_t particle) const;
    // The *NODE lines defining each of `ids` (a scan of the *NODE blocks: for rare reports only).
    std::map<long long, std::vector<grammar::Span>> node_lines(const std::set<long long>& ids) const;

    // Lookups shared by the rules, built on first use: on decks of millions of particles each
    // costs a pass over the arrays, and several rule families need them.
    const model::IdIndex& node_index() const;
    const model::IdIndex& particle_index() const;
    // Position in model.nodes of each particle's node; no_node where the node is missing (REF001).
    static constexpr std::uint32_t no_node = ParticleNodes::no_node;
    const ParticleNodes& particle_nodes() const;
    // The first node set / part set defining `id` (null when none). Decks written by pre-processors
    // hold one set per particle, so rules look sets up by id, never by scanning the list.
    const model::IdSet* node_set(const model::Id& id) const;
    const model::IdSet* part_set(const model::Id& id) const;
    // The section, material and EOS each part reads, in its own *CASE run (model/part_definitions.hpp).
    const model::PartDefinitions& definitions() const;

    // The geometry rules' preview, when RuleOptions::keep_preview asked for it (else null).
    std::shared_ptr<const preproc::Preview> preview;

    // The three lookups above, as built so far: what another deck of the same node ids and particle
    // nodes may use instead of building them (engine/shared_preview.hpp), given before the rules run.
    struct Lookups {
        std::shared_ptr<const model::IdIndex> node_index, particle_index;
        std::shared_ptr<const ParticleNodes> particle_nodes;
    };
    Lookups lookups() const { return {node_index_, particle_index_, particle_nodes_}; }
    void use_lookups(const Lookups& built) {
        node_index_ = built.node_index, particle_index_ = built.particle_index;
        particle_nodes_ = built.particle_nodes;
    }

    // Facts of the nodes and particles alone (lint/bulk_facts.hpp), computed on first use. The engine
    // gives the decks of one run whose nodes and particles are the same shared blocks one object.
    BulkFacts& bulk_facts() const;
    void use_bulk_facts(std::shared_ptr<BulkFacts> facts) { bulk_facts_ = std::move(facts); }

private:
    std::vector<diag::Diagnostic>& out_;
    mutable std::shared_ptr<BulkFacts> bulk_facts_;
    mutable std::shared_ptr<const model::IdIndex> node_index_, particle_index_;
    mutable std::shared_ptr<const ParticleNodes> particle_nodes_;
    using SetIndex = std::unordered_map<model::Id, const model::IdSet*>;
    mutable std::unique_ptr<SetIndex> node_sets_, part_sets_;
    mutable std::unique_ptr<model::PartDefinitions> definitions_;
};

// Every lint rule family, run in order.
void run_rules(RuleContext& context);

}  // namespace sphdeck::lint
