// The id index (model/id_index.hpp) answers the same for a column kept as first + step * i (found by
// arithmetic, issue 40) as for the same ids written out (a table or a sorted copy): the position of
// every id, nothing for any other, and no duplicates.
#include <doctest/doctest.h>

#include <climits>
#include <random>
#include <vector>

#include "model/id_index.hpp"

namespace test_id_index_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// A compacted column of `n` ids first + step * i (compact() keeps columns of 16384 entries or more).
model::IdColumn sequence_column(long long first, long long step, std::size_t n) {
    model::IdColumn c;
    for (std::size_t i = 0; i < n; ++i) c.push_back(first + step * static_cast<long long>(i));
    REQUIRE(c.compact());
    return c;
}

std::vector<long long> written_out(const model::IdColumn& c) { return {c.begin(), c.end()}; }

}  // namespace

TEST_CASE("an id index over a sequence finds what the written-out ids' index finds") {
    struct Case {
        long long first, step;
    };
    const Case cases[] = {{1, 1}, {0, 1}, {-20000, 1}, {1000, 3}, {7, -1}, {50000, -7}, {-3, 2}};
    std::mt19937_64 random(40);
    for (const Case& c : cases) {
        CAPTURE(c.first);
        CAPTURE(c.step);
        const std::size_t n = 20000;
        const model::IdColumn column = sequence_column(c.first, c.step, n);
        const model::IdIndex by_arithmetic(column);
        const model::IdIndex by_table(written_out(column));
        CHECK(by_arithmetic.duplicates().empty());
        CHECK(model::find_duplicate_ids(column).empty());
        const long long lo = std::min(column.front(), column.back()), hi = std::max(column.front(), column.back());
        // Every id near and inside the range (between the steps too), then random and extreme ones.
        std::vector<long long> probes;
        for (long long id = lo - 10; id <= lo + 50; ++id) probes.push_back(id);
        for (long long id = hi - 50; id <= hi + 10; ++id) probes.push_back(id);
        for (int k = 0; k < 20000; ++k)
            probes.push_back(lo - 100 +
                             static_cast<long long>(random() % static_cast<unsigned long long>(hi - lo + 200)));
        for (long long id : {LLONG_MIN, LLONG_MIN + 1, LLONG_MAX, LLONG_MAX - 1, -1LL, 0LL}) probes.push_back(id);
        std::size_t found = 0, differ = 0;
        for (long long id : probes) {
            const auto a = by_arithmetic.find(id), b = by_table.find(id);
            if (a != b) ++differ;
            if (a) {
                ++found;
                CHECK(column[*a] == id);
            }
        }
        CHECK(differ == 0);
        CHECK(found > 1000);  // the probes hit the column, not only its gaps
    }
}

TEST_CASE("an id column of one id repeated is indexed as written: its duplicates found") {
    model::IdColumn same;
    for (int i = 0; i < 20000; ++i) same.push_back(5);
    REQUIRE(same.compact());  // step 0: a sequence, but not an arithmetic index
    const model::IdIndex index(same);
    CHECK(index.find(5) == std::optional<std::size_t>(0));
    CHECK_FALSE(index.find(6));
    CHECK(index.duplicates().size() == 19999);
    CHECK_FALSE(model::find_duplicate_ids(same).empty());
}

}  // namespace test_id_index_cpp
