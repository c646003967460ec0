#include "engine/shared_preview.hpp"

#include <algorithm>
#include <exception>
#include <limits>
#include <optional>

#include "engine/preview_reuse.hpp"

namespace sphdeck::engine {
namespace {
bool same_blocks(const std::vector<std::shared_ptr<const model::SharedBulkBlock>>& a,
                 const std::vector<std::shared_ptr<const model::SharedBulkBlock>>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const auto& x, const auto& y) { return x.get() == y.get(); });
}

bool same_provenance(const model::BulkProvenance& a, const model::BulkProvenance& b) {
    return same_blocks(a.nodes, b.nodes) && same_blocks(a.particles, b.particles);
}

// What the preview reads of a model besides its nodes and particles (same_preview_settings compares
// it): the records kept are those of the materials and EOS alone (their moduli), not the deck's every
// keyword, each pointed at in the copy's own order.
model::Model settings_of(const model::Model& model) {
    model::Model out;
    out.controls = model.controls;
    out.sections = model.sections;
    out.parts = model.parts;
    out.materials = model.materials;
    out.equations_of_state = model.equations_of_state;
    out.symmetry_planes = model.symmetry_planes;
    const auto keep_record = [&](std::optional<std::size_t>& record) {
        if (!record) return;
        if (*record >= model.records.size()) {  // none there: still none in the copy
            record = std::numeric_limits<std::size_t>::max();
            return;
        }
        out.records.push_back(model.records[*record]);
        record = out.records.size() - 1;
    };
    for (model::Material& m : out.materials) keep_record(m.record);
    for (model::Eos& e : out.equations_of_state) keep_record(e.record);
    return out;
}
}  // namespace

std::shared_ptr<const preproc::Preview> SharedPreviews::preview(const model::Model& model,
                                                                const model::BulkProvenance& provenance,
                                                                bool particle_arrays, bool neighbour_counts,
                                                                const Compute& compute) {
    if (model.radioss || !provenance.covers(model)) return compute(model);
    std::promise<std::shared_ptr<const preproc::Preview>> made;
    std::shared_future<std::shared_ptr<const preproc::Preview>> kept;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (const Entry& e : entries_)
            if (e.particle_arrays == particle_arrays && e.neighbour_counts == neighbour_counts &&
                same_provenance(e.provenance, provenance) && same_preview_settings(e.settings, model)) {
                ++shared_;
                kept = e.preview;
                break;
            }
        if (!kept.valid()) {  // this deck computes it; a deck that asks meanwhile (--jobs) waits for it
            if (entries_.size() >= max_entries) entries_.pop_front();
            entries_.push_back(
                Entry{provenance, settings_of(model), particle_arrays, neighbour_counts, made.get_future().share()});
        }
    }
    if (kept.valid()) {
        try {
            return kept.get();
        } catch (...) {
            return compute(model);  // the deck that computed it failed: this one tries for itself
        }
    }
    try {
        std::shared_ptr<const preproc::Preview> preview = compute(model);
        made.set_value(preview);
        return preview;
    } catch (...) {
        made.set_exception(std::current_exception());
        throw;
    }
}

std::size_t SharedPreviews::shared() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return shared_;
}

lint::RuleContext::Lookups SharedLookups::find(const model::Model& model,
                                               const model::BulkProvenance& provenance) const {
    if (!provenance.covers(model)) return {};
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Entry& e : entries_)
        if (same_provenance(e.provenance, provenance)) return e.lookups;
    return {};
}

SharedLookups::Entry& SharedLookups::entry(const model::BulkProvenance& provenance) {
    for (Entry& e : entries_)
        if (same_provenance(e.provenance, provenance)) return e;
    if (entries_.size() >= max_entries) entries_.pop_front();
    entries_.push_back(Entry{provenance, {}, std::make_shared<lint::BulkFacts>()});
    return entries_.back();
}

std::shared_ptr<lint::BulkFacts> SharedLookups::facts(const model::Model& model,
                                                      const model::BulkProvenance& provenance) {
    if (!provenance.covers(model)) return std::make_shared<lint::BulkFacts>();  // this deck's own
    const std::lock_guard<std::mutex> lock(mutex_);
    return entry(provenance).facts;
}

void SharedLookups::keep(const model::Model& model, const model::BulkProvenance& provenance,
                         const lint::RuleContext::Lookups& built) {
    if (!provenance.covers(model) || (!built.node_index && !built.particle_index && !built.particle_nodes)) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    lint::RuleContext::Lookups& kept = entry(provenance).lookups;
    if (!kept.node_index) kept.node_index = built.node_index;
    if (!kept.particle_index) kept.particle_index = built.particle_index;
    if (!kept.particle_nodes) kept.particle_nodes = built.particle_nodes;
}

std::size_t SharedLookups::facts_computed() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::size_t n = 0;
    for (const Entry& e : entries_) n += e.facts->computed();
    return n;
}

bool SharedTextSearches::contains(const grammar::SourceText& text, std::string_view word) {
    if (!text.mapped()) return text.contains(word);  // a small file: searched again, nothing kept
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (const Searched& s : searched_)
            if (s.text.data() == text.data() && s.text.size() == text.size() && s.word == word) return s.found;
    }
    const bool found = text.contains(word);
    const std::lock_guard<std::mutex> lock(mutex_);
    constexpr std::size_t most_kept = 16;  // the most recent texts (grammar::FileCache holds them meanwhile)
    if (searched_.size() >= most_kept) searched_.erase(searched_.begin());
    searched_.push_back(Searched{text, std::string(word), found});
    return found;
}

}  // namespace sphdeck::engine
