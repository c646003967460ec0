#include "lint/bulk_facts.hpp"

#include <algorithm>

namespace sphdeck::lint {

std::shared_ptr<BulkFacts::Slot> BulkFacts::slot(std::type_index type, std::shared_ptr<const void> key) {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& s : slots_)
        if (s->type == type && s->key.get() == key.get()) return s;
    if (key) {  // an object's facts go with it: keep those of the last few objects only
        const auto same_type = [&](const std::shared_ptr<Slot>& s) { return s->type == type && s->key; };
        if (static_cast<std::size_t>(std::count_if(slots_.begin(), slots_.end(), same_type)) >= max_keyed)
            slots_.erase(std::find_if(slots_.begin(), slots_.end(), same_type));  // a holder keeps its own
    }
    slots_.push_back(std::make_shared<Slot>(type, std::move(key)));
    return slots_.back();
}

}  // namespace sphdeck::lint
