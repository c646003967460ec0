// The statistics a preview reports of per-particle values (nearest distances, neighbour counts, masses):
// min, median (the mean of the two middle values of an even count) and max. One definition, so that the
// whole preview (preview.cpp) and the one that follows an edit (preview_follow.cpp) agree to the last bit.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "preproc/preview.hpp"

namespace sphdeck::preproc {

// The value of rank `rank` (0-based, in ascending order) of counts[v - low] occurrences of each v.
inline std::uint64_t value_of_rank(const std::vector<std::uint32_t>& counts, std::uint64_t low, std::size_t rank) {
    std::size_t seen = 0;
    for (std::size_t v = 0;; ++v)
        if ((seen += counts[v]) > rank) return low + v;
}

template <typename T>
Stats stats_of(std::vector<T> v) {
    Stats s;
    if (v.empty()) return s;
    auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    s.min = static_cast<double>(*lo), s.max = static_cast<double>(*hi);
    const std::size_t mid = v.size() / 2;
    if constexpr (std::is_unsigned_v<T>) {
        // Neighbour counts span a few hundred values: counting them finds the middle ranks in one
        // pass, without the partial sort (a tenth of the time on a million particles). The same values.
        const std::uint64_t low = *lo, span = std::uint64_t{*hi} - low;
        if (span < 4096 && v.size() >= span) {
            std::vector<std::uint32_t> counts(span + 1, 0);
            for (T x : v) ++counts[x - low];
            s.median = static_cast<double>(value_of_rank(counts, low, mid));
            if (v.size() % 2 == 0)
                s.median = 0.5 * (s.median + static_cast<double>(value_of_rank(counts, low, mid - 1)));
            return s;
        }
    }
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    s.median = static_cast<double>(v[mid]);
    if (v.size() % 2 == 0)
        s.median = 0.5 * (s.median + static_cast<double>(*std::max_element(v.begin(), v.begin() + mid)));
    return s;
}

}  // namespace sphdeck::preproc
