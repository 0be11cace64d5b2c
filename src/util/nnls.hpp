#pragma once
// Least squares under bounds for the calibration. Non-negative least squares, min |A x - b|^2
// subject to x >= 0 (Lawson & Hanson 1974, ch. 23), for the calibration's small dense systems (tens
// of rows, a handful of unknowns).
#include <vector>

namespace zc {

using Matrix = std::vector<std::vector<double>>; // row-major: A[row][column]

// x >= 0 minimising |A x - b|; A is m x n with m >= 1. Throws std::invalid_argument on ragged
// input.
std::vector<double> nnls(const Matrix& A, const std::vector<double>& b);

// x within lo <= x <= hi minimising |A x - b| (bounded least squares: the calibration keeps every
// multiplier inside the plausible range of its physical estimate). Exact for the handful of
// unknowns it is used with (it tries every assignment of the variables to free/lower/upper).
std::vector<double> bounded_lsq(const Matrix& A, const std::vector<double>& b,
                                const std::vector<double>& lo, const std::vector<double>& hi);

} // namespace zc
