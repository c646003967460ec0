// The statistics a preview reports of per-particle values (nearest distances, neighbour counts, masses):
// min, median (the mean of the two middle values of an even count) and max. One definition, so that the
// whole preview (preview.cpp) and the one that follows an edit (preview_follow.cpp) agree to the last bit.
#pragma once

#include <algorithm>
#include <cmath>
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

// The values of ranks `mid` and `mid - 1` (the latter when `both`) of finite doubles in [lo, hi] without
// a negative zero: binned by (value - lo) * scale, which never decreases as the value grows, so a rank's
// value lies in the bin where the running count passes it; only that bin's values are then sorted
// partially. One pass and a few hundred values instead of a partial sort of a copy of a million (issue
// 40). The values equal nth_element's bit for bit: equal doubles other than zeros have equal bits.
inline bool middle_ranks_by_bins(const std::vector<double>& v, double lo, double hi, std::size_t mid, bool both,
                                 double& at_mid, double& below_mid) {
    constexpr std::size_t bins = 4096;
    const double width = hi - lo;
    if (width == 0 && lo != 0) {  // one value (a part's masses) is every rank's, unless NaNs hide among them
        at_mid = below_mid = lo;
        return std::all_of(v.begin(), v.end(), [lo](double x) { return x == lo; });
    }
    if (!(width > 0) || !std::isfinite(width)) return false;
    const double scale = (bins - 1) / width;  // (hi - lo) * scale <= bins - 1 (+ a rounding): clamped
    if (!std::isfinite(scale)) return false;
    std::vector<std::uint32_t> count(bins, 0);
    const auto bin_of = [&](double x) {
        return std::min<std::size_t>(static_cast<std::size_t>((x - lo) * scale), bins - 1);
    };
    for (const double x : v) {
        if (!(x >= lo && x <= hi)) return false;      // NaN: nth_element's answer is its own
        if (x == 0 && std::signbit(x)) return false;  // -0 and +0 compare equal but print differently
        ++count[bin_of(x)];
    }
    // The bins of ranks mid - 1 and mid; then their values, partially sorted.
    std::size_t seen = 0, first_bin = bins, last_bin = bins, before_first = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        if (first_bin == bins && seen + count[b] > mid - (both ? 1 : 0)) first_bin = b, before_first = seen;
        if (seen + count[b] > mid) {
            last_bin = b;
            break;
        }
        seen += count[b];
    }
    std::vector<double> chosen;
    for (const double x : v) {
        const std::size_t b = bin_of(x);
        if (b >= first_bin && b <= last_bin) chosen.push_back(x);
    }
    const std::size_t at = mid - before_first;
    std::nth_element(chosen.begin(), chosen.begin() + static_cast<std::ptrdiff_t>(at), chosen.end());
    at_mid = chosen[at];
    if (both) below_mid = *std::max_element(chosen.begin(), chosen.begin() + static_cast<std::ptrdiff_t>(at));
    return true;
}

// Min and max, and the median when counting or binning finds it (true); else `s.median` is left to
// median_by_partial_sort.
template <typename T>
bool stats_without_sort(const std::vector<T>& values, Stats& s) {
    if (values.empty()) return true;
    auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    s.min = static_cast<double>(*lo), s.max = static_cast<double>(*hi);
    const std::size_t mid = values.size() / 2;
    if constexpr (std::is_unsigned_v<T>) {
        // Neighbour counts span a few hundred values: counting them finds the middle ranks in one
        // pass, without the partial sort (a tenth of the time on a million particles). The same values.
        const std::uint64_t low = *lo, span = std::uint64_t{*hi} - low;
        if (span < 4096 && values.size() >= span) {
            std::vector<std::uint32_t> counts(span + 1, 0);
            for (T x : values) ++counts[x - low];
            s.median = static_cast<double>(value_of_rank(counts, low, mid));
            if (values.size() % 2 == 0)
                s.median = 0.5 * (s.median + static_cast<double>(value_of_rank(counts, low, mid - 1)));
            return true;
        }
    }
    if constexpr (std::is_same_v<T, double>) {
        double at_mid = 0, below_mid = 0;
        if (values.size() >= 2 &&
            middle_ranks_by_bins(values, *lo, *hi, mid, values.size() % 2 == 0, at_mid, below_mid)) {
            s.median = values.size() % 2 == 0 ? 0.5 * (at_mid + below_mid) : at_mid;
            return true;
        }
    }
    return false;
}

// The median by a partial sort of `v` (reordered).
template <typename T>
void median_by_partial_sort(std::vector<T>& v, Stats& s) {
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    s.median = static_cast<double>(v[mid]);
    if (v.size() % 2 == 0)
        s.median = 0.5 * (s.median + static_cast<double>(*std::max_element(v.begin(), v.begin() + mid)));
}

template <typename T>
Stats stats_of(const std::vector<T>& values) {
    Stats s;
    if (stats_without_sort(values, s)) return s;
    std::vector<T> v(values);
    median_by_partial_sort(v, s);
    return s;
}

// The same, the values given up: sorted in place when they must be, and freed on return, not left to the
// caller until its end (the preview's peak of memory, issue 40 item 2).
template <typename T>
Stats stats_of(std::vector<T>&& values) {
    std::vector<T> v = std::move(values);
    Stats s;
    if (!stats_without_sort(v, s)) median_by_partial_sort(v, s);
    return s;
}

}  // namespace sphdeck::preproc
