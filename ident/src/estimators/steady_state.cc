#include "uuvplan/ident/estimators/steady_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "options_check.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

// dF/dξ of the whole model at a context (for the effective variance of a row).
double ForceSlope(const model::DofModel& model, const model::TermInputs& c,
                  const Eigen::VectorXd& theta) {
  double d = 0.0;
  std::vector<double> J(model.num_parameters() + 1);
  for (std::size_t j = 0; j < model.terms().size(); ++j) {
    d += model.terms()[j]->Partials(c, theta.data() + model.term_offset(int(j)), J.data()).d_xi;
  }
  return d;
}

model::TermInputs PointTermInputs(const model::DofModel& model, const SteadyPoint& p,
                                  const Eigen::VectorXd& theta) {
  model::TermInputs c;
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
  return detection.IsValid(error) &&
         Require(max_condition > 1 && reweight_iterations >= 0,
                 "SteadyStateOptions: max_condition > 1 and reweight_iterations >= 0", error);
}

std::string_view SteadyStatusName(SteadyStatus s) {
  static constexpr model::EnumNames<SteadyStatus, 4> kNames{{{
      {SteadyStatus::kOk, "ok"},
      {SteadyStatus::kTooFewSegments, "too_few_segments"},
      {SteadyStatus::kIllConditioned, "ill_conditioned"},
      {SteadyStatus::kNotExcited, "not_excited"},
  }}};
  return kNames.Name(s);
}

bool SteadyStateResult::Estimated(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name)
      return state[i] == ParameterState::kEstimated && status == SteadyStatus::kOk;
  }
  return false;
}

namespace {

// The segments of the windows a user marked steady: each window clipped to the constant-force
// piece containing its middle (a window must not span a force change).
std::vector<SteadySegment> UserMarkedSegments(const Signal& s, bool from_position,
                                              const std::vector<ForcePiece>& pieces,
                                              const std::vector<std::pair<double, double>>& user,
                                              double sigma) {
  std::vector<SteadySegment> found;
  for (const auto& [a, b] : user) {
    const double mid = 0.5 * (a + b);
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      if (pieces[p].t0 <= mid && mid < pieces[p].t1) {
        SteadySegment seg;
        seg.piece = static_cast<int>(p);
        seg.user_marked = true;
        const double lo = std::max(a, pieces[p].t0), hi = std::min(b, pieces[p].t1);
        seg.fit =
            from_position ? ConstantSpeedFit(s, lo, hi, sigma) : MeanSpeedFit(s, lo, hi, sigma);
        if (seg.fit.ok) found.push_back(seg);
      }
    }
  }
  return found;
}

}  // namespace

std::vector<SteadyPoint> SteadyPoints(const TrialData& trial, const SteadyDetectionOptions& o,
                                      double force_tolerance,
                                      const std::vector<std::pair<double, double>>* user) {
  std::vector<SteadyPoint> out;
  // A user's window may lie in a piece of any length; detection looks at long pieces only.
  const std::vector<ForcePiece> pieces =
      ConstantForcePieces(trial, force_tolerance, user && !user->empty() ? 0.0 : o.min_duration_s);
  // Each source measured on the trial's DOF (positions: ref 000's LS slope; velocities: their
  // mean) gives its own segments; the more precise estimate of each piece is kept.
  std::vector<SteadySegment> segments;
  std::vector<char> segment_from_position;
  double noise_ar1[2] = {0.0, 0.0};  // of the velocity and the position sensor
  for (const bool from_position : {true, false}) {
    if (from_position ? !trial.has_position() : !trial.has_velocity()) continue;
    const Signal& s = from_position ? trial.position : trial.velocity;
    const double sigma = from_position ? trial.position_sigma : trial.velocity_sigma;
    std::vector<SteadySegment> found =
        user && !user->empty() ? UserMarkedSegments(s, from_position, pieces, *user, sigma)
                               : DetectSteadySegments(s, from_position, pieces, o, sigma);
    // Correlated noise: each speed's σ from the sensor's AR(1) pooled over the segments.
    std::vector<const SpeedFit*> fits;
    for (const SteadySegment& seg : found) fits.push_back(&seg.fit);
    const double rho = PooledNoiseAr1(fits);
    noise_ar1[from_position] = rho;
    for (SteadySegment& seg : found) seg.fit.sigma = Ar1SpeedSigma(seg.fit, rho, sigma);
    // Moved, not copied: a segment's fit holds per-sample weights and design.
    for (SteadySegment& seg : found) {
      bool replaced = false;
      for (std::size_t k = 0; k < segments.size(); ++k) {
        if (segments[k].piece != seg.piece) continue;
        if (seg.fit.sigma < segments[k].fit.sigma) {
          segments[k] = std::move(seg);
          segment_from_position[k] = from_position;
        }
        replaced = true;
        break;
      }
      if (!replaced) {
        segments.push_back(std::move(seg));
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
    p.noise_ar1 = noise_ar1[from_position];
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
    const double kl = -ForceSlope(model, PointTermInputs(model, p, theta), theta);
    if (!(kl > 0)) continue;
    const Signal& s = p.from_position ? trial->position : trial->velocity;
    const double sigma = p.from_position ? trial->position_sigma : trial->velocity_sigma;
    const SettlingFit f = SettlingSpeedFit(s, p.from_position, p.t0, p.t1, sigma, m / kl);
    if (!f.ok) continue;
    p.xi = f.speed;
    p.sigma_xi = Ar1SpeedSigma(f, p.noise_ar1, sigma);
  }
}

namespace {

// The regression rows at the given theta (non-linear terms evaluated at it):
// 0 = h·θ + h0  ⇒  −h0 = h·θ  (eqs. 7–10).
void SteadyRows(const model::DofModel& model, const std::vector<SteadyPoint>& points,
                const Eigen::VectorXd& theta, Eigen::MatrixXd* H, Eigen::VectorXd* y) {
  const int n = static_cast<int>(points.size()), np = model.num_parameters();
  H->resize(n, np);
  y->resize(n);
  std::vector<double> h(np);
  for (int i = 0; i < n; ++i) {
    double h0 = 0.0;
    EvaluateRegressor(model, PointTermInputs(model, points[i], theta), theta, h.data(), &h0);
    for (int j = 0; j < np; ++j) (*H)(i, j) = h[j];
    (*y)[i] = -h0;
  }
}

// The unknowns: regressor-linear parameters some point excites (the others are noted).
std::vector<int> ExcitedColumns(const model::DofModel& model, const Eigen::MatrixXd& Hall,
                                SteadyStateResult* r) {
  std::vector<int> cols;
  for (int j : LinearParameters(model)) {
    if (Hall.rows() > 0 && Hall.col(j).cwiseAbs().maxCoeff() > 0) {
      cols.push_back(j);
    } else {
      r->not_excited.push_back(r->names[j]);
    }
  }
  if (!r->not_excited.empty()) {
    r->notes.push_back("not excited by any steady segment (kept at their given values): " +
                       model::Join(r->not_excited));
  }
  return cols;
}

// Whether there are unknowns, a non-homogeneous regression and enough points; else the
// status says why.
bool EnoughPoints(const std::vector<int>& cols, const Eigen::VectorXd& y, SteadyStateResult* r) {
  const int n = r->num_points;
  if (cols.empty()) {
    r->status = SteadyStatus::kNotExcited;
    r->message =
        n == 0 ? "no steady-state segment found" : "no parameter is excited by the steady segments";
    return false;
  }
  if (n > 0 && y.cwiseAbs().maxCoeff() == 0.0) {
    r->status = SteadyStatus::kNotExcited;
    r->message =
        "every steady segment used a force whose installation coefficient is unknown: the "
        "regression is homogeneous (θ = 0 fits it); η must be known (open water) for at "
        "least one mapping and direction (seed 000 §II-A) — add legs with an open-water "
        "mapping";
    return false;
  }
  if (n < static_cast<int>(cols.size()) + 1) {
    r->status = SteadyStatus::kTooFewSegments;
    std::vector<std::string> names;
    for (int j : cols) names.push_back(r->names[j]);
    r->message =
        "too few steady-state segments: " + std::to_string(n) + " found for " +
        std::to_string(cols.size()) + " unknowns (" + model::Join(names) + "); at least " +
        std::to_string(cols.size() + 1) +
        " are needed (add constant-force legs at other speeds, each long enough to settle)";
    for (int j : cols) r->state[j] = ParameterState::kFixed;
    return false;
  }
  return true;
}

// Repeating a leg adds precision, not information: the unknowns need as many distinct
// operating points (mapping, force, ballast, other DOFs' speeds) as there are of them. A
// two-level telegraph, say, leaves k, kq, bias and η undetermined (k = kq = 0 with
// bias = −φ and η = −1 fits ±φ exactly), whatever the condition number of the noisy rows.
std::vector<SteadyPoint> DistinctPoints(const model::DofModel& model,
                                        const std::vector<SteadyPoint>& points) {
  std::vector<SteadyPoint> distinct;
  for (const SteadyPoint& a : points) {
    bool seen = false;
    for (const SteadyPoint& b : distinct) {
      bool same =
          a.mapping == b.mapping && a.ballast_steps == b.ballast_steps &&
          std::abs(a.phi - b.phi) <= 1e-6 * std::max({1.0, std::abs(a.phi), std::abs(b.phi)});
      for (int k = 0; k < model::kNumDofs && same; ++k) {
        if (k == model::Index(model.dof())) continue;
        same =
            std::abs(a.velocities[k] - b.velocities[k]) <= 1e-3 * (1 + std::abs(b.velocities[k]));
      }
      seen = seen || same;
    }
    if (!seen) distinct.push_back(a);
  }
  return distinct;
}

// Columns (of the p unknowns) in the null space of the distinct operating points' rows `Hd`
// (column-scaled, components above LeastSquaresOptions::null_component).
std::vector<int> NullColumns(const Eigen::MatrixXd& Hd, int p) {
  Eigen::MatrixXd Hsq = Eigen::MatrixXd::Zero(p, p);  // Hd padded with zero rows to p × p
  Hsq.topRows(Hd.rows()) = Hd;
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
  return null_cols;
}

// Fewer distinct points d than unknowns p: the regression is singular (the scatter of the
// measured speeds only hides it). Reports the condition number of the rows as measured and
// the parameters in the null space of the distinct points' rows.
void ReportSingular(const model::DofModel& model, const Eigen::MatrixXd& Hall,
                    const std::vector<SteadyPoint>& distinct, const std::vector<int>& cols,
                    const Eigen::VectorXd& theta, SteadyStateResult* r) {
  const int n = r->num_points, p = static_cast<int>(cols.size());
  const int d = static_cast<int>(distinct.size());
  Eigen::MatrixXd H = SelectedColumns(Hall, cols), Hd_all;
  Eigen::VectorXd y_unused;
  SteadyRows(model, distinct, theta, &Hd_all, &y_unused);
  Eigen::MatrixXd Hd = SelectedColumns(Hd_all, cols);
  for (int c = 0; c < p; ++c) {
    const double s = H.col(c).norm();
    if (s > 0) {
      H.col(c) /= s;
      Hd.col(c) /= s;
    }
  }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(H).singularValues();
  r->condition_number = sv[p - 1] > 0 ? sv[0] / sv[p - 1] : std::numeric_limits<double>::infinity();
  std::vector<std::string> col_names;
  for (int j : cols) col_names.push_back(r->names[j]);
  std::vector<std::string> null_names;
  for (int c : NullColumns(Hd, p)) null_names.push_back(col_names[c]);
  r->not_identifiable = null_names;
  r->status = SteadyStatus::kIllConditioned;
  r->message = "steady-state regression is singular: the " + std::to_string(n) +
               " steady segments hold only " + std::to_string(d) +
               " distinct operating point(s) for " + std::to_string(p) + " unknowns (" +
               model::Join(col_names) + "), condition number " +
               model::Significant(r->condition_number, 3) +
               " of the measured rows; not identifiable: " + model::Join(null_names) +
               " (add steady legs at other force levels, in both directions and with each "
               "mapping)";
}

// One least-squares fit of the columns `cols`; with velocity-variance weighting (eq. 12's
// effective variance (∂F/∂ξ·σ_ξ)² per point) reweighted at the current estimate.
LinearFit WeightedFit(const model::DofModel& model, const std::vector<SteadyPoint>& points,
                      const Eigen::MatrixXd& H, const Eigen::VectorXd& y,
                      const std::vector<int>& cols, const SteadyStateOptions& o,
                      const LeastSquaresOptions& lso, Eigen::VectorXd* theta) {
  const int n = static_cast<int>(H.rows()), p = static_cast<int>(cols.size());
  const bool weighted = o.weighting == SteadyStateOptions::Weighting::kVelocityVariance;
  LeastSquaresOptions first = lso;
  if (weighted) first.covariance = CovarianceKind::kResidual;
  LinearFit fit = SolveLeastSquares(H, y, nullptr, first);
  if (!weighted) return fit;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(n);
  for (int it = 0; it < std::max(1, o.reweight_iterations); ++it) {
    for (int c = 0; c < p; ++c) (*theta)[cols[c]] = fit.theta[c];
    for (int i = 0; i < n; ++i) {
      const double slope = ForceSlope(model, PointTermInputs(model, points[i], *theta), *theta);
      const double var = slope * slope * points[i].sigma_xi * points[i].sigma_xi;
      w[i] = var > 0 ? 1.0 / var : 1.0;
    }
    fit = SolveLeastSquares(H, y, &w, lso);
  }
  return fit;
}

// The fit with model selection (ref 000 §IV-D): drop the worst insignificant prunable
// parameter and refit until none is left. Fills r's theta, state and estimates.
LinearFit FitWithSelection(const model::DofModel& model, const std::vector<SteadyPoint>& points,
                           const Eigen::MatrixXd& Hall, const Eigen::VectorXd& y,
                           std::vector<int>* cols, const SteadyStateOptions& o,
                           SteadyStateResult* r) {
  const int n = r->num_points, np = model.num_parameters();
  LeastSquaresOptions lso;
  lso.covariance = o.covariance;
  lso.max_condition = o.max_condition;
  std::vector<double> before_value(np, 0.0), before_sigma(np, 0.0);
  Eigen::VectorXd theta = r->theta;
  LinearFit fit;
  std::vector<std::string> kept;  // insignificant parameters kept for their correlation
  while (true) {
    const int p = static_cast<int>(cols->size());
    Eigen::MatrixXd H(n, p);
    for (int c = 0; c < p; ++c) H.col(c) = Hall.col((*cols)[c]);
    // y − (dropped columns at 0) = y: dropped parameters contribute nothing.
    fit = WeightedFit(model, points, H, y, *cols, o, lso, &theta);
    for (int c = 0; c < p; ++c) theta[(*cols)[c]] = fit.theta[c];
    if (!o.selection.prune_insignificant || fit.status != FitStatus::kOk) break;
    std::vector<PruneCandidate> candidates;
    const std::vector<double> correlation = LargestCorrelations(fit.covariance);
    for (int c = 0; c < p; ++c) {
      candidates.push_back(
          {r->names[(*cols)[c]], fit.theta[c], std::sqrt(fit.covariance(c, c)), correlation[c]});
    }
    double worst_pe = 0.0;
    kept.clear();
    const int worst = WorstInsignificant(candidates, o.selection, &worst_pe, &kept);
    if (worst < 0 || p == 1) break;
    const int j = (*cols)[worst];
    r->state[j] = ParameterState::kDropped;
    before_value[j] = fit.theta[worst];
    before_sigma[j] = std::sqrt(fit.covariance(worst, worst));
    theta[j] = 0.0;
    r->notes.push_back(r->names[j] + " = " + model::Significant(before_value[j], 4) + " ± " +
                       model::Significant(before_sigma[j], 4) + " has a percentile error of " +
                       model::Significant(worst_pe, 3) +
                       "% > 51.02%: insignificant at 95%, dropped and the rest refitted "
                       "(seed 000 §IV-D)");
    cols->erase(cols->begin() + worst);
  }
  r->notes.insert(r->notes.end(), kept.begin(), kept.end());
  r->theta = theta;
  for (std::size_t c = 0; c < cols->size(); ++c) {
    r->state[(*cols)[c]] = ParameterState::kEstimated;
    for (std::size_t d = 0; d < cols->size(); ++d)
      r->covariance((*cols)[c], (*cols)[d]) = fit.covariance(c, d);
  }
  r->estimates =
      EstimatedAndDropped(r->names, r->theta, r->covariance, r->state, before_value, before_sigma);
  return fit;
}

}  // namespace

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
  Eigen::MatrixXd Hall;
  Eigen::VectorXd y;
  SteadyRows(model, points, theta_in, &Hall, &y);
  std::vector<int> cols = ExcitedColumns(model, Hall, &r);
  if (!EnoughPoints(cols, y, &r)) return r;
  const std::vector<SteadyPoint> distinct = DistinctPoints(model, points);
  if (distinct.size() < cols.size()) {
    ReportSingular(model, Hall, distinct, cols, theta_in, &r);
    return r;
  }
  const LinearFit fit = FitWithSelection(model, points, Hall, y, &cols, o, &r);
  r.sigma2 = fit.sigma2;
  r.condition_number = fit.condition_number;
  for (int i = 0; i < r.num_points; ++i) r.residuals.push_back(fit.residuals[i]);
  for (int j : fit.not_identifiable) r.not_identifiable.push_back(r.names[cols[j]]);
  std::vector<std::string> col_names;
  for (int j : cols) col_names.push_back(r.names[j]);
  if (fit.status == FitStatus::kOk) {
    r.status = SteadyStatus::kOk;
    r.message = std::to_string(r.num_points) + " steady segments, condition number " +
                model::Significant(fit.condition_number, 3);
  } else {
    r.status = SteadyStatus::kIllConditioned;
    r.message =
        "steady-state regression is ill-conditioned (condition number " +
        model::Significant(fit.condition_number, 3) +
        "); not identifiable from these segments: " + JoinNames(fit.not_identifiable, col_names) +
        " (add steady legs at other speeds / in the other direction / with other mappings)";
  }
  return r;
}

}  // namespace uuvplan::ident
