// The first pairs, in order, of a set of pairs too large to keep: the coincident pairs of a deck with
// many particles at one place (m of them make m (m - 1) / 2 pairs). A bounded max-heap keeps the `keep`
// smallest pairs (first, then second index) offered; the pairs offered must be distinct. Memory is
// `keep` pairs whatever is offered, and a set of pairs offered in increasing order stops at its first
// pair that cannot be kept: every later one comes after it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace sphdeck::preproc {

class FirstPairs {
public:
    using Pair = std::pair<std::uint32_t, std::uint32_t>;

    explicit FirstPairs(std::size_t keep) : keep_(keep) {}

    // Offers pair p (p.first < p.second); false when it is not kept: the heap is full and p comes after
    // every pair in it (so does every pair after p).
    bool offer(Pair p) {
        if (heap_.size() < keep_) {
            heap_.push_back(p), std::push_heap(heap_.begin(), heap_.end());
            return true;
        }
        if (keep_ == 0 || !(p < heap_.front())) return false;
        std::pop_heap(heap_.begin(), heap_.end());
        heap_.back() = p;
        std::push_heap(heap_.begin(), heap_.end());
        return true;
    }

    // The pairs of the points of `a` (ascending) among themselves, in increasing order.
    void offer_among(std::span<const std::uint32_t> a) {
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = i + 1; j < a.size(); ++j)
                if (!offer({a[i], a[j]})) return;
    }

    // The pairs of a point of `a` and one of `b` (each ascending, no point in both), in increasing
    // order: each point of either, smallest first, with the points of the other after it.
    void offer_between(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
        std::size_t i = 0, j = 0;
        while (i < a.size() || j < b.size()) {
            const bool from_a = j == b.size() || (i < a.size() && a[i] < b[j]);
            const std::uint32_t p = from_a ? a[i++] : b[j++];
            const std::span<const std::uint32_t> other = from_a ? b.subspan(j) : a.subspan(i);
            for (const std::uint32_t q : other)
                if (!offer({p, q})) return;
        }
    }

    // The pairs kept, in increasing order.
    std::vector<Pair> sorted() && {
        std::sort_heap(heap_.begin(), heap_.end());
        return std::move(heap_);
    }

private:
    std::size_t keep_;
    std::vector<Pair> heap_;
};

}  // namespace sphdeck::preproc
