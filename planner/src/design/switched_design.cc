// Robust optimal mapping-switched trials (see switched_design.h).
#include "uuvplan/planner/design/switched_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "design/sine_family_objective.h"
#include "uuvplan/model/util/parallel.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

// Shortest segment of a square wave (s): a shorter first or last piece is merged into its
// neighbour. CHOSEN: two RK4 steps of the fastest DOF; a pool team cannot command less.
constexpr double kShortestSegment = 0.2;
constexpr int kMultisineHarmonics = 3;

// Whether the two mappings can alternate: no thruster pushes one way in `pos` (phi > 0) and
// the other way in `neg` (phi < 0).
bool NoReversalBetween(const model::Vehicle& v, int pos, int neg) {
  for (const auto& [thruster, share_pos] : v.mappings[pos].shares) {
    for (const auto& [other, share_neg] : v.mappings[neg].shares) {
      if (thruster == other && share_pos != 0 && share_neg != 0 &&
          (share_pos > 0) != (share_neg < 0)) {
        return false;
      }
    }
  }
  return true;
}

// Sampled extremes of Σ r_i·sin(i·ω·t + p_i) over [0, T] (multisine crest, at 1/200 of the
// base period).
std::array<double, 2> WaveRange(const std::vector<model::SineComponent>& c, double duration) {
  model::SwitchedWave w;
  w.components = c;
  double lo = 0.0, hi = 0.0;
  const double h = std::min(0.05, 2 * M_PI / c.front().omega / 200.0);
  for (double t = 0.0; t <= duration; t += h) {
    const double x = w.Wave(t);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return {lo, hi};
}

// The highest harmonic of ω in a family's wave, for the sensors' bound on ω
// (SineFrequencyRange); 0 for the square, whose information is in its switches, not in the
// shape of a period (its pieces are at least kShortestSegment long).
int WaveHarmonics(model::InputFamily family) {
  switch (family) {
    case model::InputFamily::kMultisine:
      return kMultisineHarmonics;
    case model::InputFamily::kSwitchedSquare:
      return 0;
    default:
      return 1;
  }
}

class SwitchedProblem {
 public:
  SwitchedProblem(const DofPlanningProblem& ctx, model::InputFamily family,
                  const SineDesignOptions& o, const std::vector<Eigen::MatrixXd>& prior,
                  const SwitchPair& pair, double duration)
      : ctx_(ctx),
        family_(family),
        objective_(ctx, o, prior, 0.5 * (pair.pos_range.max_abs + pair.neg_range.max_abs), duration,
                   WaveHarmonics(family)),
        pair_(pair),
        duration_(duration) {
    if (pair.one_way == 0) {
      up_ = {pair.pos_range.min_abs, pair.pos_range.max_abs};
      down_ = {-pair.neg_range.min_abs, -pair.neg_range.max_abs};
    } else {  // both levels in the one mapping's one direction
      up_ = down_ = {pair.one_way * pair.pos_range.min_abs, pair.one_way * pair.pos_range.max_abs};
    }
    top_ = std::max({up_[0], up_[1], down_[0], down_[1]});
    bottom_ = std::min({up_[0], up_[1], down_[0], down_[1]});
  }

  static int VariablesOf(model::InputFamily family) {
    switch (family) {
      case model::InputFamily::kSwitchedSquare:
        return 5;
      case model::InputFamily::kSwitchedSine:
        return 4;
      default:
        return 2 * kMultisineHarmonics + 3;
    }
  }
  int num_variables() const { return VariablesOf(family_); }
  bool resolvable() const { return objective_.Resolvable(); }

  model::TrialDesign Decode(const double* x) const {
    model::TrialDesign d;
    d.dof = ctx_.dof();
    d.family = family_;
    d.duration = duration_;
    d.mapping = ctx_.vehicle().mappings[pair_.pos].name;
    if (family_ == model::InputFamily::kSwitchedSquare) {
      DecodeSquare(x, &d);
      if (pair_.one_way != 0) d.family = model::InputFamily::kPiecewise;
    } else {
      DecodeWave(x, &d);
    }
    return d;
  }

  bool Evaluate(const double* x, double* phi, double* g) const {
    const model::TrialDesign d = Decode(x);
    const auto input = model::MakeExcitation(ctx_.vehicle(), d);
    g[0] = objective_.TravelExcess(objective_.Criteria(ctx_.ModelFor(d), *input, d.duration, phi));
    return true;
  }

  // Starting points: the largest swing at the seed rule's frequency, centred (the crude
  // search: ±140 N, 30 s, from mid-pool), and at the lowest and highest frequencies allowed.
  // One way, the pool binds the mean force: the least one, and short pulses of the largest.
  std::vector<std::vector<double>> Starts() const {
    std::vector<std::vector<double>> out;
    const double low = pair_.one_way < 0 ? 1.0 : 0.0;  // the offset of the least |force|
    for (double v : {0.3, 0.5, 0.7}) {
      if (pair_.one_way != 0) {
        if (family_ == model::InputFamily::kSwitchedSquare) {
          out.push_back({1.0, 0.0, v, 0.0, 0.0});
          out.push_back({0.3, 0.0, v + 0.2, 0.2, 0.0});
        } else {
          out.push_back({v, 1.0, 0.3, 0.1, 0.0, 0.5, 0.5, 0.5, low});
        }
        continue;
      }
      switch (family_) {
        case model::InputFamily::kSwitchedSquare:
          out.push_back({1.0, 1.0, v, 0.5, 0.75});
          break;
        case model::InputFamily::kSwitchedSine:
          out.push_back({1.0, 0.5, v, 0.0});
          break;
        default:
          out.push_back({v, 1.0, 0.3, 0.1, 0.0, 0.5, 0.5, 1.0, 0.5});
          break;
      }
    }
    return out;
  }

 private:
  static double Lerp(double a, double b, double u) { return a + std::clamp(u, 0.0, 1.0) * (b - a); }

  // Square wave: positive during the first δ of each period, the period's share ψ elapsed at 0.
  void DecodeSquare(const double* x, model::TrialDesign* d) const {
    d->kind = model::TrialKind::kSegments;
    const double up = Lerp(up_[0], up_[1], x[0]);
    const double down = Lerp(down_[0], down_[1], x[1]);
    const double period = 2 * M_PI / objective_.Omega(x[2]);
    const double duty = pair_.one_way != 0 ? Lerp(0.02, 0.98, x[3]) : Lerp(0.1, 0.9, x[3]);
    const double psi = std::clamp(x[4], 0.0, 1.0) * period;
    const std::string& neg = ctx_.vehicle().mappings[pair_.neg].name;
    // Switching instants k·P - ψ and k·P - ψ + δ·P within (0, T); each piece's sign at its middle.
    std::vector<double> cuts = {0.0, duration_};
    for (int k = 0; k * period - psi < duration_ + period; ++k) {
      for (double c : {k * period - psi, k * period - psi + duty * period}) {
        if (c > 0 && c < duration_) cuts.push_back(c);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    double carry = 0.0;  // a first piece too short to command
    for (std::size_t i = 1; i < cuts.size(); ++i) {
      const double length = cuts[i] - cuts[i - 1];
      const bool positive = std::fmod(0.5 * (cuts[i] + cuts[i - 1]) + psi, period) < duty * period;
      if (length >= kShortestSegment) {
        d->segments.push_back({positive ? up : down, length + carry, positive ? "" : neg});
        carry = 0.0;
      } else if (!d->segments.empty()) {
        d->segments.back().duration += length;  // too short to command: the previous holds
      } else {
        carry += length;
      }
    }
    if (d->segments.empty()) d->segments.push_back({up, duration_, ""});
  }

  // Switched sine and multisine: offset + Σ components, within both thrust ranges.
  void DecodeWave(const double* x, model::TrialDesign* d) const {
    d->kind = model::TrialKind::kSwitched;
    d->mapping_neg = ctx_.vehicle().mappings[pair_.neg].name;
    d->floor_pos = pair_.pos_range.min_abs;
    d->floor_neg = pair_.neg_range.min_abs;
    const double top = top_, bottom = bottom_;
    if (family_ == model::InputFamily::kSwitchedSine) {
      const double a = Lerp(0.0, 0.5 * (top - bottom), x[0]);
      d->offset = Lerp(bottom + a, top - a, x[1]);
      d->components = {{a, objective_.Omega(x[2]), 2 * M_PI * std::clamp(x[3], 0.0, 1.0)}};
      return;
    }
    const double w = objective_.Omega(x[0]);
    for (int i = 0; i < kMultisineHarmonics; ++i) {
      d->components.push_back({std::clamp(x[1 + i], 1e-3, 1.0), (i + 1) * w,
                               2 * M_PI * std::clamp(x[1 + kMultisineHarmonics + i], 0.0, 1.0)});
    }
    // Crest factor: scale the sum so that its sampled range spans the share s of both ranges.
    const auto range = WaveRange(d->components, duration_);
    // The sampled crest misses the true one by up to (π/200)²/2 ≈ 1.2e-4 of the swing: 1e-3 off.
    const double scale = (1.0 - 1e-3) * Lerp(0.0, top - bottom, x[2 * kMultisineHarmonics + 1]) /
                         std::max(range[1] - range[0], 1e-12);
    for (auto& c : d->components) c.amplitude *= scale;
    d->offset =
        Lerp(bottom - scale * range[0], top - scale * range[1], x[2 * kMultisineHarmonics + 2]);
  }

  const DofPlanningProblem& ctx_;
  model::InputFamily family_;
  SineFamilyObjective objective_;
  SwitchPair pair_;
  double duration_;
  // Signed level ranges of the square's two halves (x = 0 → [0], x = 1 → [1]) and the
  // waves' crest bounds.
  std::array<double, 2> up_, down_;
  double top_ = 0.0, bottom_ = 0.0;
};

// The trial's information (real sensors), criterion per point, check and status.
void ScoreAndCheck(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                   const std::vector<Eigen::MatrixXd>& prior, SineDesignResult* r) {
  const model::TrialDesign& d = r->trial.design;
  r->information = ctx.Information(d);
  bool singular = false;
  r->criterion_per_point = ctx.CriterionValues(WithPrior(r->information, prior), o.criterion,
                                               ctx.Indices(o.interest), &singular);
  r->criterion = Aggregate(ctx.options().robustness, r->criterion_per_point);
  r->check = ctx.Check(d);
  r->trial.travel = r->check.travel;
  r->trial.thrust_min = r->check.thrust_min;
  if (!r->check.feasible) {
    r->status = DesignStatus::kInfeasible;
    std::ostringstream s;
    s << "the best " << model::InputFamilyName(d.family) << " design violates a hard constraint:";
    for (const auto& reason : r->check.reasons) s << " " << reason << ";";
    r->message = s.str();
  } else if (singular) {
    r->status = DesignStatus::kInfeasible;
    r->message = "the information of this trial (with the prior) is singular";
  } else {
    r->status = DesignStatus::kOk;
  }
}

}  // namespace

std::vector<SwitchPair> SwitchPairs(const DofPlanningProblem& ctx) {
  const model::Vehicle& v = ctx.vehicle();
  std::vector<SwitchPair> pairs;
  for (int p : v.MappingsOf(ctx.dof())) {
    for (int n : v.MappingsOf(ctx.dof())) {
      // A mapping whose thrusters all reverse alternates with itself: the zero-mean families
      // (a square, sine or multisine about zero), which keep the vehicle about its start.
      if (p == n ? !v.Reverses(p) : !NoReversalBetween(v, p, n)) continue;
      if (!v.mappings[p].IsOpenWater(model::Direction::kPos) &&
          !v.mappings[n].IsOpenWater(model::Direction::kNeg)) {
        continue;  // neither half's eta known: m is confounded with both
      }
      SwitchPair pair{p, n, ctx.ForceRangeFor(p, +1), ctx.ForceRangeFor(n, -1)};
      if (pair.pos_range.feasible && pair.neg_range.feasible) pairs.push_back(pair);
    }
  }
  // The pairs that reverse no thruster first: of two that pose the same problem the first is
  // solved (CoveredByAnotherPair), and the seeds' rule is kept where it costs nothing.
  std::stable_partition(pairs.begin(), pairs.end(),
                        [](const SwitchPair& pair) { return pair.pos != pair.neg; });
  return pairs;
}

std::vector<SwitchPair> OneWayPairs(const DofPlanningProblem& ctx, const OneWayHint& hint) {
  const model::Vehicle& v = ctx.vehicle();
  std::vector<SwitchPair> out;
  for (int mi : v.MappingsOf(ctx.dof())) {
    if (!hint.mapping.empty() && v.mappings[mi].name != hint.mapping) continue;
    for (int sign : {+1, -1}) {
      if (hint.sign != 0 && sign != hint.sign) continue;
      const model::Direction dir = sign > 0 ? model::Direction::kPos : model::Direction::kNeg;
      if (!v.mappings[mi].IsOpenWater(dir)) continue;  // eta unknown: m confounded with it
      const ForceRange r = ctx.ForceRangeFor(mi, sign);
      if (r.feasible) out.push_back({mi, mi, r, r, sign});
    }
  }
  return out;
}

namespace {

// One optimisation of DesignSwitched: a family over one pair of mappings, at one duration.
struct PairTask {
  model::InputFamily family;
  SwitchPair pair;
  double duration;
};
struct PairSolution {
  SolverSummary summary;
  model::TrialDesign design;  ///< decoded from summary.x
};

// Pair `a` covers pair `b` when both of each are in open water (no η to tell them apart: the
// information depends on φⁿ(t) alone) and each of a's force ranges has b's floor (the clamp at
// a crossing) and reaches at least as far: every design of b is one of a. Mirror-placed
// thrusters (a BlueROV2's two vertical ones) alternated either way cover each other; a
// reversible mapping alternating with itself is covered by a pair of its vectored thrusters
// whose forward thrust exceeds the reverse (a T200: 51.5 against 40 N).
bool Covers(const DofPlanningProblem& ctx, const SwitchPair& a, const SwitchPair& b) {
  const auto open = [&](const SwitchPair& p) {
    const auto& m = ctx.vehicle().mappings;
    return m[p.pos].IsOpenWater(model::Direction::kPos) &&
           m[p.neg].IsOpenWater(model::Direction::kNeg);
  };
  const auto contains = [](const ForceRange& x, const ForceRange& y) {
    return x.min_abs == y.min_abs && x.max_abs >= y.max_abs;
  };
  return a.one_way == b.one_way && open(a) && open(b) && contains(a.pos_range, b.pos_range) &&
         contains(a.neg_range, b.neg_range);
}

// Whether another pair covers `pair`: solving it could only find a design the other's search
// space holds. Of pairs that cover each other (the same problem) the first is kept.
bool CoveredByAnotherPair(const DofPlanningProblem& ctx, const std::vector<SwitchPair>& pairs,
                          const SwitchPair& pair) {
  bool earlier = true;
  for (const SwitchPair& other : pairs) {
    if (&other == &pair) {
      earlier = false;
      continue;
    }
    if (Covers(ctx, other, pair) && (earlier || !Covers(ctx, pair, other))) return true;
  }
  return false;
}

// The family's optimisations, one per switch pair (DesignSwitched's doc).
std::vector<PairTask> PairTasks(const DofPlanningProblem& ctx, model::InputFamily family,
                                const SineDesignOptions& o, const OneWayHint& hint) {
  const double longest = o.fixed_duration_s > 0
                             ? o.fixed_duration_s
                             : std::min(o.max_duration_s > 0 ? o.max_duration_s : 1e300,
                                        ctx.options().max_trial_duration_s);
  std::vector<SwitchPair> pairs = SwitchPairs(ctx);
  // No pair alternates (one mapping per direction, both reversing the same propellers: URIS
  // surge, VSOR yaw, heave): the square one way, within one direction's force range. With the
  // input bounded in amplitude, optimal inputs are bang-bang (the classic result of input
  // design, e.g. Goodwin & Payne 1977), so the two-level square stands for the one-way
  // multisine too: the multisine took 2.3× the square's time on URIS yaw (13.1 s against
  // 5.7 s) and the square won every one-way row of docs/planning.md §1b.
  if (pairs.empty() && o.one_way_families && family == model::InputFamily::kSwitchedSquare) {
    pairs = OneWayPairs(ctx, hint);
  }
  std::vector<PairTask> tasks;
  for (const SwitchPair& pair : pairs) {
    if (CoveredByAnotherPair(ctx, pairs, pair)) continue;
    // One way the vehicle drifts: the longest trial is not the best; the sine's duration is.
    const double duration = pair.one_way != 0 && o.fixed_duration_s <= 0 && hint.duration_s > 0
                                ? hint.duration_s
                                : longest;
    tasks.push_back({family, pair, duration});
  }
  return tasks;
}

PairSolution SolvePair(const DofPlanningProblem& ctx, const PairTask& t, const SineDesignOptions& o,
                       const std::vector<Eigen::MatrixXd>& prior) {
  SwitchedProblem sp(ctx, t.family, o, prior, t.pair, t.duration);
  if (!sp.resolvable()) return {};
  DesignProblem p;
  p.num_variables = sp.num_variables();
  p.lower.assign(p.num_variables, 0.0);
  p.upper.assign(p.num_variables, 1.0);
  const auto starts = sp.Starts();
  p.x0 = starts[1];
  p.num_scenarios = static_cast<int>(ctx.design_thetas().size());
  p.num_constraints = 1;
  p.evaluate = [&sp](const double* x, double* phi, double* g) { return sp.Evaluate(x, phi, g); };
  SolverOptions so = ctx.options().solver;
  so.robustness = ctx.options().robustness;
  // More variables than the sine's three: a budget in proportion (DIRECT-L's cost grows with
  // the dimension), measured on ROMEO surge; COBYLA's 15 per variable from each of the four
  // starts changed no case's predicted σ by more than 0.5% against 30 and took a third less
  // time (docs/planning.md §Designs 1b).
  so.max_global_evaluations = 100 * p.num_variables;
  so.max_local_evaluations = 15 * p.num_variables;
  so.extra_starts = starts;
  PairSolution out;
  out.summary = Solve(SolverBackend::kNlopt, p, so);
  if (out.summary.is_success()) out.design = sp.Decode(out.summary.x.data());
  return out;
}

// Every task solved, on the context's threads (PlannerOptions::threads): each writes only its
// own slot, so the solutions do not depend on the number of threads.
std::vector<PairSolution> SolveAll(const DofPlanningProblem& ctx,
                                   const std::vector<PairTask>& tasks, const SineDesignOptions& o,
                                   const std::vector<Eigen::MatrixXd>& prior) {
  // The costliest first (evaluations ∝ variables, SolvePair's budgets), so that no thread is
  // left with a multisine while the others idle; the order of solving changes no solution.
  std::vector<std::size_t> order(tasks.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto cost = [&](std::size_t i) { return SwitchedProblem::VariablesOf(tasks[i].family); };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
  std::vector<PairSolution> out(tasks.size());
  model::ParallelFor(tasks.size(), ctx.options().Threads(), [&](std::size_t k) {
    out[order[k]] = SolvePair(ctx, tasks[order[k]], o, prior);
  });
  return out;
}

// The family's best solution (the first of equal objectives, in pair order), scored and
// checked.
SineDesignResult BestOfFamily(const DofPlanningProblem& ctx, model::InputFamily family,
                              const SineDesignOptions& o, const std::vector<Eigen::MatrixXd>& prior,
                              const std::string& id, const PairSolution* first,
                              const PairSolution* last) {
  SineDesignResult result;
  double best = -std::numeric_limits<double>::infinity();
  for (const PairSolution* s = first; s != last; ++s) {
    if (!s->summary.is_success() || s->summary.objective <= best) continue;
    best = s->summary.objective;
    result.summary = s->summary;
    result.trial.design = s->design;
    result.trial.design.id = id;
  }
  if (!std::isfinite(best)) {
    result.status = DesignStatus::kFailed;
    result.message = std::string("no ") + std::string(model::InputFamilyName(family)) +
                     " design: no pair of mappings alternates without reversal, or none fits "
                     "(within the pool, the thrusters' ranges and the waves the sensors resolve)";
    return result;
  }
  ScoreAndCheck(ctx, o, prior, &result);
  return result;
}

}  // namespace

SineDesignResult DesignSwitched(const DofPlanningProblem& ctx, model::InputFamily family,
                                const SineDesignOptions& o,
                                const std::vector<Eigen::MatrixXd>& prior, const std::string& id,
                                const OneWayHint& hint) {
  const std::vector<PairSolution> solved = SolveAll(ctx, PairTasks(ctx, family, o, hint), o, prior);
  return BestOfFamily(ctx, family, o, prior, id, solved.data(), solved.data() + solved.size());
}

SineDesignResult DesignInertiaTrial(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                                    const std::vector<Eigen::MatrixXd>& prior,
                                    const std::string& id) {
  SineDesignResult best = DesignSine(ctx, o, prior, id);
  // One way, the single sine's duration (it fits the drift to the pool), mapping and direction
  // (the better of the two; they mirror each other on a symmetric vehicle): half the cost of
  // trying both, measured on URIS yaw (docs/planning.md §1b).
  OneWayHint hint;
  if (best.status == DesignStatus::kOk) {
    const model::TrialDesign& d = best.trial.design;  // a sine, or the steady run that won
    const bool pos = d.Pushes(d.mapping, +1), neg = d.Pushes(d.mapping, -1);
    hint = {d.duration, d.mapping, pos == neg ? 0 : pos ? +1 : -1};
  }
  best.notes.push_back("single sine: " +
                       (best.status == DesignStatus::kOk
                            ? "robust criterion " + model::Significant(best.criterion, 4)
                            : best.message));
  // Every family's pairs solved at once (on the context's threads), then judged family by
  // family in the order of o.families.
  std::vector<PairTask> tasks;
  std::vector<std::size_t> ends;
  for (model::InputFamily family : o.families) {
    for (PairTask& t : PairTasks(ctx, family, o, hint)) tasks.push_back(std::move(t));
    ends.push_back(tasks.size());
  }
  const std::vector<PairSolution> solved = SolveAll(ctx, tasks, o, prior);
  for (std::size_t f = 0; f < o.families.size(); ++f) {
    const model::InputFamily family = o.families[f];
    SineDesignResult r = BestOfFamily(
        ctx, family, o, prior, id, solved.data() + (f ? ends[f - 1] : 0), solved.data() + ends[f]);
    std::ostringstream s;
    s << model::InputFamilyName(r.status == DesignStatus::kOk ? r.trial.design.family : family)
      << ": "
      << (r.status == DesignStatus::kOk ? "robust criterion " + model::Significant(r.criterion, 4)
                                        : r.message);
    best.notes.push_back(s.str());
    if (r.status != DesignStatus::kOk) continue;
    if (best.status != DesignStatus::kOk || r.criterion > best.criterion) {
      r.notes.insert(r.notes.begin(), best.notes.begin(), best.notes.end());
      const std::string suffix = "-sine";
      if (model::EndsWith(id, suffix)) {
        r.trial.design.id = id.substr(0, id.size() - suffix.size()) + "-" +
                            std::string(model::InputFamilyName(r.trial.design.family));
      }
      best = std::move(r);
    }
  }
  return best;
}

}  // namespace uuvplan::planner
