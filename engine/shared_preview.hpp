// What the decks of one `sphdeck check` run share beyond the reading of their files (issue 40 item 4):
// the decoded bulk blocks (model/shared_bulk.hpp) and the geometry preview behind SPH090 and
// SPH113-SPH118, keyed by what the preview reads: the nodes and particles (the same shared blocks, in
// the same order), the parts, sections, materials, EOS and their records, the symmetry planes,
// *CONTROL_SPH and TSSFAC (engine/preview_reuse.hpp). 32 load cases over one mesh then decode it and
// compute its neighbours once. The preview holds model indices, never a place in the deck, so each
// deck's findings are the ones it makes alone. Safe to use from several threads at once.
#pragma once

#include <cstddef>
#include <functional>
#include <future>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "lint/bulk_facts.hpp"
#include "lint/rule_context.hpp"
#include "model/model.hpp"
#include "model/shared_bulk.hpp"
#include "preproc/preview.hpp"

namespace sphdeck::engine {

class SharedPreviews {
public:
    using Compute = std::function<std::shared_ptr<const preproc::Preview>(const model::Model&)>;

    // The preview of `model`, whose nodes and particles came from the shared blocks of `provenance`:
    // one kept for the same inputs and options, else `compute`'s, kept for the next decks. A model
    // not wholly made of shared blocks is computed and not kept.
    std::shared_ptr<const preproc::Preview> preview(const model::Model& model, const model::BulkProvenance& provenance,
                                                    bool particle_arrays, bool neighbour_counts,
                                                    const Compute& compute);

    std::size_t shared() const;  // previews given to another deck

private:
    struct Entry {
        model::BulkProvenance provenance;
        model::Model settings;  // the model without its nodes and particles
        bool particle_arrays = false, neighbour_counts = false;
        std::shared_future<std::shared_ptr<const preproc::Preview>> preview;  // ready once computed
    };
    static constexpr std::size_t max_entries = 4;  // the most recent previews kept
    mutable std::mutex mutex_;
    std::list<Entry> entries_;  // oldest first
    std::size_t shared_ = 0;
};

// Whether a file's text holds a word, searched once per mapped text of the run (a 100 MB include
// searched for suppression directives by every deck that includes it: a pass over its pages each time).
class SharedTextSearches {
public:
    bool contains(const grammar::SourceText& text, std::string_view word);

private:
    struct Searched {
        grammar::SourceText text;  // a mapping, kept: no other text stands at its address meanwhile
        std::string word;
        bool found = false;
    };
    std::mutex mutex_;
    std::vector<Searched> searched_;
};

// The rules' id lookups (node index, particle index, each particle's node: lint::RuleContext::Lookups)
// and their facts of the nodes and particles alone (lint/bulk_facts.hpp: the parts the particles
// name, the parts' extents, duplicated ids...) of a model made of shared blocks, for the next model
// made of the same blocks (the same nodes and particles, in the same order). Several threads may ask
// at once: decks checked at once (--jobs) share one BulkFacts, so a fact is computed once.
class SharedLookups {
public:
    // The lookups kept for models of `provenance`'s blocks (empty when none or not covered).
    lint::RuleContext::Lookups find(const model::Model& model, const model::BulkProvenance& provenance) const;
    // The facts of models of `provenance`'s blocks, made on the first ask; a model not wholly made of
    // shared blocks gets facts of its own.
    std::shared_ptr<lint::BulkFacts> facts(const model::Model& model, const model::BulkProvenance& provenance);
    // Keeps what the rules built for `model` (when it is made of shared blocks), where nothing is kept yet.
    void keep(const model::Model& model, const model::BulkProvenance& provenance,
              const lint::RuleContext::Lookups& built);
    std::size_t facts_computed() const;  // over the facts kept (tests)

private:
    struct Entry {
        model::BulkProvenance provenance;
        lint::RuleContext::Lookups lookups;
        std::shared_ptr<lint::BulkFacts> facts;
    };
    Entry& entry(const model::BulkProvenance& provenance);  // kept or made; under mutex_
    static constexpr std::size_t max_entries = 4;
    mutable std::mutex mutex_;
    std::list<Entry> entries_;  // oldest first
};

// One run's shares, made by the command line and handed to every check (CheckOptions::share).
struct RunShare {
    model::SharedBulkBlocks bulk;
    SharedPreviews previews;
    SharedTextSearches searches;
    SharedLookups lookups;
};

}  // namespace sphdeck::engine
