// The values of a per-particle array near its median (the nearest distances, the neighbour counts of
// a part), kept with a followed preview (PartPreview::follow) so that the next followed edit takes the
// part's statistics from the few values it changed instead of passes over a million (issue 45).
// Exact: the statistics are those stats_of (preproc/stats_of.hpp) gives on the whole array, or none
// when the window no longer holds the median (then the caller takes them in a pass).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "preproc/preview.hpp"

namespace sphdeck::preproc {

template <typename T>
class RankWindow {
public:
    // The window of `values` around `pivot` (any value): one pass; `width` values kept on each side.
    static RankWindow make(std::span<const T> values, T pivot, std::size_t width) {
        RankWindow w;
        w.size_ = values.size(), w.pivot_ = pivot, w.width_ = width;
        std::vector<T>&under = w.under_, &over = w.over_;  // heaps while scanning
        for (const T v : values) {
            if (v == pivot) {
                ++w.equal_;
            } else if (v < pivot) {
                ++w.below_;
                if (under.size() < width || v > under.front()) {
                    under.push_back(v), std::push_heap(under.begin(), under.end(), std::greater<T>());
                    if (under.size() > width)
                        std::pop_heap(under.begin(), under.end(), std::greater<T>()), under.pop_back();
                }
            } else if (over.size() < width || v < over.front()) {
                over.push_back(v), std::push_heap(over.begin(), over.end());
                if (over.size() > width) std::pop_heap(over.begin(), over.end()), over.pop_back();
            }
        }
        std::sort(under.begin(), under.end()), std::sort(over.begin(), over.end());
        if (!values.empty()) {
            const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
            w.min_ = *lo, w.max_ = *hi;
        }
        return w;
    }

    std::size_t size() const { return size_; }

    // One value of the array changed from `before` to `now`.
    void replace(T before, T now) {
        if (before == now) return;
        remove(before);
        insert(now);
        bounds_known_ = bounds_known_ && before != min_ && before != max_;
        min_ = std::min(min_, now), max_ = std::max(max_, now);
    }

    // min and max are known unless a value that was one of them changed (then `values` are read).
    void settle_bounds(std::span<const T> values) {
        if (bounds_known_ || values.empty()) return;
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        min_ = *lo, max_ = *hi, bounds_known_ = true;
    }

    // stats_of the array, or nullopt when the window does not hold its middle values.
    std::optional<Stats> stats() const {
        Stats s;
        if (size_ == 0) return s;
        const std::size_t mid = size_ / 2;
        const auto at_mid = rank(mid);
        if (!at_mid || !bounds_known_) return std::nullopt;
        s.min = static_cast<double>(min_), s.max = static_cast<double>(max_);
        s.median = static_cast<double>(*at_mid);
        if (size_ % 2 == 0) {
            const auto before = rank(mid - 1);
            if (!before) return std::nullopt;
            s.median = 0.5 * (s.median + static_cast<double>(*before));
        }
        return s;
    }

    // The pivot moved to the middle value, each side trimmed to `width` values: ready for the next
    // edit. False when the window no longer holds enough values for that (then make it again).
    bool recentre() {
        const auto middle = rank(size_ / 2);
        if (!middle) return false;
        const T m = *middle;
        if (m < pivot_) {
            // m lies in under_: what is past it there, the pivot's copies and over_ are above it now.
            const std::size_t first = below_ - under_.size();  // values below the window
            const auto lo = std::lower_bound(under_.begin(), under_.end(), m);
            const auto hi = std::upper_bound(lo, under_.end(), m);
            if (lo == under_.begin() && first > 0) return false;  // copies of m below the window?
            std::vector<T> over(hi,
                                hi + static_cast<std::ptrdiff_t>(
                                         std::min<std::size_t>(width_, static_cast<std::size_t>(under_.end() - hi))));
            over.insert(over.end(), std::min(equal_, width_ - over.size()), pivot_);
            over.insert(over.end(), over_.begin(),
                        over_.begin() + static_cast<std::ptrdiff_t>(std::min(over_.size(), width_ - over.size())));
            const auto keep = std::min<std::size_t>(width_, static_cast<std::size_t>(lo - under_.begin()));
            std::vector<T> under(lo - static_cast<std::ptrdiff_t>(keep), lo);
            below_ = first + static_cast<std::size_t>(lo - under_.begin());
            equal_ = static_cast<std::size_t>(hi - lo);
            under_ = std::move(under), over_ = std::move(over);
        } else if (m > pivot_) {
            // m lies in over_: what is before it there, the pivot's copies and under_ are below it now.
            const std::size_t above = size_ - below_ - equal_;
            const std::size_t last = above - over_.size();  // values above the window
            const auto lo = std::lower_bound(over_.begin(), over_.end(), m);
            const auto hi = std::upper_bound(lo, over_.end(), m);
            if (hi == over_.end() && last > 0) return false;  // copies of m above the window?
            const auto before = static_cast<std::size_t>(lo - over_.begin());
            std::vector<T> under;  // the largest values below m, in order
            const std::size_t from_under =
                std::min(under_.size(), width_ > before + equal_ ? width_ - before - equal_ : 0);
            under.insert(under.end(), under_.end() - static_cast<std::ptrdiff_t>(from_under), under_.end());
            under.insert(under.end(), std::min(equal_, width_ > before ? width_ - before : 0), pivot_);
            const std::size_t from_over = std::min(before, width_);
            under.insert(under.end(), lo - static_cast<std::ptrdiff_t>(from_over), lo);
            const auto keep = std::min<std::size_t>(width_, static_cast<std::size_t>(over_.end() - hi));
            std::vector<T> over(hi, hi + static_cast<std::ptrdiff_t>(keep));
            below_ = below_ + equal_ + before;
            equal_ = static_cast<std::size_t>(hi - lo);
            under_ = std::move(under), over_ = std::move(over);
        } else {
            if (under_.size() > width_)
                under_.erase(under_.begin(), under_.end() - static_cast<std::ptrdiff_t>(width_));
            if (over_.size() > width_) over_.resize(width_);
        }
        pivot_ = m;
        // Too few left on a side that does not hold all its values: the next edits may need more.
        const bool under_short = under_.size() < width_ / 4 && under_.size() < below_;
        const bool over_short = over_.size() < width_ / 4 && over_.size() < size_ - below_ - equal_;
        return !under_short && !over_short;
    }

private:
    // The r-th smallest value (0-based), when the window holds it.
    std::optional<T> rank(std::size_t r) const {
        if (r < below_) {
            if (r + under_.size() < below_) return std::nullopt;
            return under_[r + under_.size() - below_];
        }
        if (r < below_ + equal_) return pivot_;
        if (r - below_ - equal_ < over_.size()) return over_[r - below_ - equal_];
        return std::nullopt;
    }

    // under_ holds the largest values below the pivot (all of them when under_.size() == below_),
    // over_ the smallest above it: a value between a side's far end and the pivot is in it.
    void remove(T v) {
        if (v == pivot_) {
            --equal_;
        } else if (v < pivot_) {
            if (!under_.empty() && v >= under_.front()) erase_one(under_, v);
            --below_;
        } else {
            if (!over_.empty() && v <= over_.back()) erase_one(over_, v);
        }
        --size_;
    }
    void insert(T v) {
        if (v == pivot_) {
            ++equal_;
        } else if (v < pivot_) {
            if (under_.size() == below_ || (!under_.empty() && v >= under_.front())) insert_one(under_, v);
            ++below_;
        } else {
            const std::size_t above = size_ - below_ - equal_;
            if (over_.size() == above || (!over_.empty() && v <= over_.back())) insert_one(over_, v);
        }
        ++size_;
    }
    static void erase_one(std::vector<T>& side, T v) {
        const auto at = std::lower_bound(side.begin(), side.end(), v);
        if (at != side.end() && *at == v) side.erase(at);
    }
    static void insert_one(std::vector<T>& side, T v) { side.insert(std::upper_bound(side.begin(), side.end(), v), v); }

    std::size_t size_ = 0, below_ = 0, equal_ = 0, width_ = 0;
    T pivot_{}, min_{}, max_{};
    bool bounds_known_ = true;
    std::vector<T> under_, over_;
};

// What a followed part keeps for the next followed edit: its nearest distances and neighbour counts
// near their medians (PartPreview::follow).
struct FollowWindows {
    RankWindow<double> nn_distance;
    RankWindow<std::uint32_t> neighbours;
    // The arrays they describe (ParticlePreview's, which a followed preview moves, never copies): a
    // preview copied or made otherwise holds other arrays, and its windows are not used.
    const double* nn_distance_data = nullptr;
    const std::uint32_t* neighbours_data = nullptr;
};

}  // namespace sphdeck::preproc
