// Thruster constraints of a trial (see thrust_limits.h).
#include "uuvplan/planner/design/thrust_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {

std::string FloorName(const model::Vehicle& v) {
  return v.WorkingThrustFloor() > v.min_thrust ? "the thrusters' dead band edge (thrust.dead_band)"
                                               : "min_thrust";
}

ForceRange DirectionForceRange(const model::Vehicle& v, int mapping, int sign) {
  ForceRange r;
  if (mapping < 0 || mapping >= static_cast<int>(v.mappings.size())) {
    r.reason = "no such mapping";
    return r;
  }
  const auto& m = v.mappings[mapping];
  double min_share = std::numeric_limits<double>::infinity();
  double max_abs = std::numeric_limits<double>::infinity();
  for (const auto& [ti, share] : m.shares) {
    if (share == 0.0) continue;
    const double s = std::abs(share);
    min_share = std::min(min_share, s);
    const auto& th = v.thrusters.at(ti);
    const bool forward = share * sign > 0;
    const double limit = forward ? th.MaxForwardThrust() : th.MaxReverseThrust();
    max_abs = std::min(max_abs, limit / s);
  }
  if (!std::isfinite(min_share)) {
    r.reason = "mapping '" + m.name + "' has no working thruster";
    return r;
  }
  r.min_abs = v.WorkingThrustFloor() / min_share;
  r.max_abs = max_abs;
  r.feasible = r.max_abs > r.min_abs;
  if (!r.feasible) {
    std::ostringstream s;
    s << "mapping '" << m.name << "' " << (sign > 0 ? "positive" : "negative")
      << ": the thrusters give at most |phi| = " << model::Significant(r.max_abs, 4) << " "
      << model::ForceUnit(m.dof) << " but " << FloorName(v) << " needs "
      << model::Significant(r.min_abs, 4) << " " << model::ForceUnit(m.dof);
    r.reason = s.str();
  }
  return r;
}

ThrustCheck CheckThrust(const model::Vehicle& v, const model::Excitation& input, double duration) {
  ThrustCheck c;
  const int nt = static_cast<int>(v.thrusters.size());
  std::vector<double> fwd(nt), rev(nt);
  for (int i = 0; i < nt; ++i) {
    fwd[i] = v.thrusters[i].MaxForwardThrust();
    rev[i] = v.thrusters[i].MaxReverseThrust();
  }
  std::vector<double> times;
  constexpr int kGrid = 4000;
  for (int k = 0; k <= kGrid; ++k) times.push_back(duration * k / kGrid);
  for (double b : input.Breakpoints()) {
    if (b <= 0 || b >= duration) continue;
    const double eps = 1e-9 * std::max(1.0, b);
    times.push_back(b - eps);
    times.push_back(b);
  }
  std::sort(times.begin(), times.end());
  std::vector<int> sign_seen(nt, 0);  // bit 1: positive, bit 2: negative
  std::vector<double> tau_min(nt, std::numeric_limits<double>::infinity());
  std::vector<double> ratio_max(nt, 0.0);
  double worst_min = std::numeric_limits<double>::infinity();
  int worst_min_thruster = -1;
  double worst_min_t = 0.0;
  for (double t : times) {
    const int mi = input.Mapping(t);
    if (mi < 0 || mi >= static_cast<int>(v.mappings.size())) continue;
    const double phi = input.Force(t);
    for (const auto& [ti, share] : v.mappings[mi].shares) {
      if (share == 0.0) continue;
      const double tau = share * phi;
      sign_seen[ti] |= tau > 0 ? 1 : (tau < 0 ? 2 : 3);
      const double a = std::abs(tau);
      if (a < tau_min[ti]) tau_min[ti] = a;
      if (a < worst_min) {
        worst_min = a;
        worst_min_thruster = ti;
        worst_min_t = t;
      }
      const double limit = tau >= 0 ? fwd[ti] : rev[ti];
      ratio_max[ti] =
          std::max(ratio_max[ti], limit > 0 ? a / limit : std::numeric_limits<double>::infinity());
    }
  }
  c.thrust_min = std::isfinite(worst_min) ? worst_min : 0.0;
  for (int i = 0; i < nt; ++i) {
    c.thrust_max_ratio = std::max(c.thrust_max_ratio, ratio_max[i]);
    if (sign_seen[i] == 3 && !v.thrusters[i].reversible) {
      c.reversal = true;
      c.reasons.push_back("thruster " + v.thrusters[i].name +
                          " reverses (pushes both ways during the trial); seed 000 §III-B keeps "
                          "the sign of every thruster's force");
    }
    if (ratio_max[i] > 1.0 + 1e-9) {
      c.overload = true;
      std::ostringstream s;
      s << "thruster " << v.thrusters[i].name << " is asked " << 100.0 * (ratio_max[i] - 1.0)
        << "% beyond the thrust its command range gives";
      c.reasons.push_back(s.str());
    }
  }
  const double floor = v.WorkingThrustFloor();
  if (worst_min_thruster >= 0 && worst_min < floor - 1e-9) {
    c.below_min = true;
    std::ostringstream s;
    s << "thruster " << v.thrusters[worst_min_thruster].name << " falls to |tau| = " << worst_min
      << " N at t = " << worst_min_t << " s, below " << FloorName(v) << " " << floor << " N by "
      << floor - worst_min << " N";
    c.reasons.push_back(s.str());
  }
  return c;
}

}  // namespace uuvplan::planner
