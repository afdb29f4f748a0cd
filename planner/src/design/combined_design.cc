// Combined sine designs for a multi-DOF model (see combined_design.h).
#include "uuvplan/planner/design/combined_design.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "design/combined_envelope.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/thrust_limits.h"
#include "uuvplan/planner/design/trial_envelope.h"

namespace uuvplan::planner {
namespace {

using internal::CombinedInputs;

// (1/p)·log det F, or −∞ when F is not positive definite (a parameter the design does not
// excite).
double LogDetPerParameter(const Eigen::MatrixXd& F) {
  const Eigen::LLT<Eigen::MatrixXd> llt(F);
  if (llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  return 2.0 * llt.matrixLLT().diagonal().array().log().sum() / static_cast<double>(F.rows());
}

// Largest |φ| the DOF's mapping gives both ways (thrust_limits.h).
double ForceMax(const model::Vehicle& vehicle, int mapping) {
  const ForceRange pos = DirectionForceRange(vehicle, mapping, +1);
  const ForceRange neg = DirectionForceRange(vehicle, mapping, -1);
  return std::min(pos.max_abs, neg.max_abs);
}

// What every evaluation of one planning run shares.
struct Setup {
  Setup(const model::MultiDofModel& m, const model::Vehicle& v, const model::Pool& p,
        const CombinedDesignOptions& opt)
      : model(m), vehicle(v), pool(p), o(opt) {}
  const model::MultiDofModel& model;
  const model::Vehicle& vehicle;
  const model::Pool& pool;
  const CombinedDesignOptions& o;
  std::vector<int> moved, mapping;  // the moved DOFs (model order) and their mappings
  std::vector<double> force_max;    // per moved DOF
  std::vector<double> omega_max;    // per moved DOF: o.omega_max, or less as its sensors allow
  std::vector<int> covered;         // θ indices the criterion covers: the moved DOFs'
  Eigen::VectorXd scale;            // their nominal magnitudes (S)
  std::vector<Eigen::VectorXd> design_points, check_points;

  // Design variables, each in [0, 1] or [−1, 1], per moved DOF: offset/F, amplitude/F, and
  // (ω − ω_min)/(ω_max − ω_min) with the DOF's ω_max.
  model::CombinedTrialDesign Trial(const double* x) const {
    model::CombinedTrialDesign trial;
    for (int i : moved) trial.dofs.push_back(model.dof(i));
    trial.id = "combined-" + model::DofList(trial.dofs);
    trial.duration = o.duration_s;
    for (std::size_t d = 0; d < moved.size(); ++d) {
      model::TrialDesign in;
      in.dof = model.dof(moved[d]);
      in.kind = model::TrialKind::kSine;
      in.mapping = vehicle.mappings[mapping[d]].name;
      in.duration = o.duration_s;
      in.offset = x[3 * d] * force_max[d];
      in.amplitude = x[3 * d + 1] * force_max[d];
      in.omega = o.omega_min + x[3 * d + 2] * (omega_max[d] - o.omega_min);
      trial.inputs.push_back(in);
    }
    return trial;
  }
  // S·F·S of the covered parameters at θ (the others known).
  Eigen::MatrixXd InformationAt(const Eigen::VectorXd& theta, const CombinedInputs& in) const {
    const Eigen::MatrixXd M =
        JointInformation(model, theta, in.conditions, vehicle.sensors, o.duration_s, o.step_s);
    Eigen::MatrixXd F(covered.size(), covered.size());
    for (std::size_t a = 0; a < covered.size(); ++a) {
      for (std::size_t b = 0; b < covered.size(); ++b) {
        F(a, b) = scale[a] * M(covered[a], covered[b]) * scale[b];
      }
    }
    return F;
  }
};

// The box's points as θ: the criterion's (its design points) and the constraints' (centre,
// every vertex, the swept axis inside).
void AddBoxPoints(const ParameterBox& box, Setup* s) {
  for (const ParameterValues& p : box.DesignPoints())
    s->design_points.push_back(ThetaAt(s->model, p));
  s->check_points = {ThetaAt(s->model, box.nominal)};
  for (const ParameterValues& p : box.CheckPoints(2))
    s->check_points.push_back(ThetaAt(s->model, p));
  for (std::size_t a = 0; a < box.axes.size(); ++a) {
    if (box.axes[a].name != s->o.swept_axis) continue;
    constexpr int kSweep = 17;
    std::vector<double> factors(box.axes.size(), 1.0);
    for (int k = 1; k < kSweep - 1; ++k) {
      factors[a] = box.axes[a].lo + (box.axes[a].hi - box.axes[a].lo) * k / (kSweep - 1);
      s->check_points.push_back(ThetaAt(s->model, box.At(factors)));
    }
  }
}

// The largest ω of a moved DOF's sine: o.omega_max, or 2π over the shortest period its sensors
// resolve (o.samples_per_period samples of the faster); InputError when that is below
// o.omega_min.
double FastestOmega(const model::Vehicle& vehicle, model::Dof dof, const CombinedDesignOptions& o) {
  const auto sensors = vehicle.sensors.find(dof);
  const double period =
      sensors == vehicle.sensors.end() ? 0.0 : sensors->second.ShortestPeriod(o.samples_per_period);
  if (!(period > 0)) return o.omega_max;
  const double omega = std::min(o.omega_max, 2 * M_PI / period);
  if (omega < o.omega_min) {
    throw model::InputError(
        "vehicle '" + vehicle.name + "' sensors." + std::string(model::DofName(dof)) + ": " +
        model::Significant(o.samples_per_period / period, 3) + " Hz resolves waves of " +
        model::Significant(period, 3) + " s and longer (" +
        model::Significant(o.samples_per_period, 3) +
        " samples per period); a combined design's slowest wave has ω " +
        model::Significant(o.omega_min, 3) + " rad/s (a faster sensor is needed)");
  }
  return omega;
}

Setup MakeSetup(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                const model::Pool& pool, const CombinedDesignOptions& o, const ParameterBox& box) {
  if (!(o.samples_per_period >= 2)) {
    throw model::InputError(
        "CombinedDesignOptions: samples_per_period",
        "expected >= 2 (Nyquist), got " + model::Significant(o.samples_per_period, 3));
  }
  Setup s(model, vehicle, pool, o);
  for (int i = 0; i < model.num_dofs(); ++i) {
    const model::Dof dof = model.dof(i);
    if (std::find(o.dofs.begin(), o.dofs.end(), dof) == o.dofs.end()) continue;
    const int mapping = CombinedMappingOf(vehicle, dof);
    if (mapping < 0) {
      throw model::InputError("vehicle '" + vehicle.name + "' has no mapping of " +
                              std::string(model::DofName(dof)) + " for a combined design");
    }
    s.moved.push_back(i);
    s.mapping.push_back(mapping);
    s.force_max.push_back(ForceMax(vehicle, mapping));
    s.omega_max.push_back(FastestOmega(vehicle, dof, o));
  }
  // Scale of each covered parameter: its nominal magnitude; a bias's 1% of the DOF's largest
  // force (nominal 0).
  const Eigen::VectorXd nominal = ThetaAt(model, box.nominal);
  std::vector<double> scale;
  for (int j = 0; j < model.num_parameters(); ++j) {
    const int i = model.DofIndex(model.LocalName(j).first);
    const auto d = std::find(s.moved.begin(), s.moved.end(), i);
    if (d == s.moved.end()) continue;
    s.covered.push_back(j);
    scale.push_back(nominal[j] != 0 ? std::abs(nominal[j])
                                    : 0.01 * s.force_max[d - s.moved.begin()]);
  }
  s.scale = Eigen::Map<Eigen::VectorXd>(scale.data(), static_cast<Eigen::Index>(scale.size()));
  bool measured = false;
  for (int i = 0; i < model.num_dofs(); ++i)
    measured = measured || vehicle.sensors.count(model.dof(i));
  if (!measured) {
    throw model::InputError("vehicle '" + vehicle.name + "' declares no sensor of " +
                            model::DofList(o.dofs) +
                            ": a combined design has nothing to measure "
                            "(sensors.<dof> in the vehicle file)");
  }
  AddBoxPoints(box, &s);
  return s;
}

// Variables per moved DOF (offset/F, amplitude/F, ω scaled) from `o.start`, the criterion at
// the design points, the constraints at the check points (the thrusters bounded from the sines).
DesignProblem ProblemOf(const Setup& s) {
  DesignProblem problem;
  problem.num_variables = static_cast<int>(3 * s.moved.size());
  for (int i : s.moved) {
    problem.lower.insert(problem.lower.end(), {-1.0, 0.0, 0.0});
    problem.upper.insert(problem.upper.end(), {1.0, 1.0, 1.0});
    const auto start = s.o.start.find(s.model.dof(i));
    const std::array<double, 3> x0 =
        start == s.o.start.end() ? std::array<double, 3>{0.0, 0.1, 0.1} : start->second;
    problem.x0.insert(problem.x0.end(), x0.begin(), x0.end());
  }
  problem.num_scenarios = static_cast<int>(s.design_points.size());
  problem.num_constraints = s.model.num_dofs() + 3;
  problem.evaluate = [&s](const double* x, double* phi, double* g) {
    const model::CombinedTrialDesign trial = s.Trial(x);
    const CombinedInputs in = internal::InputsOf(s.model, s.vehicle, trial);
    CombinedEnvelope e = internal::TrackEnvelope(s.model, in, trial, s.check_points, s.o);
    if (!e.finite) return false;
    internal::ThrustBound(s.vehicle, trial, &e);
    const std::vector<double> c = internal::Constraints(s.model, e, s.vehicle, s.pool);
    std::copy(c.begin(), c.end(), g);
    for (std::size_t j = 0; j < s.design_points.size(); ++j) {
      const double v = LogDetPerParameter(s.InformationAt(s.design_points[j], in));
      phi[j] = std::isfinite(v) ? v : -1e3;
    }
    return true;
  };
  return problem;
}

// The start: each translational DOF's travel centred in the pool's free length or width
// (trial_envelope.h StartOf), a rotation at the options' heading.
void PlaceStart(const Setup& s, CombinedDesign* d) {
  for (int i = 0; i < s.model.num_dofs(); ++i) {
    const model::Dof dof = s.model.dof(i);
    d->start.push_back(model::IsRotational(dof)
                           ? s.o.start_heading_rad
                           : StartOf(s.pool, dof, d->envelope.travel[i]).value);
  }
}

// Cramér–Rao bounds over the design points: σ_j = √(F⁻¹)_jj (in θ's units); infinite, with a
// reason, where F is singular (the trial does not determine every parameter).
void AddCramerRao(const Setup& s, CombinedDesign* d) {
  const std::size_t p = s.covered.size();
  for (int c : s.covered) {
    d->parameters.push_back(s.model.parameter_names()[c]);
    d->units.push_back(s.model.ParameterUnit(c));
  }
  d->worst_sigma.assign(p, 0.0);
  d->worst_relative_sigma.assign(p, 0.0);
  const CombinedInputs in = internal::InputsOf(s.model, s.vehicle, d->trial);
  for (const Eigen::VectorXd& theta : s.design_points) {
    const Eigen::MatrixXd F = s.InformationAt(theta, in);
    const Eigen::LLT<Eigen::MatrixXd> llt(F);
    if (llt.info() != Eigen::Success) {
      d->worst_sigma.assign(p, std::numeric_limits<double>::infinity());
      d->worst_relative_sigma.assign(p, std::numeric_limits<double>::infinity());
      d->reasons.push_back(
          "the trial does not determine every parameter of the DOFs it moves "
          "(singular Fisher information at a point of the box)");
      return;
    }
    const Eigen::MatrixXd cov = llt.solve(Eigen::MatrixXd::Identity(F.rows(), F.cols()));
    for (std::size_t c = 0; c < p; ++c) {
      const double sigma = std::sqrt(std::max(cov(c, c), 0.0)) * s.scale[c];
      const double value = std::abs(theta[s.covered[c]]);
      d->worst_sigma[c] = std::max(d->worst_sigma[c], sigma);
      d->worst_relative_sigma[c] = value > 0 ? std::max(d->worst_relative_sigma[c], sigma / value)
                                             : std::numeric_limits<double>::quiet_NaN();
    }
  }
}

// How far the envelope reaches in each direction the constraints bound: per translational DOF
// both ends of its travel, per rotation its turns.
std::vector<double> ReachOfAxes(const model::MultiDofModel& model, const CombinedEnvelope& e) {
  std::vector<double> r;
  for (int i = 0; i < model.num_dofs(); ++i) {
    if (model::IsRotational(model.dof(i))) {
      r.push_back(e.turns);
    } else {
      r.insert(r.end(), {-e.travel[i][0], e.travel[i][1]});
    }
  }
  return r;
}

// Exchange step of semi-infinite programming (the constraints hold for every θ of the box, a
// continuum): the check set's vertices and sweep miss interior extremes of the travel (a
// spin-rate resonance peaks inside the box), so the probes that reach farther than the check
// set join it. Returns how many joined.
std::size_t AddExtremes(const Setup& s, const model::CombinedTrialDesign& trial,
                        const std::vector<Eigen::VectorXd>& probes,
                        std::vector<Eigen::VectorXd>* check_points) {
  const CombinedInputs in = internal::InputsOf(s.model, s.vehicle, trial);
  std::vector<double> reach =
      ReachOfAxes(s.model, internal::TrackEnvelope(s.model, in, trial, *check_points, s.o));
  std::vector<int> best(reach.size(), -1);
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const std::vector<double> r =
        ReachOfAxes(s.model, internal::TrackEnvelope(s.model, in, trial, {probes[k]}, s.o));
    for (std::size_t c = 0; c < r.size(); ++c) {
      if (r[c] > reach[c] + 1e-3) {
        reach[c] = r[c];
        best[c] = static_cast<int>(k);
      }
    }
  }
  std::sort(best.begin(), best.end());
  best.erase(std::unique(best.begin(), best.end()), best.end());
  std::size_t added = 0;
  for (int k : best) {
    if (k < 0) continue;
    check_points->push_back(probes[k]);
    ++added;
  }
  return added;
}

}  // namespace

CombinedDesignOptions::CombinedDesignOptions() {
  solver.robustness = Robustness::kMaximin;
  // Local search from the options' start: a global search (DIRECT-L, 200 evaluations) over the
  // 9 variables of the ASV's surge+sway+yaw design took 58 s and found no feasible point
  // (docs/planning.md §5).
  solver.global = GlobalMethod::kNone;
  solver.max_local_evaluations = 300;
}

CombinedDesign PlanCombinedDesign(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                                  const model::Pool& pool, const CombinedDesignOptions& o) {
  CombinedDesign out;
  const ParameterBox box = JointAPrioriBox(vehicle, model, o.box, &out.notes);
  Setup s = MakeSetup(model, vehicle, pool, o, box);
  std::vector<Eigen::VectorXd> probes;
  for (const ParameterValues& p : box.Sample(o.probe_points, o.probe_seed))
    probes.push_back(ThetaAt(model, p));
  DesignProblem problem = ProblemOf(s);
  SolverOptions solver = o.solver;
  for (int round = 0; round <= o.exchange_rounds; ++round) {
    out.solver = Solve(SolverBackend::kNlopt, problem, solver);
    if (out.solver.x.empty()) {
      out.reasons.push_back("the optimiser found no design: " + out.solver.message);
      return out;
    }
    if (AddExtremes(s, s.Trial(out.solver.x.data()), probes, &s.check_points) == 0) break;
    problem.x0 = out.solver.x;  // warm start on the larger check set: a polish
    solver.max_local_evaluations = o.exchange_evaluations;
  }
  out.trial = s.Trial(out.solver.x.data());
  out.criterion = out.solver.objective;
  // The verdict over the check set and every probe.
  std::vector<Eigen::VectorXd> verdict_points = s.check_points;
  verdict_points.insert(verdict_points.end(), probes.begin(), probes.end());
  out.envelope = EnvelopeOf(model, vehicle, out.trial, verdict_points, o);
  out.reasons = internal::Reasons(model, out.envelope, vehicle, pool);
  PlaceStart(s, &out);
  AddCramerRao(s, &out);
  out.fits = out.reasons.empty();
  return out;
}

}  // namespace uuvplan::planner
