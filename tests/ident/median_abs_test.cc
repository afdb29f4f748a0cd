// MedianAbs (ident/stats/median_abs.h) picks what std::nth_element picks from a float copy of |r|:
// the radix selection must agree element for element, ties, zeros, signs and wide ranges
// included (the output error's gross-error limit is 6·1.4826 times it).
#include "uuvplan/ident/stats/median_abs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace uuvplan::ident {
namespace {

double CopiedMedianAbs(const Eigen::VectorXd& r) {
  std::vector<float> a(r.size());
  for (Eigen::Index i = 0; i < r.size(); ++i) a[i] = static_cast<float>(std::abs(r[i]));
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(a.size() / 2), a.end());
  return a[a.size() / 2];
}

TEST(MedianAbsTest, AgreesWithSelectionFromACopy) {
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_int_distribution<int> small(-3, 3);
  for (const int n : {1, 2, 3, 4, 5, 10, 11, 1000, 1001, 30001}) {
    Eigen::VectorXd normal(n), ties(n), wide(n);
    for (int i = 0; i < n; ++i) {
      normal[i] = 0.01 * gauss(rng);
      ties[i] = small(rng);                                      // many equal values and zeros
      wide[i] = std::exp(20.0 * gauss(rng)) * (i % 2 ? -1 : 1);  // 1e-40 .. 1e40: every exponent
    }
    for (const Eigen::VectorXd* r : {&normal, &ties, &wide}) {
      EXPECT_EQ(MedianAbs(*r), CopiedMedianAbs(*r)) << "n = " << n;
    }
  }
  EXPECT_EQ(MedianAbs(Eigen::VectorXd()), 0.0);
}

}  // namespace
}  // namespace uuvplan::ident
