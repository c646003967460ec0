#include "engine/shared_preview.hpp"

#include <algorithm>

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

// What the preview reads of a model besides its nodes and particles (same_preview_settings compares it).
model::Model settings_of(const model::Model& model) {
    model::Model out;
    out.records = model.records;
    out.controls = model.controls;
    out.sections = model.sections;
    out.parts = model.parts;
    out.materials = model.materials;
    out.equations_of_state = model.equations_of_state;
    out.symmetry_planes = model.symmetry_planes;
    return out;
}
}  // namespace

std::shared_ptr<const preproc::Preview> SharedPreviews::preview(const model::Model& model,
                                                                const model::BulkProvenance& provenance,
                                                                bool particle_arrays, bool neighbour_counts,
                                                                const Compute& compute) {
    if (model.radioss || !provenance.covers(model)) return compute(model);
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (const Entry& e : entries_)
            if (e.particle_arrays == particle_arrays && e.neighbour_counts == neighbour_counts &&
                same_provenance(e.provenance, provenance) && same_preview_settings(e.settings, model)) {
                ++shared_;
                return e.preview;
            }
    }
    std::shared_ptr<const preproc::Preview> made = compute(model);
    if (!made) return made;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (entries_.size() >= max_entries) entries_.pop_front();
    entries_.push_back(Entry{provenance, settings_of(model), particle_arrays, neighbour_counts, made});
    return made;
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

void SharedLookups::keep(const model::Model& model, const model::BulkProvenance& provenance,
                         const lint::RuleContext::Lookups& built) {
    if (!provenance.covers(model) || (!built.node_index && !built.particle_index && !built.particle_nodes)) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Entry& e : entries_)
        if (same_provenance(e.provenance, provenance)) return;
    if (entries_.size() >= max_entries) entries_.pop_front();
    entries_.push_back(Entry{provenance, built});
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
