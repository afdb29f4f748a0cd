// Means and centred cross products of K aligned quantities, accumulated one sample at a time:
// Welford's update generalised to co-moments (Chan, Golub & LeVeque 1983, "Algorithms for
// computing the sample variance"): n ← n + 1, d = x − x̄, x̄ ← x̄ + d/n, S ← S + d·(x − x̄)ᵀ.
// They are the normal equations of a least-squares fit with a constant, centred (no
// cancellation between large means), without the n × K samples in memory.
#pragma once

#include <Eigen/Dense>
#include <cstddef>

namespace uuvplan::ident {

template <int K>
class CentredMoments {
 public:
  using Vector = Eigen::Matrix<double, K, 1>;
  using Matrix = Eigen::Matrix<double, K, K>;

  void Add(const Vector& x) {
    ++n_;
    const Vector d = x - mean_;
    mean_ += d / static_cast<double>(n_);
    scatter_ += d * (x - mean_).transpose();
  }
  std::size_t count() const { return n_; }
  const Vector& mean() const { return mean_; }
  /// Σ (x − x̄)(x − x̄)ᵀ, symmetrised.
  Matrix scatter() const { return 0.5 * (scatter_ + scatter_.transpose()); }

 private:
  std::size_t n_ = 0;
  Vector mean_ = Vector::Zero();
  Matrix scatter_ = Matrix::Zero();
};

}  // namespace uuvplan::ident
