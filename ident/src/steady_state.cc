#include "uuvplan/ident/steady_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "uuvplan/ident/regression.h"
#include "uuvplan/ident/significance.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"

namespace uuvplan::ident {
namespace {

std::string Fmt(double v, int precision = 4) {
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

// dF/dξ of the whole model at a context (for the effective variance of a row).
double ForceSlope(const model::DofModel& model, const model::TermContext& c,
                  const Eigen::VectorXd& theta) {
  double d = 0.0;
  std::vector<double> J(model.num_parameters() + 1);
  for (std::size_t j = 0; j < model.terms().size(); ++j) {
    d += model.terms()[j]->Partials(c, theta.data() + model.term_offset(int(j)), J.data()).d_xi;
  }
  return d;
}

bool IsDragName(const std::string& n) {
  return n == model::param::kLinearDrag || n == model::param::kQuadraticDrag ||
         n == model::param::kLinearDragNeg || n == model::param::kQuadraticDragNeg;
}

int CountDrag(const std::vector<int>& cols, const std::vector<std::string>& names) {
  int n = 0;
  for (int j : cols) n += IsDragName(names[j]) ? 1 : 0;
  return n;
}

model::TermContext PointContext(const model::DofModel& model, const SteadyPoint& p,
                                const Eigen::VectorXd& theta) {
  model::TermContext c;
  c.xi = p.xi;
  c.phi = model.ActuatorInput(p.phi, theta.data());
  c.mapping = p.mapping;
  c.t_campaign = p.t_campaign;
  c.ballast_steps = p.ballast_steps;
  c.velocities = p.velocities;
  c.velocities[model::Index(model.dof())] = p.xi;
  return c;
}

}  // namespace

bool SteadyStateOptions::IsValid(std::string* error) const {
  if (!detection.IsValid(error)) return false;
  if (!(max_condition > 1) || reweight_iterations < 0) {
    if (error) *error = "SteadyStateOptions: max_condition > 1 and reweight_iterations >= 0";
    return false;
  }
  return true;
}

std::string_view SteadyStatusName(SteadyStatus s) {
  switch (s) {
    case SteadyStatus::kOk: return "ok";
    case SteadyStatus::kTooFewSegments: return "too_few_segments";
    case SteadyStatus::kIllConditioned: return "ill_conditioned";
    case SteadyStatus::kNotExcited: return "not_excited";
  }
  return "ok";
}

bool SteadyStateResult::Estimated(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return state[i] == ParameterState::kEstimated && status == SteadyStatus::kOk;
  }
  return false;
}

std::vector<SteadyPoint> SteadyPoints(const TrialData& trial, const SteadyDetectionOptions& o,
                                      double force_tolerance,
                                      const std::vector<std::pair<double, double>>* user) {
  std::vector<SteadyPoint> out;
  const std::vector<ForcePiece> pieces = ConstantForcePieces(trial, force_tolerance);
  // Each source measured on the trial's DOF (positions: seed 000's LS slope; velocities: their
  // mean) gives its own segments; the more precise estimate of each piece is kept.
  std::vector<SteadySegment> segments;
  std::vector<char> segment_from_position;
  for (const bool from_position : {true, false}) {
    if (from_position ? !trial.has_position() : !trial.has_velocity()) continue;
    const Signal& s = from_position ? trial.position : trial.velocity;
    const double sigma = from_position ? trial.position_sigma : trial.velocity_sigma;
    std::vector<SteadySegment> found;
    if (user && !user->empty()) {
      for (const auto& [a, b] : *user) {
        // The piece containing the window's middle; the window must not span a force change.
        const double mid = 0.5 * (a + b);
        for (std::size_t p = 0; p < pieces.size(); ++p) {
          if (pieces[p].t0 <= mid && mid < pieces[p].t1) {
            SteadySegment seg;
            seg.piece = static_cast<int>(p);
            seg.user_marked = true;
            const double lo = std::max(a, pieces[p].t0), hi = std::min(b, pieces[p].t1);
            seg.fit = from_position ? ConstantSpeedFit(s, lo, hi, sigma) : MeanSpeedFit(s, lo, hi, sigma);
            if (seg.fit.ok) found.push_back(seg);
          }
        }
      }
    } else {
      found = DetectSteadySegments(s, from_position, pieces, o, sigma);
    }
    for (const SteadySegment& seg : found) {
      bool replaced = false;
      for (std::size_t k = 0; k < segments.size(); ++k) {
        if (segments[k].piece != seg.piece) continue;
        if (seg.fit.sigma < segments[k].fit.sigma) {
          segments[k] = seg;
          segment_from_position[k] = from_position;
        }
        replaced = true;
      }
      if (!replaced) {
        segments.push_back(seg);
        segment_from_position.push_back(from_position);
      }
    }
  }
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const SteadySegment& seg = segments[k];
    const bool from_position = segment_from_position[k];
    const ForcePiece& piece = pieces[seg.piece];
    SteadyPoint p;
    p.trial = trial.index;
    p.t0 = seg.fit.t0;
    p.t1 = seg.fit.t1;
    p.xi = seg.fit.speed;
    p.sigma_xi = seg.fit.sigma;
    p.phi = piece.force;
    p.mapping = piece.mapping;
    p.ballast_steps = trial.ballast_steps;
    const double mid = 0.5 * (p.t0 + p.t1);
    p.t_campaign = trial.start_time + mid;
    if (trial.aux) trial.aux->At(mid, &p.velocities);
    p.user_marked = seg.user_marked;
    p.from_position = from_position;
    out.push_back(p);
  }
  return out;
}

void RefineSteadyPoints(const model::DofModel& model, const Eigen::VectorXd& theta,
                        const std::vector<const TrialData*>& trials,
                        std::vector<SteadyPoint>* points) {
  const double m = theta[0];
  if (!(m > 0)) return;
  for (SteadyPoint& p : *points) {
    if (p.user_marked) continue;
    const TrialData* trial = nullptr;
    for (const TrialData* t : trials) {
      if (t->index == p.trial) trial = t;
    }
    if (!trial) continue;
    const double kl = -ForceSlope(model, PointContext(model, p, theta), theta);
    if (!(kl > 0)) continue;
    const Signal& s = p.from_position ? trial->position : trial->velocity;
    const double sigma = p.from_position ? trial->position_sigma : trial->velocity_sigma;
    const SettlingFit f = SettlingSpeedFit(s, p.from_position, p.t0, p.t1, sigma, m / kl);
    if (!f.ok) continue;
    p.xi = f.speed;
    p.sigma_xi = f.sigma;
  }
}

SteadyStateResult SteadyStateFit(const model::DofModel& model,
                                 const std::vector<SteadyPoint>& points,
                                 const Eigen::VectorXd& theta_in, const SteadyStateOptions& o) {
  SteadyStateResult r;
  const int np = model.num_parameters();
  r.names = model.parameter_names();
  r.theta = theta_in;
  r.covariance = Eigen::MatrixXd::Zero(np, np);
  r.state.assign(np, ParameterState::kFixed);
  r.num_points = static_cast<int>(points.size());
  const int n = r.num_points;

  // Rows of the regression at the given theta (non-linear terms evaluated at it).
  Eigen::MatrixXd Hall(n, np);
  Eigen::VectorXd y(n);
  std::vector<double> h(np);
  for (int i = 0; i < n; ++i) {
    double h0 = 0.0;
    EvaluateRegressor(model, PointContext(model, points[i], theta_in), theta_in, h.data(), &h0);
    for (int j = 0; j < np; ++j) Hall(i, j) = h[j];
    y[i] = -h0;  // 0 = h·θ + h0  ⇒  −h0 = h·θ  (eqs. 7–10)
  }
  std::vector<int> cols;
  for (int j : LinearParameters(model)) {
    if (n > 0 && Hall.col(j).cwiseAbs().maxCoeff() > 0) {
      cols.push_back(j);
    } else {
      r.not_excited.push_back(r.names[j]);
    }
  }
  if (!r.not_excited.empty()) {
    std::string list;
    for (const auto& s : r.not_excited) list += (list.empty() ? "" : ", ") + s;
    r.notes.push_back("not excited by any steady segment (kept at their given values): " + list);
  }
  if (cols.empty()) {
    r.status = SteadyStatus::kNotExcited;
    r.message = n == 0 ? "no steady-state segment found" : "no parameter is excited by the steady segments";
    return r;
  }
  if (n > 0 && y.cwiseAbs().maxCoeff() == 0.0) {
    r.status = SteadyStatus::kNotExcited;
    r.message = "every steady segment used a force whose installation coefficient is unknown: the "
                "regression is homogeneous (θ = 0 fits it); η must be known (open water) for at "
                "least one mapping and direction (seed 000 §II-A) — add legs with an open-water "
                "mapping";
    return r;
  }
  if (n < static_cast<int>(cols.size()) + 1) {
    r.status = SteadyStatus::kTooFewSegments;
    std::string list;
    for (int j : cols) list += (list.empty() ? "" : ", ") + r.names[j];
    r.message = "too few steady-state segments: " + std::to_string(n) + " found for " +
                std::to_string(cols.size()) + " unknowns (" + list + "); at least " +
                std::to_string(cols.size() + 1) +
                " are needed (add constant-force legs at other speeds, each long enough to settle)";
    for (int j : cols) r.state[j] = ParameterState::kFixed;
    return r;
  }

  // Repeating a leg adds precision, not information: the unknowns need as many distinct
  // operating points (mapping, force, ballast, other DOFs' speeds) as there are of them. A
  // two-level telegraph, say, leaves k, kq, bias and η undetermined (k = kq = 0 with
  // bias = −φ and η = −1 fits ±φ exactly), whatever the condition number of the noisy rows.
  {
    std::vector<SteadyPoint> distinct;
    for (const SteadyPoint& a : points) {
      bool seen = false;
      for (const SteadyPoint& b : distinct) {
        bool same = a.mapping == b.mapping && a.ballast_steps == b.ballast_steps &&
                    std::abs(a.phi - b.phi) <= 1e-6 * std::max({1.0, std::abs(a.phi), std::abs(b.phi)});
        for (int k = 0; k < model::kNumDofs && same; ++k) {
          if (k == model::Index(model.dof())) continue;
          same = std::abs(a.velocities[k] - b.velocities[k]) <= 1e-3 * (1 + std::abs(b.velocities[k]));
        }
        seen = seen || same;
      }
      if (!seen) distinct.push_back(a);
    }
    const int p = static_cast<int>(cols.size());
    const int d = static_cast<int>(distinct.size());
    if (d < p) {
      // The regression is singular: its rows span at most d < p directions of the unknowns
      // (the scatter of the measured speeds only hides it). Report the condition number of the
      // rows as measured, and name the parameters in the null space of the distinct operating
      // points' rows (column-scaled, components above LeastSquaresOptions::null_component).
      Eigen::MatrixXd H(n, p), Hd(d, p);
      for (int c = 0; c < p; ++c) H.col(c) = Hall.col(cols[c]);
      for (int i = 0; i < d; ++i) {
        double h0 = 0.0;
        EvaluateRegressor(model, PointContext(model, distinct[i], theta_in), theta_in, h.data(), &h0);
        for (int c = 0; c < p; ++c) Hd(i, c) = h[cols[c]];
      }
      for (int c = 0; c < p; ++c) {
        const double s = H.col(c).norm();
        if (s > 0) {
          H.col(c) /= s;
          Hd.col(c) /= s;
        }
      }
      const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(H).singularValues();
      r.condition_number = sv[p - 1] > 0 ? sv[0] / sv[p - 1] : std::numeric_limits<double>::infinity();
      Eigen::MatrixXd Hsq = Eigen::MatrixXd::Zero(p, p);  // Hd padded with zero rows to p × p
      Hsq.topRows(d) = Hd;
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Hsq, Eigen::ComputeFullV);
      const double smax = svd.singularValues()[0];
      const double null_component = LeastSquaresOptions{}.null_component;
      std::vector<int> null_cols;
      for (int k = 0; k < p; ++k) {
        if (svd.singularValues()[k] > 1e-10 * smax) continue;  // rank of the distinct rows
        for (int c = 0; c < p; ++c) {
          if (std::abs(svd.matrixV()(c, k)) > null_component &&
              std::find(null_cols.begin(), null_cols.end(), c) == null_cols.end()) {
            null_cols.push_back(c);
          }
        }
      }
      std::sort(null_cols.begin(), null_cols.end());
      std::vector<std::string> col_names;
      for (int j : cols) col_names.push_back(r.names[j]);
      for (int c : null_cols) r.not_identifiable.push_back(col_names[c]);
      r.status = SteadyStatus::kIllConditioned;
      r.message = "steady-state regression is singular: the " + std::to_string(n) +
                  " steady segments hold only " + std::to_string(d) +
                  " distinct operating point(s) for " + std::to_string(p) + " unknowns (" +
                  JoinNames([&] {
                    std::vector<int> all(p);
                    for (int c = 0; c < p; ++c) all[c] = c;
                    return all;
                  }(), col_names) +
                  "), condition number " + Fmt(r.condition_number, 3) +
                  " of the measured rows; not identifiable: " + JoinNames(null_cols, col_names) +
                  " (add steady legs at other force levels, in both directions and with each "
                  "mapping)";
      return r;
    }
  }
  LeastSquaresOptions lso;
  lso.covariance = o.covariance;
  lso.max_condition = o.max_condition;
  std::vector<char> dropped(np, 0);
  std::vector<double> before_value(np, 0.0), before_sigma(np, 0.0);
  Eigen::VectorXd theta = theta_in;
  LinearFit fit;
  while (true) {
    const int p = static_cast<int>(cols.size());
    Eigen::MatrixXd H(n, p);
    for (int c = 0; c < p; ++c) H.col(c) = Hall.col(cols[c]);
    // y − (dropped columns at 0) = y: dropped parameters contribute nothing.
    Eigen::VectorXd w = Eigen::VectorXd::Ones(n);
    LeastSquaresOptions first = lso;
    if (o.weighting == SteadyStateOptions::Weighting::kVelocityVariance) {
      first.covariance = CovarianceKind::kResidual;
    }
    fit = SolveLeastSquares(H, y, nullptr, first);
    if (o.weighting == SteadyStateOptions::Weighting::kVelocityVariance) {
      for (int it = 0; it < std::max(1, o.reweight_iterations); ++it) {
        for (int c = 0; c < p; ++c) theta[cols[c]] = fit.theta[c];
        for (int i = 0; i < n; ++i) {
          const double slope = ForceSlope(model, PointContext(model, points[i], theta), theta);
          const double var = slope * slope * points[i].sigma_xi * points[i].sigma_xi;
          w[i] = var > 0 ? 1.0 / var : 1.0;
        }
        fit = SolveLeastSquares(H, y, &w, lso);
      }
    }
    for (int c = 0; c < p; ++c) theta[cols[c]] = fit.theta[c];
    if (!o.prune_insignificant || fit.status != FitStatus::kOk) break;
    // Seed 000 §IV-D: drop the prunable parameter with the largest percentile error > 51.02%.
    int worst = -1;
    double worst_pe = kInsignificantPercentileError;
    for (int c = 0; c < p; ++c) {
      const std::string& name = r.names[cols[c]];
      if (std::find(o.prunable.begin(), o.prunable.end(), name) == o.prunable.end()) continue;
      // At least one drag term stays: a model without drag has no steady state.
      if (IsDragName(name) && CountDrag(cols, r.names) <= 1) continue;
      const double pe = PercentileError(fit.theta[c], std::sqrt(fit.covariance(c, c)));
      if (pe > worst_pe) {
        worst_pe = pe;
        worst = c;
      }
    }
    if (worst < 0 || p == 1) break;
    const int j = cols[worst];
    dropped[j] = 1;
    before_value[j] = fit.theta[worst];
    before_sigma[j] = std::sqrt(fit.covariance(worst, worst));
    theta[j] = 0.0;
    r.notes.push_back(r.names[j] + " = " + Fmt(before_value[j]) + " ± " + Fmt(before_sigma[j]) +
                      " has a percentile error of " + Fmt(worst_pe, 3) +
                      "% > 51.02%: insignificant at 95%, dropped and the rest refitted "
                      "(seed 000 §IV-D)");
    cols.erase(cols.begin() + worst);
  }
  r.theta = theta;
  r.sigma2 = fit.sigma2;
  r.condition_number = fit.condition_number;
  for (int i = 0; i < n; ++i) r.residuals.push_back(fit.residuals[i]);
  for (std::size_t c = 0; c < cols.size(); ++c) {
    r.state[cols[c]] = ParameterState::kEstimated;
    for (std::size_t d = 0; d < cols.size(); ++d) r.covariance(cols[c], cols[d]) = fit.covariance(c, d);
  }
  for (int j = 0; j < np; ++j) {
    if (dropped[j]) r.state[j] = ParameterState::kDropped;
  }
  for (int j : fit.not_identifiable) r.not_identifiable.push_back(r.names[cols[j]]);
  std::vector<ParameterEstimate> all = MakeEstimates(r.names, r.theta, r.covariance, r.state);
  for (int j = 0; j < np; ++j) {
    if (r.state[j] == ParameterState::kFixed) continue;
    if (r.state[j] == ParameterState::kDropped) {
      all[j].value_before_drop = before_value[j];
      all[j].sigma_before_drop = before_sigma[j];
      all[j].significant = false;
    }
    r.estimates.push_back(all[j]);
  }
  if (fit.status == FitStatus::kOk) {
    r.status = SteadyStatus::kOk;
    r.message = std::to_string(n) + " steady segments, condition number " + Fmt(fit.condition_number, 3);
  } else {
    r.status = SteadyStatus::kIllConditioned;
    r.message = "steady-state regression is ill-conditioned (condition number " +
                Fmt(fit.condition_number, 3) + "); not identifiable from these segments: " +
                JoinNames(fit.not_identifiable, [&] {
                  std::vector<std::string> v;
                  for (int j : cols) v.push_back(r.names[j]);
                  return v;
                }()) +
                " (add steady legs at other speeds / in the other direction / with other mappings)";
  }
  return r;
}

}  // namespace uuvplan::ident
