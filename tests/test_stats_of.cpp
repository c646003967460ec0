// stats_of on doubles (preproc/stats_of.hpp): the median found through bins is the partial sort's, bit for bit,
// on odd and even sizes, ties, narrow and wide ranges, subnormal widths, negatives; a NaN or a negative zero
// takes the partial sort itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "preproc/stats_of.hpp"

namespace test_stats_of_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// The median as stats_of computed it before the bins: nth_element on a copy, then the lower half's largest.
double sorted_median(std::vector<double> v) {
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
    return m;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("stats_of: the median of doubles through bins equals the partial sort's bit for bit") {
    std::mt19937_64 rng(4040);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::lognormal_distribution<double> wide(0.0, 3.0);
    for (const std::size_t size : {2u, 3u, 8u, 999u, 1000u, 20001u, 20002u}) {
        for (int kind = 0; kind < 8; ++kind) {
            std::vector<double> v(size);
            for (auto& x : v) {
                switch (kind) {
                    case 0: x = 8.9e-4 * (1 + 0.1 * unit(rng)); break;       // distances of a jittered lattice
                    case 1: x = wide(rng); break;                            // heavy tails
                    case 2: x = std::floor(unit(rng) * 5) * 0.1; break;      // a few values, many ties
                    case 3: x = 1e-6; break;                                 // all equal
                    case 4: x = unit(rng) < 0.999 ? 1.0 : 1e300; break;      // one far value
                    case 5: x = (unit(rng) - 0.5) * 1e-310; break;           // subnormals, signs
                    case 6: x = -wide(rng); break;                           // negatives
                    default: x = 1.0 + std::floor(unit(rng) * 3) * 0x1p-52;  // ulps apart
                }
            }
            CAPTURE(size);
            CAPTURE(kind);
            const preproc::Stats s = preproc::stats_of(v);
            CHECK(same_bits(s.median, sorted_median(v)));
            CHECK(s.min == *std::min_element(v.begin(), v.end()));
            CHECK(s.max == *std::max_element(v.begin(), v.end()));
        }
    }
}

TEST_CASE("stats_of: a negative zero or a NaN leaves the median to the partial sort") {
    std::vector<double> v = {0.0, -0.0, 0.0, 1.0, -0.0, 2.0};
    CHECK(same_bits(preproc::stats_of(v).median, sorted_median(v)));
    v = {3.0, 1.0, std::numeric_limits<double>::quiet_NaN(), 2.0, 5.0};
    CHECK(same_bits(preproc::stats_of(v).median, sorted_median(v)));
    for (std::size_t at = 0; at < 6; ++at) {  // one value and a NaN
        v.assign(6, 2.5);
        v[at] = std::numeric_limits<double>::quiet_NaN();
        CHECK(same_bits(preproc::stats_of(v).median, sorted_median(v)));
    }
}

}  // namespace test_stats_of_cpp
