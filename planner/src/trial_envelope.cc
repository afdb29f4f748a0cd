#include "uuvplan/planner/trial_envelope.h"

#include <algorithm>
#include <stdexcept>

#include "uuvplan/model/excitation.h"
#include "uuvplan/planner/fisher_information.h"

namespace uuvplan::planner {

PositionEnvelope EnvelopeOf(const DofContext& ctx, const model::TrialDesign& design, int points) {
  if (points < 2 || !(design.duration > 0)) {
    throw std::invalid_argument("EnvelopeOf: needs >= 2 points and a duration > 0");
  }
  const auto input = model::MakeExcitation(ctx.vehicle(), design);
  const DofContext::TrialModel& tm = ctx.ModelFor(design);
  const double dt = design.duration / (points - 1);
  const double step = std::min(ctx.step_s(), 0.1);  // as DofContext::Check
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
      f.force[thruster][k] = share * phi;  // tau_i = share_i·phi_n (seed 000 Table I)
      if (share != 0) f.used[thruster] = true;
    }
  }
  return f;
}

}  // namespace uuvplan::planner
