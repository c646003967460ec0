// The statistics a preview reports of per-particle values (nearest distances, neighbour counts, masses):
// min, median (the mean of the two middle values of an even count) and max. One definition, so that the
// whole preview (preview.cpp) and the one that follows an edit (preview_follow.cpp) agree to the last bit.
#pragma once

#include <algorithm>
#include <vector>

#include "preproc/preview.hpp"

namespace sphdeck::preproc {

template <typename T>
Stats stats_of(std::vector<T> v) {
    Stats s;
    if (v.empty()) return s;
    auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    s.min = static_cast<double>(*lo), s.max = static_cast<double>(*hi);
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    s.median = static_cast<double>(v[mid]);
    if (v.size() % 2 == 0)
        s.median = 0.5 * (s.median + static_cast<double>(*std::max_element(v.begin(), v.begin() + mid)));
    return s;
}

}  // namespace sphdeck::preproc
