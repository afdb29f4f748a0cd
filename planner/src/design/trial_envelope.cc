#include "uuvplan/planner/design/trial_envelope.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "uuvplan/model/excitation.h"
#include "uuvplan/planner/design/fisher_information.h"

namespace uuvplan::planner {

PositionEnvelope EnvelopeOf(const DofPlanningProblem& ctx, const model::TrialDesign& design,
                            int points) {
  if (points < 2 || !(design.duration > 0)) {
    throw std::invalid_argument("EnvelopeOf: needs >= 2 points and a duration > 0");
  }
  const auto input = model::MakeExcitation(ctx.vehicle(), design);
  const DofPlanningProblem::TrialModel& tm = ctx.ModelFor(design);
  const double dt = design.duration / (points - 1);
  const double step = std::min(ctx.step_s(), 0.1);  // as DofPlanningProblem::Check
  PositionEnvelope e;
  auto add = [&](const Eigen::VectorXd& theta, bool centre) {
    const PositionTrace trace = TracePosition(*tm.model, theta, *input, design.duration, dt, step);
    const std::size_t n = trace.position.size();
    if (e.t.empty()) {
      for (std::size_t i = 0; i < n; ++i) e.t.push_back(std::min(i * dt, design.duration));
      e.low.assign(n, trace.position[0]);
      e.high.assign(n, trace.position[0]);
    }
    for (std::size_t i = 0; i < n && i < e.t.size(); ++i) {
      e.low[i] = std::min(e.low[i], trace.position[i]);
      e.high[i] = std::max(e.high[i], trace.position[i]);
    }
    if (centre) e.nominal = trace.position;
  };
  add(tm.design_thetas.front(), true);  // DesignPoints(): centre first
  for (const auto& theta : tm.check_thetas) add(theta, false);
  return e;
}

namespace {

std::vector<double> SampleTimes(const model::Excitation& input, double duration, int points) {
  std::vector<double> t;
  for (int i = 0; i < points; ++i) t.push_back(duration * i / (points - 1));
  const double eps = 1e-9 * std::max(1.0, duration);
  for (double b : input.Breakpoints()) {
    if (b <= 0 || b >= duration) continue;
    t.push_back(b - eps);
    t.push_back(b);
  }
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace

ThrusterForces ThrusterForcesOf(const model::Vehicle& vehicle, const model::TrialDesign& design,
                                int points) {
  if (points < 2 || !(design.duration > 0)) {
    throw std::invalid_argument("ThrusterForcesOf: needs >= 2 points and a duration > 0");
  }
  const auto input = model::MakeExcitation(vehicle, design);
  ThrusterForces f;
  f.t = SampleTimes(*input, design.duration, points);
  const std::size_t nt = vehicle.thrusters.size();
  f.force.assign(nt, std::vector<double>(f.t.size(), 0.0));
  f.used.assign(nt, false);
  for (std::size_t k = 0; k < f.t.size(); ++k) {
    double phi = 0.0;
    int mapping = -1;
    input->Sample(f.t[k], &phi, &mapping);
    f.nominal.push_back(phi);
    if (mapping < 0 || mapping >= static_cast<int>(vehicle.mappings.size())) continue;
    for (const auto& [thruster, share] : vehicle.mappings[mapping].shares) {
      f.force[thruster][k] = share * phi;  // tau_i = share_i·phi_n (ref 000 Table I)
      if (share != 0) f.used[thruster] = true;
    }
  }
  return f;
}

TrialProfile SampleProfile(const model::Vehicle& vehicle, const model::TrialDesign& design,
                           double max_spacing_s) {
  TrialProfile p;
  if (!(design.duration > 0) || !(max_spacing_s > 0)) return p;
  const auto input = model::MakeExcitation(vehicle, design);
  const int points = static_cast<int>(std::ceil(design.duration / max_spacing_s - 1e-9)) + 1;
  p.t = SampleTimes(*input, design.duration, std::max(points, 2));
  p.t.erase(std::unique(p.t.begin(), p.t.end()), p.t.end());
  for (double t : p.t) {
    double phi = 0.0;
    int mapping = -1;
    input->Sample(t, &phi, &mapping);
    p.force.push_back(phi);
    p.mapping.push_back(mapping >= 0 ? vehicle.mappings[mapping].name : "");
  }
  return p;
}

StartPosition StartOf(const model::Pool& pool, model::Dof dof,
                      const std::array<double, 2>& travel) {
  StartPosition s;
  const double free = pool.FreeTravel(dof), span = travel[1] - travel[0];
  // A travel longer than the free one starts from the negative end; without a limit (an
  // untethered rotation), from the heading the trial starts at.
  const double slack = std::isfinite(free) ? std::max(0.0, free - span) : 0.0;
  const double from_end = CentreTravel(slack, travel).start;
  if (model::IsRotational(dof)) {
    s.value = from_end * 180.0 / M_PI;
    s.unit = "deg";
    s.from = std::isfinite(free) ? "the heading at the tether's counter-clockwise end of its " +
                                       std::string(model::DofName(dof)) + " travel"
                                 : "the heading the trial starts at";
    return s;
  }
  static const char* const kFrom[3] = {"the rear wall (negative surge)",
                                       "the port wall (negative sway)",
                                       "the surface (negative heave, z down)"};
  s.value = pool.margin + from_end;
  s.unit = "m";
  s.from = kFrom[model::Index(dof) % 3];
  return s;
}

void AddReplayFields(const model::Vehicle& vehicle, const model::Pool& pool, PlannedTrial* trial) {
  // A fast wave sampled 0.1 s apart does not replay it (VSOR heave: 7.7 mm of travel off):
  // at least 40 samples per period of its fastest component, linear interpolation then within
  // (2π/40)²/8 = 0.3% of its amplitude.
  const model::TrialDesign& d = trial->design;
  double omega = d.kind == model::TrialKind::kSine ? d.omega : 0.0;
  for (const auto& c : d.components) omega = std::max(omega, c.omega);
  const double spacing = omega > 0 ? std::min(0.1, 2 * M_PI / omega / 40) : 0.1;
  trial->profile = SampleProfile(vehicle, d, spacing);
  trial->start = StartOf(pool, trial->design.dof, trial->travel);
}

}  // namespace uuvplan::planner
