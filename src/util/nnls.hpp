#pragma once
// Least squares under bounds for the calibration and the probe. Non-negative least squares, min
// |A x - b|^2 subject to x >= 0 (Lawson & Hanson 1974, ch. 23), and its two-bound form (Stark &
// Parker's BVLS): one active-set method, each step's least squares on Eigen's column-pivoted QR.
#include <vector>

namespace zc {

using Matrix = std::vector<std::vector<double>>; // row-major: A[row][column]

// x >= 0 minimising |A x - b|; A is m x n with m >= 1. Throws std::invalid_argument on ragged
// input.
std::vector<double> nnls(const Matrix& A, const std::vector<double>& b);

// x within lo <= x <= hi minimising |A x - b| (bounded least squares: the calibration keeps every
// multiplier inside the plausible range of its physical estimate).
std::vector<double> bounded_lsq(const Matrix& A, const std::vector<double>& b,
                                const std::vector<double>& lo, const std::vector<double>& hi);

} // namespace zc
