// The sentence of a stuck DOF (next_trial_policy.h, StuckReason): which limit keeps the best
// trial from informing the bottleneck parameter, and what would lift it. The pool is tested
// by planning the DOF again in a pool with twice the free travel; the thrust range by the
// trial's demands against the thrusters' range; what remains is the trial family itself.
#include <cmath>
#include <sstream>

#include "design/speed_limit.h"
#include "loop/next_trial_policy.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner::internal {
namespace {

using model::Dof;

std::string GainText(const CandidateGain& g) {
  std::string s = "cut σ(" + g.parameter + ") by " + model::Significant(100.0 * g.gain, 2) + "%";
  if (std::isfinite(g.trials_to_target)) {
    return s + " (about " + model::Significant(std::ceil(g.trials_to_target), 3) +
           " such trials to the target)";
  }
  return s + " (no number of such trials reaches the target)";
}

// The pool with twice the free travel on every side (margins kept).
model::Pool Doubled(const model::Pool& pool) {
  model::Pool big = pool;
  big.name = pool.name + " (free travel doubled)";
  big.length = 2 * pool.length - 2 * pool.margin;
  big.width = 2 * pool.width - 2 * pool.margin;
  big.depth = 2 * pool.depth - 2 * pool.margin;
  return big;
}

// "" or the thrust-range sentence when a demand of the trial is within 5% of its mapping's
// largest force in that direction (DirectionForceRange).
std::string ThrustLimit(const model::Vehicle& vehicle, const PlannedTrial& trial,
                        const std::string& unit) {
  for (const auto& demand : trial.design.Demands()) {
    const int mi = vehicle.MappingIndex(demand.mapping);
    if (mi < 0) continue;
    for (const double f : {demand.min, demand.max}) {
      if (f == 0.0) continue;
      const ForceRange range = DirectionForceRange(vehicle, mi, f > 0 ? +1 : -1);
      if (range.feasible && std::abs(f) >= 0.95 * range.max_abs) {
        return "thrust range: the trial asks " + model::Significant(std::abs(f), 3) + " " + unit +
               " of the " + model::Significant(range.max_abs, 3) + " " + unit + " " +
               demand.mapping + " gives in that direction; stronger thrusters would lift it";
      }
    }
  }
  return "";
}

// Whether a mapping of `dof` may reverse its thrusters (model::Vehicle::Reverses).
bool ReversesAny(const model::Vehicle& vehicle, Dof dof) {
  for (int m : vehicle.MappingsOf(dof)) {
    if (vehicle.Reverses(m)) return true;
  }
  return false;
}

}  // namespace

std::string StuckReason(Planner& planner, const model::Campaign& campaign,
                        const DofProgress& progress, const ident::DofIdentification* id,
                        const PlannedTrial& trial, const CandidateGain& gain) {
  const Dof dof = progress.dof;
  const std::string name(model::DofName(dof));
  const std::string unit = model::IsRotational(dof) ? "N·m" : "N";
  std::ostringstream m;
  m << name << " " << gain.parameter << " is stuck at "
    << model::Significant(progress.worst_percent, 3) << "% (target "
    << model::Significant(planner.options.target_percent, 3) << "%): the best next trial ('"
    << trial.design.id << "', " << model::TrialKindName(trial.design.kind) << " in "
    << trial.design.mapping << ") would " << GainText(gain) << ". Limit: ";
  std::string pool_note;
  if (!model::IsRotational(dof)) {
    const model::Pool big = Doubled(planner.pool);
    Planner relaxed{planner.vehicle, big, planner.options, {}, planner.run};
    Decision scratch;
    CandidateGain g2;
    std::string why;
    const double free = planner.pool.FreeTravel(dof);
    const bool planned = PlanCandidate(relaxed, campaign, progress, id, &scratch, &g2, &why);
    if (planned && !g2.negligible) {
      m << "pool size — the trial travels "
        << model::Significant(trial.travel[1] - trial.travel[0], 3) << " m of the "
        << model::Significant(free, 3) << " m of free " << model::Pool::SideName(dof)
        << "; in a pool with twice the free travel (" << model::Significant(big.WallToWall(dof), 3)
        << " m wall to wall) the best trial would " << GainText(g2);
      return m.str();
    }
    pool_note = planned ? "; a pool with twice the free travel would not lift it (its best trial "
                          "would " +
                              GainText(g2) + ")"
                        : "";
  }
  const std::string thrust = ThrustLimit(planner.vehicle, trial, unit);
  if (!thrust.empty()) {
    m << thrust << pool_note;
  } else if (model::IsRotational(dof)) {
    m << "rotation-rate limit — designs keep below "
      << model::Significant(SpeedLimitOf(planner.vehicle, dof, planner.options.schedule.planner), 3)
      << " rad/s, where the drag of interest hardly acts; a higher max_rotation_rate in the "
         "vehicle file (if the vehicle's tether and drag fit allow it) would lift it";
  } else if (ReversesAny(planner.vehicle, dof)) {
    m << "the trial families — a thruster reverses only in the switched families about zero, "
         "and those do not lift it; a model that needs less of the drag would"
      << pool_note;
  } else {
    m << "no reversal — the planner's trials push one direction per mapping and never reverse a "
         "thruster within a trial, so the drag is seen over one speed range; trials that "
         "reverse, or a model that needs less of it, would lift it"
      << pool_note;
  }
  return m.str();
}

}  // namespace uuvplan::planner::internal
