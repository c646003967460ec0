#include "preproc/close_pairs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

namespace sphdeck::preproc {

namespace {

using Key = std::array<std::int64_t, 3>;

struct Keyed {
    Key key;
    std::uint32_t point;
};

// Cells of at least 2 reach, and at least 2^-48 of the largest coordinate: the quotient p / cell is then
// below 2^48 (an exact int64 key) and rounded by at most 2^-5 of a cell, so two points within reach
// (their exact quotients at most 1/2 apart) get keys at most 1 apart on every axis.
double cell_for(std::span<const double> x, std::span<const double> y, std::span<const double> z, double reach) {
    double largest = 0;
    for (const auto axis : {x, y, z})
        for (const double p : axis)
            if (std::isfinite(p)) largest = std::max(largest, std::abs(p));
    const double cell = std::max(2 * reach, std::ldexp(largest, -48));
    return cell > 0 && std::isfinite(cell) ? cell : 1.0;
}

}  // namespace

void for_each_close_pair(std::span<const double> x, std::span<const double> y, std::span<const double> z, double reach,
                         const std::function<void(std::uint32_t, std::uint32_t)>& pair) {
    const double cell = cell_for(x, y, z, std::max(reach, 0.0));
    std::vector<Keyed> keyed;
    keyed.reserve(x.size());
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i])) continue;
        const auto key_of = [&](double p) { return static_cast<std::int64_t>(std::floor(p / cell)); };
        keyed.push_back({{key_of(x[i]), key_of(y[i]), key_of(z[i])}, i});
    }
    std::sort(keyed.begin(), keyed.end(),
              [](const Keyed& a, const Keyed& b) { return std::tie(a.key, a.point) < std::tie(b.key, b.point); });
    // Runs of one key: run r holds keyed[start[r] .. start[r + 1]).
    std::vector<std::size_t> start;
    for (std::size_t k = 0; k < keyed.size(); ++k)
        if (k == 0 || keyed[k].key != keyed[k - 1].key) start.push_back(k);
    const std::size_t runs = start.size();
    start.push_back(keyed.size());
    const auto key = [&](std::size_t r) { return keyed[start[r]].key; };
    const auto pair_runs = [&](std::size_t r, std::size_t q) {
        for (std::size_t a = start[r]; a < start[r + 1]; ++a)
            for (std::size_t b = start[q]; b < start[q + 1]; ++b) pair(keyed[a].point, keyed[b].point);
    };
    // The keys after a key in its 3x3x3 block, as (dx, dy) columns of dz from `low` to +1: (0, 0) with dz
    // +1 only, then the columns (0, 1), (1, -1), (1, 0), (1, 1) with dz -1..1. A column's first key grows
    // with the run's key, so each column's search goes on from where the run before left it.
    struct Column {
        std::int64_t dx, dy, low;
    };
    static constexpr Column columns[] = {{0, 0, 1}, {0, 1, -1}, {1, -1, -1}, {1, 0, -1}, {1, 1, -1}};
    std::array<std::size_t, std::size(columns)> from{};
    for (std::size_t r = 0; r < runs; ++r) {
        for (std::size_t a = start[r]; a < start[r + 1]; ++a)
            for (std::size_t b = a + 1; b < start[r + 1]; ++b) pair(keyed[a].point, keyed[b].point);
        const Key k = key(r);
        for (std::size_t c = 0; c < std::size(columns); ++c) {
            const Key first{k[0] + columns[c].dx, k[1] + columns[c].dy, k[2] + columns[c].low};
            const Key last{first[0], first[1], k[2] + 1};
            std::size_t& q = from[c];
            while (q < runs && key(q) < first) ++q;
            for (std::size_t p = q; p < runs && key(p) <= last; ++p) pair_runs(r, p);
        }
    }
}

}  // namespace sphdeck::preproc
