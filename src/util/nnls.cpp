#include "util/nnls.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace zc {

namespace {

Eigen::MatrixXd to_eigen(const Matrix& A, const char* who) {
  if (A.empty()) throw std::invalid_argument(std::string(who) + ": rows of A and b differ");
  const std::size_t n = A[0].size();
  Eigen::MatrixXd M(Eigen::Index(A.size()), Eigen::Index(n));
  for (std::size_t r = 0; r < A.size(); ++r) {
    if (A[r].size() != n) throw std::invalid_argument(std::string(who) + ": ragged matrix");
    for (std::size_t j = 0; j < n; ++j)
      M(Eigen::Index(r), Eigen::Index(j)) = A[r][j];
  }
  return M;
}

// Least squares on the columns in `free` of A with the right-hand side rhs, by a rank-revealing
// QR of those columns (column-pivoted Householder: the condition number is not squared, as the
// normal equations would). A direction the columns do not determine gets 0; columns outside the
// set get 0.
Eigen::VectorXd ls_on(const Eigen::MatrixXd& A, const Eigen::VectorXd& rhs,
                      const std::vector<bool>& free) {
  std::vector<Eigen::Index> cols;
  for (std::size_t j = 0; j < free.size(); ++j)
    if (free[j]) cols.push_back(Eigen::Index(j));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(A.cols());
  if (cols.empty()) return x;
  Eigen::MatrixXd S(A.rows(), Eigen::Index(cols.size()));
  for (std::size_t k = 0; k < cols.size(); ++k)
    S.col(Eigen::Index(k)) = A.col(cols[k]);
  const Eigen::VectorXd z = S.colPivHouseholderQr().solve(rhs);
  for (std::size_t k = 0; k < cols.size(); ++k)
    x(cols[k]) = std::isfinite(z(Eigen::Index(k))) ? z(Eigen::Index(k)) : 0.0;
  return x;
}

// min |A x - b| subject to lo <= x <= hi (entries may be infinite): the active-set method of
// Lawson & Hanson (1974, ch. 23) with both bounds (Stark & Parker's BVLS, 1995), each step's least
// squares on a QR. A variable leaves its bound when the gradient pulls it inwards; a step that
// would cross a bound stops there and fixes the variables it reached.
Eigen::VectorXd active_set(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                           const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  const Eigen::Index n = A.cols();
  enum State { Lower, Upper, Free };
  std::vector<State> state(std::size_t(n), Lower);
  Eigen::VectorXd x(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    // Start at the finite bound nearest 0 (NNLS: every variable at 0).
    if (std::isfinite(lo(j))) {
      x(j) = lo(j);
    } else if (std::isfinite(hi(j))) {
      x(j) = hi(j);
      state[std::size_t(j)] = Upper;
    } else {
      x(j) = 0;
      state[std::size_t(j)] = Free;
    }
  }
  const double tol = 1e-12 * std::max(1.0, A.cwiseAbs().maxCoeff()) * double(A.rows() * n);
  const int limit = 3 * int(n) + 10;
  auto solve_free = [&] {
    std::vector<bool> free(static_cast<std::size_t>(n), false);
    Eigen::VectorXd rhs = b;
    for (Eigen::Index j = 0; j < n; ++j) {
      free[std::size_t(j)] = state[std::size_t(j)] == Free;
      if (!free[std::size_t(j)]) rhs -= A.col(j) * x(j);
    }
    Eigen::VectorXd z = ls_on(A, rhs, free);
    for (Eigen::Index j = 0; j < n; ++j)
      if (!free[std::size_t(j)]) z(j) = x(j);
    return z;
  };
  for (int outer = 0; outer < limit; ++outer) {
    // The gradient of -|A x - b|^2 / 2: where it points into the box, the bound can be left.
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    Eigen::Index best = -1;
    double wmax = tol;
    for (Eigen::Index j = 0; j < n; ++j) {
      const State s = state[std::size_t(j)];
      const double pull = s == Lower ? w(j) : s == Upper ? -w(j) : 0.0;
      if (pull > wmax) {
        wmax = pull;
        best = j;
      }
    }
    if (best < 0) break; // Kuhn-Tucker conditions hold
    state[std::size_t(best)] = Free;
    for (int inner = 0; inner < limit; ++inner) {
      const Eigen::VectorXd z = solve_free();
      double alpha = 1;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (state[std::size_t(j)] != Free || z(j) == x(j)) continue;
        if (z(j) < lo(j)) alpha = std::min(alpha, (lo(j) - x(j)) / (z(j) - x(j)));
        if (z(j) > hi(j)) alpha = std::min(alpha, (hi(j) - x(j)) / (z(j) - x(j)));
      }
      alpha = std::clamp(alpha, 0.0, 1.0);
      if (alpha >= 1) {
        x = z;
        break;
      }
      // Step towards z as far as the box allows; the variables that reached a bound stay there.
      x += alpha * (z - x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (state[std::size_t(j)] != Free) continue;
        const double eps = 1e-15 * std::max(1.0, std::fabs(z(j)));
        if (x(j) <= lo(j) + eps) {
          x(j) = lo(j);
          state[std::size_t(j)] = Lower;
        } else if (x(j) >= hi(j) - eps) {
          x(j) = hi(j);
          state[std::size_t(j)] = Upper;
        }
      }
    }
  }
  return x;
}

std::vector<double> to_vector(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

Eigen::VectorXd to_eigen(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
}

} // namespace

std::vector<double> nnls(const Matrix& A, const std::vector<double>& b) {
  if (A.empty() || A.size() != b.size())
    throw std::invalid_argument("nnls: rows of A and b differ");
  const Eigen::MatrixXd M = to_eigen(A, "nnls");
  const Eigen::Index n = M.cols();
  return to_vector(
      active_set(M, to_eigen(b), Eigen::VectorXd::Zero(n),
                 Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity())));
}

std::vector<double> bounded_lsq(const Matrix& A, const std::vector<double>& b,
                                const std::vector<double>& lo, const std::vector<double>& hi) {
  if (A.empty() || A.size() != b.size())
    throw std::invalid_argument("bounded_lsq: rows of A and b differ");
  const Eigen::MatrixXd M = to_eigen(A, "bounded_lsq");
  const std::size_t n = std::size_t(M.cols());
  if (lo.size() != n || hi.size() != n) throw std::invalid_argument("bounded_lsq: bounds size");
  for (std::size_t j = 0; j < n; ++j)
    if (!(lo[j] <= hi[j])) throw std::invalid_argument("bounded_lsq: empty bound");
  return to_vector(active_set(M, to_eigen(b), to_eigen(lo), to_eigen(hi)));
}

} // namespace zc
