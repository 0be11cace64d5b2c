#include "util/nnls.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace zc {

namespace {

// Unconstrained least squares on the columns in `set` (normal equations, Gaussian elimination
// with partial pivoting: n is tiny). Columns outside the set get 0.
std::vector<double> ls_on(const Matrix& A, const std::vector<double>& b,
                          const std::vector<bool>& set) {
  const std::size_t n = set.size();
  std::vector<std::size_t> cols;
  for (std::size_t j = 0; j < n; ++j)
    if (set[j]) cols.push_back(j);
  const std::size_t k = cols.size();
  std::vector<std::vector<double>> M(k, std::vector<double>(k + 1, 0.0));
  for (std::size_t r = 0; r < A.size(); ++r)
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j)
        M[i][j] += A[r][cols[i]] * A[r][cols[j]];
      M[i][k] += A[r][cols[i]] * b[r];
    }
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < k; ++r)
      if (std::fabs(M[r][c]) > std::fabs(M[p][c])) p = r;
    std::swap(M[c], M[p]);
    if (std::fabs(M[c][c]) < 1e-300) continue; // singular direction: leave it at 0
    for (std::size_t r = 0; r < k; ++r) {
      if (r == c) continue;
      const double f = M[r][c] / M[c][c];
      for (std::size_t j = c; j <= k; ++j)
        M[r][j] -= f * M[c][j];
    }
  }
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < k; ++i)
    x[cols[i]] = std::fabs(M[i][i]) < 1e-300 ? 0.0 : M[i][k] / M[i][i];
  return x;
}

} // namespace

std::vector<double> nnls(const Matrix& A, const std::vector<double>& b) {
  if (A.empty() || A.size() != b.size())
    throw std::invalid_argument("nnls: rows of A and b differ");
  const std::size_t n = A[0].size();
  for (const auto& row : A)
    if (row.size() != n) throw std::invalid_argument("nnls: ragged matrix");
  std::vector<double> x(n, 0.0);
  std::vector<bool> passive(n, false);
  double scale = 0;
  for (const auto& row : A)
    for (double v : row)
      scale = std::max(scale, std::fabs(v));
  const double tol = 1e-12 * std::max(1.0, scale) * double(A.size() * n);
  for (int outer = 0; outer < int(3 * n) + 10; ++outer) {
    // Gradient w = A^T (b - A x).
    std::vector<double> resid(b);
    for (std::size_t r = 0; r < A.size(); ++r)
      for (std::size_t j = 0; j < n; ++j)
        resid[r] -= A[r][j] * x[j];
    std::vector<double> w(n, 0.0);
    for (std::size_t r = 0; r < A.size(); ++r)
      for (std::size_t j = 0; j < n; ++j)
        w[j] += A[r][j] * resid[r];
    std::size_t best = n;
    double wmax = tol;
    for (std::size_t j = 0; j < n; ++j)
      if (!passive[j] && w[j] > wmax) {
        wmax = w[j];
        best = j;
      }
    if (best == n) break; // Kuhn-Tucker conditions hold
    passive[best] = true;
    for (int inner = 0; inner < int(3 * n) + 10; ++inner) {
      const std::vector<double> z = ls_on(A, b, passive);
      bool feasible = true;
      for (std::size_t j = 0; j < n; ++j)
        if (passive[j] && z[j] <= 0) feasible = false;
      if (feasible) {
        x = z;
        break;
      }
      // Step from x towards z as far as feasibility allows; drop the columns that hit zero.
      double alpha = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < n; ++j)
        if (passive[j] && z[j] <= 0) alpha = std::min(alpha, x[j] / (x[j] - z[j]));
      for (std::size_t j = 0; j < n; ++j) {
        x[j] += alpha * (z[j] - x[j]);
        if (passive[j] && x[j] <= 1e-15 * std::max(1.0, std::fabs(z[j]))) {
          passive[j] = false;
          x[j] = 0;
        }
      }
    }
  }
  return x;
}

} // namespace zc

namespace zc {

std::vector<double> bounded_lsq(const Matrix& A, const std::vector<double>& b,
                                const std::vector<double>& lo, const std::vector<double>& hi) {
  if (A.empty() || A.size() != b.size())
    throw std::invalid_argument("bounded_lsq: rows of A and b differ");
  const std::size_t n = A[0].size();
  if (lo.size() != n || hi.size() != n) throw std::invalid_argument("bounded_lsq: bounds size");
  for (std::size_t j = 0; j < n; ++j)
    if (!(lo[j] <= hi[j])) throw std::invalid_argument("bounded_lsq: empty bound");
  auto cost = [&](const std::vector<double>& x) {
    double s = 0;
    for (std::size_t r = 0; r < A.size(); ++r) {
      double e = -b[r];
      for (std::size_t j = 0; j < n; ++j)
        e += A[r][j] * x[j];
      s += e * e;
    }
    return s;
  };
  // The problem is convex: its minimum is the unconstrained minimum over the free variables of
  // one assignment of each variable to {free, at lo, at hi}. n is tiny (the cost groups), so every
  // assignment is tried (3^n) and the best feasible one kept.
  std::vector<double> best;
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<int> state(n, 0); // 0 free, 1 lo, 2 hi
  for (;;) {
    std::vector<double> rhs(b);
    std::vector<bool> freeset(n);
    for (std::size_t j = 0; j < n; ++j) {
      freeset[j] = state[j] == 0;
      if (state[j] == 0) continue;
      const double v = state[j] == 1 ? lo[j] : hi[j];
      for (std::size_t r = 0; r < A.size(); ++r)
        rhs[r] -= A[r][j] * v;
    }
    std::vector<double> x = ls_on(A, rhs, freeset);
    bool feasible = true;
    for (std::size_t j = 0; j < n; ++j) {
      if (state[j] == 1) x[j] = lo[j];
      if (state[j] == 2) x[j] = hi[j];
      if (x[j] < lo[j] - 1e-12 || x[j] > hi[j] + 1e-12) feasible = false;
    }
    if (feasible) {
      const double c = cost(x);
      if (c < best_cost) {
        best_cost = c;
        best = x;
      }
    }
    std::size_t j = 0;
    while (j < n && ++state[j] == 3)
      state[j++] = 0;
    if (j == n) break;
  }
  return best;
}

} // namespace zc
