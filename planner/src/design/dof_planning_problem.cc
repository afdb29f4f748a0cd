// The per-DOF design context (see dof_planning_problem.h).
#include "uuvplan/planner/design/dof_planning_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "design/sensor_information.h"
#include "design/speed_limit.h"
#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {

PriorInformation PriorInformation::FromCovariance(const std::vector<std::string>& names,
                                                  const Eigen::MatrixXd& C) {
  PriorInformation p;
  if (C.size() == 0) {  // no estimates yet: no prior information (names dropped with it)
    p.M = Eigen::MatrixXd::Zero(0, 0);
    return p;
  }
  if (C.rows() != C.cols() || C.rows() != static_cast<Eigen::Index>(names.size())) {
    throw std::invalid_argument("PriorInformation::FromCovariance: covariance " +
                                std::to_string(C.rows()) + " x " + std::to_string(C.cols()) +
                                " for " + std::to_string(names.size()) +
                                " names. Violated constraint: square, one row per name");
  }
  p.names = names;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C);
  const Eigen::VectorXd& lam = es.eigenvalues();
  const double top = lam.size() ? lam.maxCoeff() : 0.0;
  Eigen::VectorXd inv(lam.size());
  for (int i = 0; i < lam.size(); ++i) inv[i] = lam[i] > 1e-14 * top ? 1.0 / lam[i] : 0.0;
  p.M = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
  return p;
}

bool PlannerOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("PlannerOptions", error);
  check.Require(max_trial_duration_s > 0, "max_trial_duration_s", max_trial_duration_s, "> 0")
      .Require(pause_s >= 0, "pause_s", pause_s, ">= 0")
      .Require(max_step_s > 0, "max_step_s", max_step_s, "> 0")
      .Require(least_time_constant_s >= 0, "least_time_constant_s", least_time_constant_s, ">= 0")
      .Require(samples_per_period >= 2, "samples_per_period", samples_per_period, ">= 2 (Nyquist)")
      .Require(check_grid >= 2, "check_grid", check_grid, ">= 2")
      .Require(box.drag_sigmas >= 0, "box.drag_sigmas", box.drag_sigmas, ">= 0")
      .Require(threads >= 0, "threads", threads, ">= 0 (0: one per core)");
  return check.ok() && solver.IsValid(error);
}

int PlannerOptions::Threads() const {
  const bool ipopt =
      sine_backend == SolverBackend::kIpopt || steady_backend == SolverBackend::kIpopt;
  return ipopt ? 1 : threads;
}

namespace {

// `s` with the effects of the model the vehicle file gives the DOF with σ (identified, or
// derived from an identified base): the Fisher information then covers their parameters too
// (a lag, a thrust exponent, ...), at the file's values.
model::ModelStructure WithFileEffects(const model::Vehicle& v, model::Dof dof,
                                      model::ModelStructure s) {
  const auto model = v.models.find(dof);
  if (model == v.models.end() || !model->second.identified()) return s;
  return model::WithWrittenEffects(std::move(s), model->second);
}

// The standard model of the DOF's mappings, with the file's effects.
model::ModelStructure StructureFor(const model::Vehicle& v, model::Dof dof) {
  std::vector<std::string> names;
  for (int i : v.MappingsOf(dof)) names.push_back(v.mappings[i].name);
  return WithFileEffects(v, dof, model::ModelStructure::Standard(v, dof, names, false));
}

void RequireDesignable(const model::Vehicle& v, model::Dof dof) {
  const std::string d(model::DofName(dof));
  auto s = v.sensors.find(dof);
  if (s == v.sensors.end() || (!s->second.position && !s->second.velocity)) {
    throw model::InputError("vehicle '" + v.name + "': sensors." + d,
                            "no position or velocity sensor on " + d +
                                ": a trial on it could not be measured (add sensors." + d + ")");
  }
  if (v.MappingsOf(dof).empty()) {
    throw model::InputError("vehicle '" + v.name + "': mappings",
                            "no thrust mapping acts on " + d + ": it cannot be excited");
  }
}

// A box whose fastest point has a time constant under `least` would be simulated in steps of
// half of it (ChooseStep): refused, so that no design runs for hours.
void RequireBoundedWork(const model::Vehicle& v, model::Dof dof, double tc_min, double least) {
  if (tc_min >= least) return;
  const std::string d(model::DofName(dof));
  throw model::InputError(
      "vehicle '" + v.name + "': " + d,
      "the planning box of " + d + " reaches a time constant of " +
          model::Significant(1e3 * tc_min, 3) + " ms (m over the drag at the largest thrust), " +
          "under the planner's least " + model::Significant(1e3 * least, 3) +
          " ms: its simulations would take more steps than a design may; check the units of the "
          "inertia and the drag (kg or kg·m², N·s/m or N·m·s/rad)");
}

}  // namespace

std::unique_ptr<DofPlanningProblem> DofPlanningProblem::APriori(const model::Vehicle& vehicle,
                                                                const model::Pool& pool,
                                                                model::Dof dof,
                                                                const PlannerOptions& options,
                                                                std::vector<std::string>* notes) {
  RequireDesignable(vehicle, dof);
  const model::DofModel probe(vehicle, StructureFor(vehicle, dof));
  ParameterBox box = PlanningBox(vehicle, dof, probe.parameter_names(), options.box, notes);
  return std::make_unique<DofPlanningProblem>(vehicle, pool, dof, std::move(box), options);
}

DofPlanningProblem::DofPlanningProblem(const model::Vehicle& vehicle, const model::Pool& pool,
                                       model::Dof dof, ParameterBox box,
                                       const PlannerOptions& options)
    : vehicle_(vehicle), pool_(pool), dof_(dof), box_(std::move(box)), options_(options) {
  RequireDesignable(vehicle, dof);
  model_ = std::make_unique<model::DofModel>(vehicle, StructureFor(vehicle, dof));
  sensors_ = vehicle.sensors.at(dof);
  for (const auto& n : model_->parameter_names()) {
    if (!box_.nominal.count(n)) box_.nominal[n] = 0.0;
  }
  for (const auto& p : box_.DesignPoints()) design_thetas_.push_back(model_->Theta(p));
  for (const auto& p : box_.CheckPoints(options_.check_grid)) {
    check_thetas_.push_back(model_->Theta(p));
  }
  // Time constants m/k_L (ref 000 eq. 13) over the box, from rest to the largest force any
  // mapping of the DOF can give.
  double phi_max = 0.0, phi_min = std::numeric_limits<double>::infinity();
  for (int mi : vehicle.MappingsOf(dof)) {
    for (int s : {+1, -1}) {
      const ForceRange r = DirectionForceRange(vehicle, mi, s);
      if (!r.feasible) continue;
      phi_max = std::max(phi_max, r.max_abs);
      phi_min = std::min(phi_min, r.min_abs);
    }
  }
  if (!std::isfinite(phi_min)) phi_min = 0.0;
  const int im = Index(model::param::kMass), ik = Index(model::param::kLinearDrag),
            iq = Index(model::param::kQuadraticDrag);
  tc_min_ = std::numeric_limits<double>::infinity();
  tc_max_ = 0.0;
  for (const auto& th : check_thetas_) {
    const double m = th[im], k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    const double v_hi = SteadySpeed(k, kq, phi_max);
    const double v_lo = SteadySpeed(k, kq, phi_min);
    const double kl_hi = LinearisedDrag(k, kq, v_hi), kl_lo = LinearisedDrag(k, kq, v_lo);
    if (kl_hi > 0) tc_min_ = std::min(tc_min_, TimeConstant(m, kl_hi));
    if (kl_lo > 0) tc_max_ = std::max(tc_max_, TimeConstant(m, kl_lo));
  }
  if (!std::isfinite(tc_min_)) tc_min_ = 1.0;
  if (tc_max_ <= 0) tc_max_ = tc_min_;
  RequireBoundedWork(vehicle, dof, tc_min_, options_.least_time_constant_s);
  step_s_ = ChooseStep(tc_min_, options_.max_step_s);
  design_sensors_ = sensors_;
  for (auto* spec : {&design_sensors_.position, &design_sensors_.velocity}) {
    if (*spec) **spec = AtMostRate(**spec, 1.0 / step_s_);
  }
}

double DofPlanningProblem::ShortestPeriod() const {
  return sensors_.ShortestPeriod(options_.samples_per_period);
}

ForceRange DofPlanningProblem::ForceRangeFor(int mapping, int sign) const {
  ForceRange r = DirectionForceRange(vehicle_, mapping, sign);
  const double limit = SpeedLimitOf(vehicle_, dof_, options_);
  if (!r.feasible || !(limit > 0)) return r;
  // phi at which k·xi + kq·xi² = phi reaches the limit at the lowest drag of the box.
  const int ik = Index(model::param::kLinearDrag), iq = Index(model::param::kQuadraticDrag);
  double phi = std::numeric_limits<double>::infinity(), k_low = 0.0, kq_low = 0.0;
  for (const auto& th : check_thetas_) {
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    const double at_limit = k * limit + kq * limit * limit;
    if (at_limit < phi) {
      phi = at_limit;
      k_low = k;
      kq_low = kq;
    }
  }
  if (phi < r.max_abs) {
    r.max_abs = phi;
    if (!(r.max_abs > r.min_abs)) {
      r.feasible = false;
      r.reason = SpeedLimitRefusal(vehicle_.mappings[mapping].name, sign, dof_, r.min_abs, limit,
                                   {k_low, kq_low, phi},
                                   vehicle_.WorkingThrustFloor() > vehicle_.min_thrust);
    }
  }
  return r;
}

std::vector<int> DofPlanningProblem::Indices(const std::vector<std::string>& names) const {
  std::vector<int> out;
  for (const auto& n : names) {
    const int i = Index(n);
    if (i >= 0) out.push_back(i);
  }
  return out;
}

Eigen::MatrixXd DofPlanningProblem::PriorMatrix(const PriorInformation* prior) const {
  const int np = model_->num_parameters();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(np, np);
  if (!prior || prior->names.empty()) return M;
  if (prior->M.rows() != static_cast<Eigen::Index>(prior->names.size()) ||
      prior->M.cols() != prior->M.rows()) {
    throw std::invalid_argument("PriorInformation: M is " + std::to_string(prior->M.rows()) +
                                " x " + std::to_string(prior->M.cols()) + " for " +
                                std::to_string(prior->names.size()) +
                                " names. Violated constraint: square, one row per name");
  }
  std::vector<int> map;
  for (const auto& n : prior->names) map.push_back(Index(n));
  for (std::size_t a = 0; a < map.size(); ++a) {
    for (std::size_t b = 0; b < map.size(); ++b) {
      if (map[a] >= 0 && map[b] >= 0) M(map[a], map[b]) += prior->M(a, b);
    }
  }
  return M;
}

Eigen::MatrixXd DofPlanningProblem::TrialModel::Embed(const Eigen::MatrixXd& M, int np) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(np, np);
  for (int a = 0; a < M.rows(); ++a) {
    for (int b = 0; b < M.cols(); ++b) out(to_dof[a], to_dof[b]) = M(a, b);
  }
  return out;
}

namespace {
// The eta parameters a trial can reach: non-open-water (mapping, direction) pairs it uses.
std::vector<std::string> UsedEtas(const model::Vehicle& v, const model::TrialDesign& d) {
  std::vector<std::pair<std::string, int>> uses;  // mapping, sign bits (1 pos, 2 neg)
  for (const model::ForceDemand& demand : d.Demands()) {
    uses.push_back({demand.mapping, (demand.max >= 0 ? 1 : 0) | (demand.min < 0 ? 2 : 0)});
  }
  std::vector<std::string> etas;
  for (const auto& [name, bits] : uses) {
    const int mi = v.MappingIndex(name);
    if (mi < 0) continue;
    const auto& m = v.mappings[mi];
    if ((bits & 1) && !m.IsOpenWater(model::Direction::kPos)) {
      etas.push_back(model::EtaName(name, model::Direction::kPos));
    }
    if ((bits & 2) && !m.IsOpenWater(model::Direction::kNeg)) {
      etas.push_back(model::EtaName(name, model::Direction::kNeg));
    }
  }
  std::sort(etas.begin(), etas.end());
  etas.erase(std::unique(etas.begin(), etas.end()), etas.end());
  return etas;
}
}  // namespace

const DofPlanningProblem::TrialModel& DofPlanningProblem::ModelFor(
    const model::TrialDesign& design) const {
  const std::vector<std::string> etas = UsedEtas(vehicle_, design);
  std::string key;
  for (const auto& e : etas) key += e + ";";
  const std::lock_guard<std::mutex> lock(trial_models_mutex_);
  auto it = trial_models_.find(key);
  if (it != trial_models_.end()) return *it->second;
  auto tm = std::make_unique<TrialModel>();
  model::ModelStructure s = model::ModelStructure::Standard(vehicle_, dof_, {}, false);
  for (const std::string& eta : etas) s.Add(eta);
  tm->model = std::make_unique<model::DofModel>(vehicle_, WithFileEffects(vehicle_, dof_, s));
  for (const auto& n : tm->model->parameter_names()) tm->to_dof.push_back(Index(n));
  auto sub = [&](const Eigen::VectorXd& th) {
    Eigen::VectorXd out(tm->to_dof.size());
    for (std::size_t i = 0; i < tm->to_dof.size(); ++i) out[i] = th[tm->to_dof[i]];
    return out;
  };
  for (const auto& th : design_thetas_) tm->design_thetas.push_back(sub(th));
  // Check points that differ only in parameters this trial does not have are one point.
  for (const auto& th : check_thetas_) {
    Eigen::VectorXd t = sub(th);
    bool seen = false;
    for (const auto& u : tm->check_thetas) seen = seen || u == t;
    if (!seen) tm->check_thetas.push_back(std::move(t));
  }
  return *(trial_models_[key] = std::move(tm));
}

std::vector<Eigen::MatrixXd> DofPlanningProblem::Information(
    const model::TrialDesign& design) const {
  const auto input = model::MakeExcitation(vehicle_, design);
  const TrialModel& tm = ModelFor(design);
  std::vector<Eigen::MatrixXd> out;
  for (const auto& th : tm.design_thetas) {
    const TrialResponse r = SimulateTrial(*tm.model, th, *input, sensors_, design.duration,
                                          options_.max_step_s, true, options_.start_known);
    out.push_back(tm.Embed(r.M, model_->num_parameters()));
  }
  return out;
}

std::vector<Eigen::MatrixXd> DofPlanningProblem::DesignInformation(
    const TrialModel& tm, const model::Excitation& input, double duration,
    std::array<double, 2>* travel) const {
  std::vector<Eigen::MatrixXd> out;
  *travel = {0.0, 0.0};
  for (const auto& th : tm.design_thetas) {
    const TrialResponse r = SimulateTrial(*tm.model, th, input, design_sensors_, duration,
                                          options_.max_step_s, true, options_.start_known);
    (*travel)[0] = std::min((*travel)[0], r.position_min);
    (*travel)[1] = std::max((*travel)[1], r.position_max);
    out.push_back(tm.Embed(r.M, model_->num_parameters()));
  }
  return out;
}

std::vector<Eigen::MatrixXd> WithPrior(std::vector<Eigen::MatrixXd> information,
                                       const std::vector<Eigen::MatrixXd>& prior) {
  for (std::size_t j = 0; j < information.size() && j < prior.size(); ++j) {
    if (prior[j].size() == information[j].size()) information[j] += prior[j];
  }
  return information;
}

std::vector<double> DofPlanningProblem::CriterionValues(const std::vector<Eigen::MatrixXd>& M,
                                                        Criterion c,
                                                        const std::vector<int>& interest,
                                                        bool* any_singular) const {
  std::vector<double> out;
  if (any_singular) *any_singular = false;
  for (std::size_t j = 0; j < M.size() && j < design_thetas_.size(); ++j) {
    const CriterionValue v =
        EvaluateCriterion(RelativeInformation(M[j], design_thetas_[j]), c, interest);
    out.push_back(v.value);
    if (any_singular && v.singular) *any_singular = true;
  }
  return out;
}

namespace {
// Why a travel from `lo` to `hi` over the box does not fit: the pool side and its free length,
// or the tether's turns, with what would host it.
std::string TravelReason(const model::Pool& pool, model::Dof dof, double lo, double hi) {
  const auto F = [](double v) { return model::Significant(v, 4); };
  std::ostringstream s;
  const double span = hi - lo, free = pool.FreeTravel(dof);
  if (model::IsRotational(dof)) {
    s << "rotation " << F(span) << " rad (" << F(span / (2 * M_PI))
      << " turns) over the a priori box (from " << F(lo) << " to " << F(hi)
      << " rad) exceeds the tether limit of " << F(free) << " rad (max_turns " << F(pool.max_turns)
      << "): needs max_turns " << F(pool.ExtentFor(dof, span));
    return s.str();
  }
  const std::string_view side = model::Pool::SideName(dof);
  s << "travel " << F(span) << " m over the a priori box (from " << F(lo) << " to " << F(hi)
    << " m) exceeds the " << F(free) << " m of free " << side << " (" << F(pool.WallToWall(dof))
    << " m wall to wall - 2·" << F(pool.margin) << " m margin) by " << F(span - free)
    << " m: needs a pool " << side << " of " << F(pool.WallToWallFor(span)) << " m wall to wall";
  return s.str();
}
}  // namespace

TrialCheck DofPlanningProblem::Check(const model::TrialDesign& design) const {
  TrialCheck c;
  c.available = available();
  const auto input = model::MakeExcitation(vehicle_, design);
  const ThrustCheck tc = CheckThrust(vehicle_, *input, design.duration);
  c.thrust_min = tc.thrust_min;
  c.thrust_max_ratio = tc.thrust_max_ratio;
  c.reasons = tc.reasons;
  c.reversal = tc.reversal;
  c.thrust_out_of_range = tc.below_min || tc.overload;
  c.exceeds_duration =
      !(design.duration > 0) || design.duration > options_.max_trial_duration_s + 1e-9;
  if (!(design.duration > 0)) c.reasons.push_back("duration must be > 0 s");
  if (design.duration > options_.max_trial_duration_s + 1e-9) {
    std::ostringstream s;
    s << "duration " << design.duration << " s exceeds the " << options_.max_trial_duration_s
      << " s limit of a trial by " << design.duration - options_.max_trial_duration_s << " s";
    c.reasons.push_back(s.str());
  }
  double lo = 0.0, hi = 0.0;
  if (design.duration > 0) {
    const TrialModel& tm = ModelFor(design);
    for (const auto& th : tm.check_thetas) {
      const TrialResponse r =
          SimulateExcursion(*tm.model, th, *input, design.duration, std::min(step_s_, 0.1));
      lo = std::min(lo, r.position_min);
      hi = std::max(hi, r.position_max);
    }
  }
  c.travel = {lo, hi};
  c.span = hi - lo;
  if (std::isfinite(c.available) && c.span > c.available + 1e-9) {
    c.exceeds_travel = true;
    c.reasons.push_back(TravelReason(pool_, dof_, lo, hi));
  }
  c.feasible = c.reasons.empty();
  return c;
}

}  // namespace uuvplan::planner
