// The solver's small tensors with Eigen's fixed-size types (Matrix3d, Vector3d). The particle arrays
// keep their flat storage (the SIMD pair rows read 6 doubles per particle: pair_rows.hpp), so these
// helpers view that storage as Eigen matrices:
//   symmetric tensors as xx yy zz xy xz yz (std::array<double, 6>: the FORM 1 correction B^-1, the
//   deviatoric stress S), full tensors row-major (std::array<double, 9>: the velocity gradient).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // determinant
#include <array>

namespace sphdeck::refsolver {

using RowMajorMatrix3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// The full matrix of a symmetric tensor stored as xx yy zz xy xz yz.
inline Eigen::Matrix3d symmetric_matrix(const std::array<double, 6>& s) {
    Eigen::Matrix3d m;
    m << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
    return m;
}

// The six entries (xx yy zz xy xz yz) of a symmetric matrix, read from its upper triangle.
inline std::array<double, 6> symmetric_entries(const Eigen::Matrix3d& m) {
    return {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2)};
}

// A row-major 3x3 tensor's storage seen as a matrix.
inline Eigen::Map<const RowMajorMatrix3d> tensor_view(const std::array<double, 9>& t) {
    return Eigen::Map<const RowMajorMatrix3d>(t.data());
}
inline Eigen::Map<RowMajorMatrix3d> tensor_view(std::array<double, 9>& t) {
    return Eigen::Map<RowMajorMatrix3d>(t.data());
}

// The adjugate of a symmetric 3x3 matrix (its cofactors: row k is the cross product of the other
// two columns), so that M^-1 = adj(M) / det(M) with det(M) = col0 . (col1 x col2).
inline Eigen::Matrix3d symmetric_adjugate(const Eigen::Matrix3d& m) {
    Eigen::Matrix3d adj;
    adj.row(0) = m.col(1).cross(m.col(2)).transpose();
    adj.row(1) = m.col(2).cross(m.col(0)).transpose();
    adj.row(2) = m.col(0).cross(m.col(1)).transpose();
    return adj;
}

}  // namespace sphdeck::refsolver
