// The automatic thread count of the reference solver (refsolver/core_share.hpp): as many threads as
// the cores other processes leave free, never more than allowed, never fewer than one.
#include <doctest/doctest.h>

#include <chrono>
#include <thread>

#include "refsolver/core_share.hpp"

namespace test_refsolver_core_share_cpp {  // each test file's names stay its own in a unity batch

using sphdeck::refsolver::CoreShare;

TEST_CASE("refsolver core share: free cores from the load of other processes") {
    CHECK(CoreShare::free_cores(2, 0.0, 2) == 2);
    CHECK(CoreShare::free_cores(2, 0.2, 2) == 2);   // a little noise keeps both
    CHECK(CoreShare::free_cores(2, 1.0, 2) == 1);   // a busy loop on one core: one thread, not a 9x collapse
    CHECK(CoreShare::free_cores(2, 0.5, 2) == 1);   // a core half taken still stalls a static schedule
    CHECK(CoreShare::free_cores(2, 3.0, 2) == 1);   // never fewer than one
    CHECK(CoreShare::free_cores(8, 0.0, 2) == 2);   // never more than allowed (OMP_NUM_THREADS)
    CHECK(CoreShare::free_cores(2, -0.1, 2) == 2);  // tick jitter can make the others' load negative
}

TEST_CASE("refsolver core share: one thread until the first window, then within bounds") {
    CoreShare one(1);
    CHECK(one.threads() == 1);
    CoreShare two(2);
    CHECK(two.threads() == 1);
    std::this_thread::sleep_for(std::chrono::duration<double>(CoreShare::window_seconds + 0.05));
    const int n = two.threads();
    CHECK(n >= 1);
    CHECK(n <= 2);
}
}  // namespace test_refsolver_core_share_cpp
