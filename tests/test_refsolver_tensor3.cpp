// The Eigen views of the solver's small tensors (refsolver/tensor3.hpp): symmetric storage
// (xx yy zz xy xz yz), row-major 3x3 storage and the adjugate of a symmetric matrix.
#include <doctest/doctest.h>

#include <cmath>

#include "refsolver/tensor3.hpp"

namespace test_refsolver_tensor3_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::refsolver;

TEST_CASE("refsolver tensor3: symmetric storage, row-major views and the adjugate") {
    const std::array<double, 6> b{2.0, 3.0, 4.0, 0.5, -0.25, 0.75};  // xx yy zz xy xz yz
    const Eigen::Matrix3d m = symmetric_matrix(b);
    CHECK(m(1, 0) == 0.5);
    CHECK(m(2, 0) == -0.25);
    CHECK(m(2, 1) == 0.75);
    CHECK(symmetric_entries(m) == b);
    const double det = m.determinant();
    CHECK((symmetric_adjugate(m) * m - det * Eigen::Matrix3d::Identity()).norm() < 1e-12);
    std::array<double, 9> t{1, 2, 3, 4, 5, 6, 7, 8, 9};
    CHECK(tensor_view(t)(0, 1) == 2.0);  // row-major
    CHECK(tensor_view(t)(1, 0) == 4.0);
    tensor_view(t)(2, 2) = -1;
    CHECK(t[8] == -1.0);
}
}  // namespace test_refsolver_tensor3_cpp
