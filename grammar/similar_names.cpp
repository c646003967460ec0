#include "grammar/similar_names.hpp"

#include <algorithm>
#include <cctype>

// The distance table's comparisons (thousands of cells for each unknown name a fuzzer makes, against the
// names within reach) guide a fuzzer nowhere: clang's coverage instrumentation (`-fsanitize=fuzzer-no-link`,
// fuzz/README.md) leaves these functions out, while ASan and UBSan still check them. A tenth of the LS-DYNA
// read target's time went to these callbacks.
#if defined(__clang__)
#define SPHDECK_NO_FUZZ_COVERAGE __attribute__((no_sanitize("coverage")))
#else
#define SPHDECK_NO_FUZZ_COVERAGE
#endif

namespace sphdeck::grammar {

namespace {
char folded(char c, bool fold_case) {
    return fold_case ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
}

// A lower bound of the distance from the letters alone: each letter one name has more of than the
// other needs an insertion, deletion or substitution, and one edit (2) settles at most two such letters
// (a swap settles none), so the distance is at least their count. Letters are counted in 64 buckets
// (merging letters only lowers the count, so the bound holds); thousands of names are tried per
// unknown keyword, and most are told apart here without the quadratic table.
SPHDECK_NO_FUZZ_COVERAGE std::size_t letter_bound(std::string_view a, std::string_view b, bool fold_case) {
    int counts[64] = {};
    for (char c : a) ++counts[static_cast<unsigned char>(folded(c, fold_case)) & 63];
    for (char c : b) --counts[static_cast<unsigned char>(folded(c, fold_case)) & 63];
    std::size_t differing = 0;
    for (int count : counts) differing += static_cast<std::size_t>(count < 0 ? -count : count);
    return differing;
}
}  // namespace

SPHDECK_NO_FUZZ_COVERAGE std::size_t typing_distance(std::string_view a, std::string_view b, bool fold_case,
                                                     std::size_t limit, SwapCost swap) {
    const auto swap_cost = static_cast<std::size_t>(swap);
    if (letter_bound(a, b, fold_case) > limit) return limit + 1;
    // Optimal string alignment with weights: three rows suffice, kept per thread (no allocation per call).
    const std::size_t n = a.size(), m = b.size();
    // Each insertion or deletion costs 2, and only they change the length.
    if (2 * (n > m ? n - m : m - n) > limit) return limit + 1;
    // Only the band |i - j| <= limit / 2 of the table can hold a value within the limit (a cell off the
    // diagonal by k is at least 2k), and a value within the limit is reached through such cells only
    // (values never fall along a path): the cells beside the band stand for "more than the limit".
    const std::size_t band = limit / 2, over = limit + 1;
    thread_local std::vector<std::size_t> prev2, prev, cur;
    prev2.assign(m + 1, over), prev.assign(m + 1, over), cur.assign(m + 1, over);
    for (std::size_t j = 0; j <= m; ++j) prev[j] = 2 * j;
    std::size_t prev_min = 0;
    for (std::size_t i = 1; i <= n; ++i) {
        const std::size_t first = i > band ? i - band : 1, last = std::min(m, i + band);
        cur[0] = 2 * i;
        if (first > 1) cur[first - 1] = over;
        if (last < m) cur[last + 1] = over;  // read by the next row as the cell above
        std::size_t row_min = cur[0];
        const char ai = folded(a[i - 1], fold_case);
        for (std::size_t j = first; j <= last; ++j) {
            const char bj = folded(b[j - 1], fold_case);
            const std::size_t cost = ai == bj ? 0 : 2;
            // Not std::min({...}): its out-of-line min_element would be instrumented after all.
            cur[j] = std::min(std::min(prev[j] + 2, cur[j - 1] + 2), prev[j - 1] + cost);
            if (i > 1 && j > 1 && ai == folded(b[j - 2], fold_case) && folded(a[i - 2], fold_case) == bj && ai != bj)
                cur[j] = std::min(cur[j], prev2[j - 2] + swap_cost);
            row_min = std::min(row_min, cur[j]);
        }
        // A row depends on the two rows above it only: once both exceed the limit, so does the end.
        if (row_min > limit && prev_min > limit) return limit + 1;
        prev_min = row_min;
        std::swap(prev2, prev);
        std::swap(prev, cur);
    }
    return std::min(prev[m], limit + 1);
}

std::size_t edit_distance(std::string_view a, std::string_view b, SwapCost swap) {
    return typing_distance(a, b, false, static_cast<std::size_t>(-1) / 2, swap) / 2;
}

std::size_t close_enough(std::string_view known) { return close_enough_for_length(known.size()); }

std::size_t close_enough_for_length(std::size_t length) {
    const std::size_t edits = length <= 4 ? 1 : std::max<std::size_t>(2, length / 4);
    return 2 * edits;
}

std::vector<std::string> closest_names(std::string_view typed, std::span<const std::string> candidates, std::size_t max,
                                       bool fold_case) {
    std::vector<std::pair<std::size_t, const std::string*>> found;
    for (const std::string& c : candidates) {
        const std::size_t limit = close_enough(c);
        const std::size_t gap = typed.size() > c.size() ? typed.size() - c.size() : c.size() - typed.size();
        if (2 * gap > limit) continue;  // each insertion or deletion costs 2
        const std::size_t d = typing_distance(typed, c, fold_case, limit);
        if (d <= limit && d > 0) found.emplace_back(d, &c);
    }
    std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) {
        return x.first != y.first ? x.first < y.first : *x.second < *y.second;
    });
    std::vector<std::string> out;
    for (const auto& [d, name] : found) {
        if (out.size() >= max) break;
        if (std::find(out.begin(), out.end(), *name) == out.end()) out.push_back(*name);
    }
    return out;
}

}  // namespace sphdeck::grammar

#undef SPHDECK_NO_FUZZ_COVERAGE
