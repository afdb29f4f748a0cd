#include "uuvplan/ident/estimators/regression.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::ident {

std::vector<int> LinearParameters(const model::DofModel& model) {
  std::vector<int> out;
  const model::TermInputs c;
  std::vector<double> h(model.num_parameters() + 1);
  for (std::size_t j = 0; j < model.terms().size(); ++j) {
    const auto& term = model.terms()[j];
    double h0 = 0.0;
    if (term->num_parameters() == 0 || !term->Regressor(c, h.data(), &h0)) continue;
    for (int i = 0; i < term->num_parameters(); ++i) out.push_back(model.term_offset(int(j)) + i);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void EvaluateRegressor(const model::DofModel& model, const model::TermInputs& c,
                       const Eigen::VectorXd& theta, double* h, double* h0) {
  const int np = model.num_parameters();
  for (int i = 0; i < np; ++i) h[i] = 0.0;
  *h0 = 0.0;
  for (std::size_t j = 0; j < model.terms().size(); ++j) {
    const auto& term = model.terms()[j];
    const int off = model.term_offset(int(j));
    double k0 = 0.0;
    if (term->Regressor(c, h + off, &k0)) {
      *h0 += k0;
    } else {
      for (int i = 0; i < term->num_parameters(); ++i) h[off + i] = 0.0;
      *h0 += term->Value(c, theta.data() + off);
    }
  }
}

model::TermInputs MeasuredTermInputs(const model::DofModel& model, const TrialData& trial, double t,
                                     double xi, const Eigen::VectorXd& theta) {
  model::TermInputs c;
  c.xi = xi;
  c.phi = model.ActuatorInput(trial.input->Force(t), theta.data());
  c.mapping = trial.input->Mapping(t);
  c.t_campaign = trial.start_time + t;
  c.ballast_steps = trial.ballast_steps;
  if (trial.aux) trial.aux->At(t, &c.velocities);
  c.velocities[model::Index(model.dof())] = xi;
  return c;
}

IntegratedRegressors IntegrateRegressors(const model::DofModel& model, const TrialData& trial,
                                         model::TimesView b, const Eigen::VectorXd& theta,
                                         double max_step, const SmoothedSignal* velocity_source,
                                         double velocity_shift) {
  IntegratedRegressors out;
  const int np = model.num_parameters();
  const int n = b.size() < 2 ? 0 : static_cast<int>(b.size()) - 1;
  out.H = Eigen::MatrixXd::Zero(n, np);
  out.h0 = Eigen::VectorXd::Zero(n);
  if (n == 0) return out;
  const model::TimesView breaks = trial.breakpoints();
  std::size_t next_break = std::lower_bound(breaks.begin(), breaks.end(), b[0]) - breaks.begin();
  std::vector<double> h(np);
  const double g = 0.5 / std::sqrt(3.0);  // Gauss–Legendre nodes at mid ± g·len
  const SmoothedSignal& src = velocity_source ? *velocity_source : trial.velocity_estimate;
  const auto& vt = src.t;
  const auto& vv = src.value;
  // Slopes for cubic Hermite interpolation: the filter's acceleration where known.
  const std::vector<float>* va = &src.derivative;
  if (va && va->size() != vv.size()) va = nullptr;
  // The cursor starts at the first boundary (a binary search), not at the signal's start: the
  // callers integrate one run of a long trial at a time, and a scan from the start each time
  // made the one-step rows quadratic in the trial's length (400 runs × 10⁶ samples).
  std::size_t cursor = vt.empty()
                           ? 0
                           : static_cast<std::size_t>(std::max<std::ptrdiff_t>(
                                 0, std::upper_bound(vt.begin(), vt.end(), b[0]) - vt.begin() - 1));
  // Interpolation with a forward-moving cursor (queries are increasing): cubic Hermite between
  // samples with the filter's accelerations (the local polynomials of the Savitzky–Golay fit),
  // linear where an acceleration is missing.
  auto velocity = [&](double t) -> double {
    if (vt.empty()) return 0.0;
    if (t <= vt.front()) return vv.front();
    if (t >= vt.back()) return vv.back();
    while (cursor + 1 < vt.size() && vt[cursor + 1] < t) ++cursor;
    while (cursor > 0 && vt[cursor] > t) --cursor;
    const double dt = vt[cursor + 1] - vt[cursor];
    const double w = (t - vt[cursor]) / dt;
    const double v0 = vv[cursor], v1 = vv[cursor + 1];
    if (va) {
      const double a0 = (*va)[cursor], a1 = (*va)[cursor + 1];
      if (std::isfinite(a0) && std::isfinite(a1)) {
        const double w2 = w * w, w3 = w2 * w;
        return (2 * w3 - 3 * w2 + 1) * v0 + (w3 - 2 * w2 + w) * dt * a0 + (-2 * w3 + 3 * w2) * v1 +
               (w3 - w2) * dt * a1;
      }
    }
    return v0 + w * (v1 - v0);
  };
  for (int k = 0; k < n; ++k) {
    double a = b[k];
    const double end = b[k + 1];
    while (a < end) {
      double stop = end;
      while (next_break < breaks.size() && breaks[next_break] <= a) ++next_break;
      if (next_break < breaks.size() && breaks[next_break] < stop) stop = breaks[next_break];
      const int pieces = std::max(
          1, model::CheckedCount<int>((stop - a) / max_step, "regression quadrature pieces",
                                      model::limits::kMaxSimulationSteps,
                                      "a shorter interval between samples"));
      const double len = (stop - a) / pieces;
      for (int p = 0; p < pieces; ++p) {
        const double mid = a + (p + 0.5) * len;
        for (double node : {mid - g * len, mid + g * len}) {
          const double xi = velocity(node) + velocity_shift;
          if (std::isnan(xi)) continue;
          const model::TermInputs c = MeasuredTermInputs(model, trial, node, xi, theta);
          double h0 = 0.0;
          EvaluateRegressor(model, c, theta, h.data(), &h0);
          for (int i = 0; i < np; ++i) out.H(k, i) += 0.5 * len * h[i];
          out.h0[k] += 0.5 * len * h0;
        }
      }
      a = stop;
    }
  }
  return out;
}

}  // namespace uuvplan::ident
