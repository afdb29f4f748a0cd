// Determinacy of the parameters of interest and the loop-family completion (determinacy.h).
#include "uuvplan/planner/determinacy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "format.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/criteria.h"
#include "uuvplan/planner/design_loop.h"
#include "uuvplan/planner/thrust_limits.h"

namespace uuvplan::planner {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 100·(worst σ over the design points)/(smallest |θ| there) of parameter i; +inf when a point
// leaves it unreached (NaN σ) or unidentifiable (+inf σ), or its a priori value is 0.
double WorstPercent(const DofContext& ctx, const std::vector<Eigen::MatrixXd>& info, int i) {
  double worst = 0.0, nominal = kInf;
  for (std::size_t j = 0; j < info.size() && j < ctx.design_thetas().size(); ++j) {
    const Eigen::VectorXd& th = ctx.design_thetas()[j];
    const double s = PredictedSigma(info[j], th)[i];
    worst = std::isnan(s) ? kInf : std::max(worst, s);
    nominal = std::min(nominal, std::abs(th[i]));
  }
  return nominal > 0 && std::isfinite(nominal) ? 100.0 * worst / nominal : kInf;
}

// The parameters of interest (determinacy.h): m, the drag of interest, the holdable η.
std::vector<std::string> InterestNames(const DofContext& ctx,
                                       const std::vector<Eigen::MatrixXd>& info) {
  std::vector<std::string> names = {model::param::kMass};
  const int iq = ctx.Index(model::param::kQuadraticDrag);
  const bool kq = iq >= 0 && WorstPercent(ctx, info, iq) <= kInsignificantPercent;
  names.push_back(kq || ctx.Index(model::param::kLinearDrag) < 0 ? model::param::kQuadraticDrag
                                                                  : model::param::kLinearDrag);
  const model::Vehicle& v = ctx.vehicle();
  for (const auto& n : ctx.model().parameter_names()) {
    if (!model::StartsWith(n, model::param::kEtaPrefix)) continue;
    const std::string rest = n.substr(std::string(model::param::kEtaPrefix).size());
    const std::size_t dot = rest.rfind('.');
    const int mi = v.MappingIndex(rest.substr(0, dot));
    const int sign = rest.substr(dot + 1) == "pos" ? +1 : -1;
    if (mi >= 0 && DirectionForceRange(v, mi, sign).feasible) names.push_back(n);
  }
  return names;
}

// The robust D criterion of (info + trial information) and the trial's information.
struct Candidate {
  PlannedTrial trial;
  TrialCheck check;
  std::vector<Eigen::MatrixXd> information;
  double criterion = -kInf;
};

double RobustD(const DofContext& ctx, const std::vector<Eigen::MatrixXd>& info,
               const std::vector<Eigen::MatrixXd>& add) {
  std::vector<Eigen::MatrixXd> total = info;
  for (std::size_t j = 0; j < total.size(); ++j) total[j] += add[j];
  return Aggregate(ctx.options().robustness, ctx.CriterionValues(total, Criterion::kD, {}));
}

void ConsiderSine(const DofContext& ctx, SineDesignOptions so,
                  const std::vector<Eigen::MatrixXd>& info, const std::string& id,
                  Candidate* best) {
  so.criterion = Criterion::kD;
  so.interest.clear();
  const SineDesignResult sn = DesignSine(ctx, so, info, id);
  if (sn.status != DesignStatus::kOk) return;
  const double c = RobustD(ctx, info, sn.information);
  if (!(c > best->criterion + 1e-9)) return;
  *best = {sn.trial, sn.check, sn.information, c};
}

void ConsiderSteadyLegs(const DofContext& ctx, const SteadyDesignOptions& o,
                        const std::vector<Eigen::MatrixXd>& info, const std::string& id,
                        Candidate* best) {
  for (const SteadyLeg& leg : MakeSteadyCandidates(ctx, o).legs) {
    const model::TrialDesign d = LegDesign(leg, ctx.dof(), id);
    std::vector<Eigen::MatrixXd> m = ctx.Information(d);
    const double c = RobustD(ctx, info, m);
    if (!(c > best->criterion + 1e-9)) continue;
    const TrialCheck check = ctx.Check(d);
    if (!check.feasible) continue;
    PlannedTrial t;
    t.design = d;
    t.travel = check.travel;
    t.thrust_min = check.thrust_min;
    *best = {t, check, std::move(m), c};
  }
}

}  // namespace

Determinacy InterestDeterminacy(const DofContext& ctx, const std::vector<Eigen::MatrixXd>& info) {
  Determinacy d;
  d.determined = true;
  d.worst_percent = -1.0;
  for (const std::string& n : InterestNames(ctx, info)) {
    const double p = WorstPercent(ctx, info, ctx.Index(n));
    if (p > d.worst_percent) {
      d.worst_percent = p;
      d.worst = n;
    }
    if (p <= kInsignificantPercent) continue;
    d.determined = false;
    d.undetermined.push_back(
        n + (std::isfinite(p) ? " (σ " + internal::Fmt(p) + "% of its value)" : " (no trial)"));
  }
  return d;
}

CompletionResult CompleteWithLoopFamilies(const DofContext& ctx, const SineDesignOptions& sine,
                                          const SteadyDesignOptions& steady,
                                          std::vector<Eigen::MatrixXd>* info,
                                          const std::string& id_prefix, int max_trials) {
  CompletionResult out;
  for (int n = 1; n <= max_trials; ++n) {
    const Determinacy det = InterestDeterminacy(ctx, *info);
    if (det.determined) break;
    const std::string id = id_prefix + "-" + std::to_string(n);
    Candidate best;
    // An undetermined η first, in its own direction (the loop's step 2), else D on all.
    for (const std::string& u : det.undetermined) {
      if (!model::StartsWith(u, model::param::kEtaPrefix) || std::isfinite(best.criterion)) continue;
      const std::string name = u.substr(0, u.find(' '));
      const std::string rest = name.substr(std::string(model::param::kEtaPrefix).size());
      SineDesignOptions so = sine;
      so.mappings = {rest.substr(0, rest.rfind('.'))};
      so.sign = rest.substr(rest.rfind('.') + 1) == "pos" ? +1 : -1;
      so.open_water_only = false;
      ConsiderSine(ctx, so, *info, id, &best);
    }
    const bool only_etas = std::all_of(det.undetermined.begin(), det.undetermined.end(),
                                       [](const std::string& u) {
                                         return model::StartsWith(u, model::param::kEtaPrefix);
                                       });
    // No trial pushes the way an undetermined η needs: no other family reaches it either.
    if (!std::isfinite(best.criterion) && only_etas) break;
    if (!std::isfinite(best.criterion)) {
      ConsiderSine(ctx, sine, *info, id, &best);
      ConsiderSteadyLegs(ctx, steady, *info, id, &best);
    }
    if (!std::isfinite(best.criterion)) break;
    for (std::size_t j = 0; j < info->size(); ++j) (*info)[j] += best.information[j];
    out.notes.push_back(std::string(model::DofName(ctx.dof())) + ": '" + id + "' (" +
                        std::string(model::TrialKindName(best.trial.design.kind)) +
                        ", the loop's next-trial design) added for " + model::Join(det.undetermined));
    out.trials.push_back(best.trial);
    out.checks.push_back(best.check);
  }
  return out;
}

}  // namespace uuvplan::planner
