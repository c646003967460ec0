// Facts about a model's nodes and particles alone that the rules passing over every particle derive
// (the parts the particles name and their extents, the duplicated particle ids, the massless
// particles...): each computed on first use and kept. The decks of one run whose nodes and particles
// came from the same shared bulk blocks share one BulkFacts (engine/shared_preview.hpp), so 32 load
// cases over one mesh pass over its particles once, not 32 times (issue 40 item 4).
//
// What a fact may read, to be shared so: the values of the node and particle columns (node ids and
// coordinates; the particles' nodes, parts, masses and volume flags, in model order), and the rules'
// id lookups made from them. Never a particle's line, a card of the deck or an option: a rule whose
// answer depends on those keeps only the part that does not in a fact (particle indices, counts),
// and places and words its findings per deck. A fact that also reads another object (the geometry
// preview, which depends on the deck's smoothing settings too) is kept under that object (`key`),
// held alive meanwhile so that no other object takes its address.
//
// Safe to use from several threads at once (`check --jobs N`): a fact asked for by two decks at once
// is computed once, the other waiting for it.
#pragma once

#include <cstddef>
#include <atomic>
#include <memory>
#include <mutex>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

namespace sphdeck::lint {

class BulkFacts {
public:
    // The fact of type `Fact` (one type a fact, declared by the rule that reads it), `compute()`'s on
    // first use. `key`: the other object the fact reads, or null when it reads the columns alone.
    template <typename Fact, typename Compute>
    std::shared_ptr<const Fact> get(Compute&& compute, std::shared_ptr<const void> key = nullptr) {
        const std::shared_ptr<Slot> s = slot(typeid(Fact), std::move(key));
        std::call_once(s->once, [&] {
            s->value = std::make_shared<const Fact>(compute());
            ++computed_;
        });
        return std::static_pointer_cast<const Fact>(s->value);
    }

    std::size_t computed() const { return computed_; }  // facts computed so far (tests)

private:
    struct Slot {
        std::type_index type;
        std::shared_ptr<const void> key;  // kept alive: its address stays its own
        std::once_flag once;
        std::shared_ptr<const void> value;
        explicit Slot(std::type_index t, std::shared_ptr<const void> k) : type(t), key(std::move(k)) {}
    };
    std::shared_ptr<Slot> slot(std::type_index type, std::shared_ptr<const void> key);

    static constexpr std::size_t max_keyed = 4;  // slots of one fact type under other objects, the newest
    std::mutex mutex_;
    std::atomic<std::size_t> computed_{0};
    std::vector<std::shared_ptr<Slot>> slots_;  // oldest first
};

}  // namespace sphdeck::lint
