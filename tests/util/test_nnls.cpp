// util/nnls: non-negative and bounded least squares against their optimality conditions.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "csv.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/paper_figures.hpp"
#include "repro/regress.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

TEST(Nnls, EqualsLeastSquaresWhenThatIsNonNegative) {
  // Exact system: x = (1, 2).
  const Matrix A = {{1, 0}, {0, 1}, {1, 1}};
  const auto x = nnls(A, {1, 2, 3});
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[1], 2, 1e-12);
}

TEST(Nnls, ClampsANegativeComponentAndMeetsTheKuhnTuckerConditions) {
  // Unconstrained least squares gives x1 < 0; NNLS must give x1 = 0, x0 = argmin over x0 alone.
  const Matrix A = {{1, 1}, {1, 2}, {1, 3}};
  const std::vector<double> b = {3, 2, 1};
  const auto x = nnls(A, b);
  EXPECT_EQ(x[1], 0);
  EXPECT_NEAR(x[0], 2, 1e-12); // mean of b
  // Gradient A^T (b - A x) <= 0 on the clamped component.
  double g1 = 0;
  for (int r = 0; r < 3; ++r)
    g1 += A[r][1] * (b[r] - A[r][0] * x[0]);
  EXPECT_LE(g1, 1e-12);
  EXPECT_THROW(nnls({{1, 2}, {3}}, {1, 2}), std::invalid_argument);
}

TEST(BoundedLsq, StaysInsideItsBoxAndFindsTheInteriorOptimum) {
  const Matrix A = {{1, 0}, {0, 1}, {1, 1}};
  // Unconstrained optimum (1, 2) lies inside [0, 3]^2.
  auto x = bounded_lsq(A, {1, 2, 3}, {0, 0}, {3, 3});
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[1], 2, 1e-12);
  // With x1 <= 1.5 the optimum moves to the bound and x0 compensates: minimise
  // (x0-1)^2 + (1.5-2)^2 + (x0+1.5-3)^2 -> x0 = 1.25.
  x = bounded_lsq(A, {1, 2, 3}, {0, 0}, {3, 1.5});
  EXPECT_NEAR(x[0], 1.25, 1e-12);
  EXPECT_DOUBLE_EQ(x[1], 1.5);
  EXPECT_THROW(bounded_lsq(A, {1, 2, 3}, {1, 0}, {0, 1}), std::invalid_argument);
}

TEST(BoundedLsq, MeetsTheKuhnTuckerConditionsOnRandomIllScaledProblems) {
  // At the optimum of a box-constrained least squares, the gradient A^T (b - A x) is 0 on a free
  // variable, <= 0 at a lower bound and >= 0 at an upper one; columns scaled 1e-3..1e3 apart would
  // lose those digits to the normal equations' squared condition number.
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0, 1);
  for (int t = 0; t < 300; ++t) {
    const int n = 1 + t % 6, m = n + 4 + t % 5;
    Matrix A(m, std::vector<double>(n));
    std::vector<double> b(m), lo(n, 0.5), hi(n, 2.0);
    for (auto& row : A)
      for (int j = 0; j < n; ++j)
        row[j] = std::fabs(normal(rng)) * std::pow(10.0, 3 * (j % 3) - 3);
    for (auto& v : b)
      v = 3 * normal(rng);
    const auto x = bounded_lsq(A, b, lo, hi);
    for (int j = 0; j < n; ++j) {
      double w = 0, scale = 0;
      for (int r = 0; r < m; ++r) {
        double e = b[r];
        for (int k = 0; k < n; ++k)
          e -= A[r][k] * x[k];
        w += A[r][j] * e;
        scale += std::fabs(A[r][j]) * (std::fabs(b[r]) + 1);
      }
      const double tol = 1e-9 * scale;
      ASSERT_GE(x[j], lo[j]);
      ASSERT_LE(x[j], hi[j]);
      if (x[j] == lo[j])
        EXPECT_LE(w, tol) << t << " " << j;
      else if (x[j] == hi[j])
        EXPECT_GE(w, -tol) << t << " " << j;
      else
        EXPECT_NEAR(w, 0, tol) << t << " " << j;
    }
  }
}
