// Step 4 of the steady design (steady_design.h): the exact design's legs packed into trials.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

#include "design/steady_legs.h"

namespace uuvplan::planner::internal {
namespace {

// A direction of a mapping: which thrusters work and which way each pushes.
std::map<int, int> ThrusterSigns(const model::Vehicle& v, const std::string& mapping,
                                 double force) {
  std::map<int, int> s;
  const int mi = v.MappingIndex(mapping);
  if (mi < 0) return s;
  for (const auto& [ti, share] : v.mappings[mi].shares) {
    if (share != 0.0 && force != 0.0) s[ti] = share * force > 0 ? 1 : -1;
  }
  return s;
}

bool Compatible(const std::map<int, int>& a, const std::map<int, int>& b) {
  for (const auto& [t, s] : b) {
    auto it = a.find(t);
    if (it != a.end() && it->second != s) return false;
  }
  return true;
}

// Packs legs into trials, each a chain of legs alternating in direction, in compatible
// thrusters, within the pool and the trial duration limit.
class LegPacker {
 public:
  LegPacker(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
            std::vector<SteadyLeg> legs)
      : ctx_(ctx), o_(o), timer_(ctx, o), remaining_(std::move(legs)) {
    std::sort(remaining_.begin(), remaining_.end(),
              [](const SteadyLeg& a, const SteadyLeg& b) { return a.travel > b.travel; });
  }

  bool done() const { return remaining_.empty(); }

  /// The next trial: the longest-travelling leg left, then legs chained after it.
  model::TrialDesign NextTrial(const std::string& id) {
    chain_ = {remaining_.front()};
    remaining_.erase(remaining_.begin());
    signs_ = ThrusterSigns(ctx_.vehicle(), chain_[0].mapping, chain_[0].force);
    segs_ = {{chain_[0].force, chain_[0].duration(), chain_[0].mapping}};
    total_ = chain_[0].duration();
    tried_.assign(remaining_.size(), false);
    while (static_cast<int>(chain_.size()) < o_.max_legs_per_trial) {
      const int pick = PickNext();
      if (pick < 0) break;
      tried_[pick] = true;
      TryChain(pick);
    }
    return ChainDesign(id);
  }

 private:
  // A leg left, not tried for this chain, moving against the chain's last leg in compatible
  // thrusters, with the closest travel; -1 if none.
  int PickNext() const {
    const double dir = chain_.back().speed;
    int pick = -1;
    for (std::size_t r = 0; r < remaining_.size(); ++r) {
      if (tried_[r] || remaining_[r].speed * dir >= 0) continue;
      if (!Compatible(signs_,
                      ThrusterSigns(ctx_.vehicle(), remaining_[r].mapping, remaining_[r].force))) {
        continue;
      }
      if (pick < 0 || std::abs(remaining_[r].travel - chain_.back().travel) <
                          std::abs(remaining_[pick].travel - chain_.back().travel)) {
        pick = static_cast<int>(r);
      }
    }
    return pick;
  }

  // Appends leg `pick` (timed after the chain so far) if the trial stays feasible.
  void TryChain(int pick) {
    const double t_max = ctx_.options().max_trial_duration_s;
    SteadyLeg leg = remaining_[pick];
    const SteadyLegTimer::Timing t = timer_.TimeLeg(segs_, leg, t_max);
    if (!t.settled) return;
    leg.settle_s = t.settle_s;
    leg.hold_s = t.hold_s;
    if (total_ + leg.duration() > t_max) return;
    if (t.travel_hi - t.travel_lo > ctx_.available() - kSteadyTravelMargin) return;
    std::vector<model::SegmentDesign> trial_segs = segs_;
    trial_segs.push_back({leg.force, leg.duration(), leg.mapping});
    model::TrialDesign d;
    d.dof = ctx_.dof();
    d.kind = model::TrialKind::kSegments;
    d.mapping = chain_[0].mapping;
    d.segments = trial_segs;
    d.duration = total_ + leg.duration();
    if (!ctx_.Check(d).feasible) return;
    chain_.push_back(leg);
    segs_ = trial_segs;
    total_ += leg.duration();
    for (const auto& [th, s] : ThrusterSigns(ctx_.vehicle(), leg.mapping, leg.force)) {
      signs_[th] = s;
    }
    remaining_.erase(remaining_.begin() + pick);
    tried_.erase(tried_.begin() + pick);
  }

  // The chain as a steady trial (one leg) or a segments trial.
  model::TrialDesign ChainDesign(const std::string& id) const {
    model::TrialDesign d;
    d.id = id;
    d.dof = ctx_.dof();
    d.mapping = chain_[0].mapping;
    d.duration = total_;
    if (chain_.size() == 1) {
      d.kind = model::TrialKind::kSteady;
      d.force = chain_[0].force;
      return d;
    }
    d.kind = model::TrialKind::kSegments;
    for (auto s : segs_) {
      if (s.mapping == d.mapping) s.mapping.clear();  // the trial's mapping
      d.segments.push_back(s);
    }
    return d;
  }

  const DofPlanningProblem& ctx_;
  const SteadyDesignOptions& o_;
  SteadyLegTimer timer_;
  std::vector<SteadyLeg> remaining_;
  std::vector<SteadyLeg> chain_;
  std::map<int, int> signs_;
  std::vector<model::SegmentDesign> segs_;
  double total_ = 0.0;
  std::vector<bool> tried_;
};

}  // namespace

void PackTrials(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
                const std::string& id_prefix, SteadyDesignResult* result) {
  LegPacker packer(ctx, o, result->legs);
  const int np = ctx.model().num_parameters();
  result->information.assign(ctx.design_thetas().size(), Eigen::MatrixXd::Zero(np, np));
  int trial_no = 0;
  while (!packer.done()) {
    PlannedTrial trial;
    trial.design = packer.NextTrial(id_prefix + "-" + std::to_string(++trial_no));
    const TrialCheck check = ctx.Check(trial.design);
    trial.travel = check.travel;
    trial.thrust_min = check.thrust_min;
    const auto info = ctx.Information(trial.design);
    for (std::size_t j = 0; j < info.size(); ++j) result->information[j] += info[j];
    result->trials.push_back(trial);
    result->checks.push_back(check);
  }
}

}  // namespace uuvplan::planner::internal
