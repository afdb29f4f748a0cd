// The concrete force terms (force_term.h), visible to the model library only: DofModel holds
// them by their final type so that the hot simulation loop calls them without virtual dispatch.
// Each states its equation and source.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/force_term.h"
#include "uuvplan/model/mapping.h"

namespace uuvplan::model::internal {

// -k·xi - kq·xi·|xi| (ref 000 eq. 3); asymmetric: (k, kq) for xi >= 0, (k_neg, kq_neg) below.
class DragTerm final : public ForceTerm {
 public:
  DragTerm(bool linear, bool quadratic, bool asymmetric)
      : ForceTerm(Names(linear, quadratic, asymmetric)),
        lin_(linear ? 0 : -1),
        quad_(quadratic ? (linear ? (asymmetric ? 2 : 1) : 0) : -1),
        asym_(asymmetric) {}

  double Value(const TermInputs& c, const double* theta) const override {
    // Both sides' coefficients are loaded before the sign of xi selects one, so the select
    // (not an indexed load) sits on the simulation's dependency chain.
    const bool neg = c.xi < 0;
    double f = 0.0;
    if (lin_ >= 0) f -= Select(theta, lin_, neg) * c.xi;
    if (quad_ >= 0) f -= Select(theta, quad_, neg) * c.xi * std::abs(c.xi);
    return f;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    for (int i = 0; i < num_parameters(); ++i) J[i] = 0.0;
    const int side = asym_ && c.xi < 0 ? 1 : 0;
    TermPartials p;
    if (lin_ >= 0) {
      J[lin_ + side] = -c.xi;
      p.value -= theta[lin_ + side] * c.xi;
      p.d_xi -= theta[lin_ + side];
    }
    if (quad_ >= 0) {
      J[quad_ + side] = -c.xi * std::abs(c.xi);
      p.value -= theta[quad_ + side] * c.xi * std::abs(c.xi);
      p.d_xi -= 2.0 * theta[quad_ + side] * std::abs(c.xi);
    }
    return p;
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    for (int i = 0; i < num_parameters(); ++i) h[i] = 0.0;
    const int side = asym_ && c.xi < 0 ? 1 : 0;
    if (lin_ >= 0) h[lin_ + side] = -c.xi;
    if (quad_ >= 0) h[quad_ + side] = -c.xi * std::abs(c.xi);
    *h0 = 0.0;
    return true;
  }

 private:
  static std::vector<std::string> Names(bool linear, bool quadratic, bool asymmetric) {
    std::vector<std::string> n;
    if (linear) n.push_back(param::kLinearDrag);
    if (linear && asymmetric) n.push_back(param::kLinearDragNeg);
    if (quadratic) n.push_back(param::kQuadraticDrag);
    if (quadratic && asymmetric) n.push_back(param::kQuadraticDragNeg);
    return n;
  }
  double Select(const double* theta, int i, bool neg) const {
    const double pos = theta[i];
    const double other = asym_ ? theta[i + 1] : pos;
    return neg ? other : pos;
  }
  int lin_, quad_;  // offsets of k and kq (k_neg, kq_neg follow each when asymmetric)
  bool asym_;
};

// eta(mu, sign phi)·phi (ref 000 eq. 3); eta = 1 in open water, else a parameter.
class ThrustTerm final : public ForceTerm {
 public:
  ThrustTerm(std::vector<std::string> names, std::vector<std::array<int, 2>> index)
      : ForceTerm(std::move(names)), index_(std::move(index)) {}

  double Value(const TermInputs& c, const double* theta) const override {
    const int j = ParamFor(c);
    return (j < 0 ? 1.0 : theta[j]) * c.phi;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    for (int i = 0; i < num_parameters(); ++i) J[i] = 0.0;
    const int j = ParamFor(c);
    const double eta = j < 0 ? 1.0 : theta[j];
    if (j >= 0) J[j] = c.phi;
    return {eta * c.phi, 0.0, eta};
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    for (int i = 0; i < num_parameters(); ++i) h[i] = 0.0;
    const int j = ParamFor(c);
    if (j < 0) {
      *h0 = c.phi;
    } else {
      h[j] = c.phi;
      *h0 = 0.0;
    }
    return true;
  }

 private:
  int ParamFor(const TermInputs& c) const {
    if (c.mapping < 0 || c.mapping >= static_cast<int>(index_.size())) return -1;
    return index_[c.mapping][c.phi >= 0 ? 0 : 1];
  }
  std::vector<std::array<int, 2>> index_;  // [mapping][pos, neg] -> parameter or -1
};

// bias + bias_step·ballast_steps (ref 000 eq. 7, eq. 20).
class ConstantTerm final : public ForceTerm {
 public:
  ConstantTerm(bool bias, bool ballast)
      : ForceTerm(Names(bias, ballast)),
        bias_(bias ? 0 : -1),
        step_(ballast ? (bias ? 1 : 0) : -1) {}
  double Value(const TermInputs& c, const double* theta) const override {
    double f = 0.0;
    if (bias_ >= 0) f += theta[bias_];
    if (step_ >= 0) f += theta[step_] * c.ballast_steps;
    return f;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    double h0;
    Regressor(c, J, &h0);
    return {Value(c, theta), 0.0, 0.0};
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    if (bias_ >= 0) h[bias_] = 1.0;
    if (step_ >= 0) h[step_] = c.ballast_steps;
    *h0 = 0.0;
    return true;
  }

 private:
  static std::vector<std::string> Names(bool bias, bool ballast) {
    std::vector<std::string> n;
    if (bias) n.push_back(param::kBias);
    if (ballast) n.push_back(param::kBiasStep);
    return n;
  }
  int bias_, step_;
};

// -c_a·sqrt(|phi_a|)·xi: ref 000 eq. 5 with |n| ∝ sqrt(|phi|) and v_a = xi. |phi| is
// smoothed as sqrt(phi² + eps²) so the partial in phi stays finite at phi = 0.
class AdvanceLossTerm final : public ForceTerm {
 public:
  AdvanceLossTerm() : ForceTerm({param::kAdvanceLoss}) {}
  double Value(const TermInputs& c, const double* theta) const override {
    return -theta[0] * Root(c.phi) * c.xi;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    const double r = Root(c.phi);
    J[0] = -r * c.xi;
    const double a = std::sqrt(c.phi * c.phi + kEps * kEps);
    const double dr_dphi = 0.5 / r * c.phi / a;
    return {-theta[0] * r * c.xi, -theta[0] * r, -theta[0] * c.xi * dr_dphi};
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    h[0] = -Root(c.phi) * c.xi;
    *h0 = 0.0;
    return true;
  }

 private:
  static constexpr double kEps = 1e-3;  // N: far below any working thrust
  static double Root(double phi) { return std::sqrt(std::sqrt(phi * phi + kEps * kEps)); }
};

// Σ c_ab·a·b with a, b velocities (ref 003: surge (m - Y_v̇)·v·r, (m·x_g - Y_ṙ)·r²;
// yaw -(m·x_g - Y_ṙ)·u·r, -(X_u̇ - Y_v̇)·u·v).
class CouplingTerm final : public ForceTerm {
 public:
  CouplingTerm(Dof own, const std::vector<std::string>& pairs)
      : ForceTerm(Names(pairs)), own_(Index(own)) {
    for (const auto& p : pairs) {
      if (p.size() != 2) throw std::invalid_argument("coupling needs two velocity letters: " + p);
      pairs_.push_back({LetterIndex(p[0]), LetterIndex(p[1])});
    }
  }
  bool NeedsOtherVelocities() const override { return true; }
  double Value(const TermInputs& c, const double* theta) const override {
    double f = 0.0;
    for (std::size_t j = 0; j < pairs_.size(); ++j) f += theta[j] * Product(c, j);
    return f;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    TermPartials p;
    for (std::size_t j = 0; j < pairs_.size(); ++j) {
      J[j] = Product(c, j);
      p.value += theta[j] * J[j];
      // d(a·b)/dxi: each factor that is the own DOF contributes the other factor.
      const auto [a, b] = pairs_[j];
      if (a == own_) p.d_xi += theta[j] * V(c, b);
      if (b == own_) p.d_xi += theta[j] * V(c, a);
    }
    return p;
  }
  void OtherVelocityPartials(const TermInputs& c, const double* theta,
                             double* J_F_v) const override {
    // d(a·b)/d(other velocity): each factor that is not the own DOF contributes the other one.
    for (std::size_t j = 0; j < pairs_.size(); ++j) {
      const auto [a, b] = pairs_[j];
      if (a != own_) J_F_v[a] += theta[j] * V(c, b);
      if (b != own_) J_F_v[b] += theta[j] * V(c, a);
    }
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    for (std::size_t j = 0; j < pairs_.size(); ++j) h[j] = Product(c, j);
    *h0 = 0.0;
    return true;
  }

 private:
  static std::vector<std::string> Names(const std::vector<std::string>& pairs) {
    std::vector<std::string> n;
    for (const auto& p : pairs) n.push_back(param::kCouplingPrefix + p);
    return n;
  }
  static int LetterIndex(char l) {
    for (Dof d : kAllDofs) {
      if (VelocityLetter(d) == l) return Index(d);
    }
    throw std::invalid_argument(std::string("unknown velocity letter '") + l + "'");
  }
  double V(const TermInputs& c, int i) const { return i == own_ ? c.xi : c.velocities[i]; }
  double Product(const TermInputs& c, std::size_t j) const {
    return V(c, pairs_[j].first) * V(c, pairs_[j].second);
  }
  int own_;
  std::vector<std::pair<int, int>> pairs_;
};

// drift·t_c·phi_a: thrust changing slowly over the campaign (battery), t_c campaign clock.
class DriftTerm final : public ForceTerm {
 public:
  DriftTerm() : ForceTerm({param::kDrift}) {}
  double Value(const TermInputs& c, const double* theta) const override {
    return theta[0] * c.t_campaign * c.phi;
  }
  TermPartials Partials(const TermInputs& c, const double* theta, double* J) const override {
    J[0] = c.t_campaign * c.phi;
    return {theta[0] * J[0], 0.0, theta[0] * c.t_campaign};
  }
  bool Regressor(const TermInputs& c, double* h, double* h0) const override {
    h[0] = c.t_campaign * c.phi;
    *h0 = 0.0;
    return true;
  }
};

/// The thrust term with its [mapping][pos, neg] -> parameter index table.
inline std::unique_ptr<ThrustTerm> MakeThrust(const std::vector<std::string>& mapping_names,
                                              const std::vector<std::string>& free_eta) {
  std::vector<std::array<int, 2>> index(mapping_names.size(), {-1, -1});
  for (std::size_t m = 0; m < mapping_names.size(); ++m) {
    for (std::size_t j = 0; j < free_eta.size(); ++j) {
      if (free_eta[j] == EtaName(mapping_names[m], Direction::kPos)) index[m][0] = int(j);
      if (free_eta[j] == EtaName(mapping_names[m], Direction::kNeg)) index[m][1] = int(j);
    }
  }
  return std::make_unique<ThrustTerm>(free_eta, std::move(index));
}

}  // namespace uuvplan::model::internal
