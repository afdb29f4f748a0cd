// The loop's validation tallies (loop_validation.h).
#include "support/loop_validation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::testing {
namespace {

using model::Significant;

double TruthOf(const model::Truth& truth, model::Dof dof, const std::string& name) {
  const auto d = truth.dofs.find(dof);
  if (d != truth.dofs.end()) {
    if (const auto p = d->second.params.find(name); p != d->second.params.end()) return p->second;
  }
  return model::NullValue(name);
}

EstimateCheck Check(const model::Truth& truth, model::Dof dof, const std::string& name,
                    double value, double sigma) {
  EstimateCheck c;
  c.dof = dof;
  c.name = name;
  c.value = value;
  c.sigma = sigma;
  c.truth = TruthOf(truth, dof, name);
  c.z = (c.value - c.truth) / c.sigma;
  c.within3 = std::abs(c.z) <= 3.0;  // the loop's criterion
  return c;
}

std::vector<EstimateCheck> EveryCheck(const model::Truth& truth,
                                      const planner::LoopIteration& last) {
  std::vector<EstimateCheck> out;
  for (const auto& [dof, params] : last.params) {
    for (const ident::ParameterEstimate& p : params) {
      if (p.state != ident::ParameterState::kEstimated) continue;
      out.push_back(Check(truth, dof, p.name, p.value, p.sigma));
    }
  }
  return out;
}

std::vector<EstimateCheck> InterestChecks(const model::Truth& truth,
                                          const std::vector<planner::DofProgress>& progress) {
  std::vector<EstimateCheck> out;
  for (const auto& p : progress) {
    for (const auto& q : p.interest) {
      if (!q.estimated || q.held) continue;
      out.push_back(Check(truth, p.dof, q.name, q.value, q.sigma));
    }
  }
  return out;
}

std::string IterationText(const model::Truth& truth, const planner::LoopIteration& it) {
  const model::TrialDesign& d = it.trial.design;
  std::ostringstream o;
  o << "  #" << it.index << " " << d.id << " (" << it.source << ", " << d.mapping << ", force "
    << Significant(d.force, 3) << ", offset " << Significant(d.offset, 3) << ", amplitude "
    << Significant(d.amplitude, 3) << ", " << Significant(d.duration, 3) << " s)"
    << (it.new_information ? "" : " no new information");
  for (const auto& p : it.progress) {
    if (p.dof != it.dof) continue;
    for (const auto& q : p.interest) {
      o << "\n      " << q.name << " = " << Significant(q.value, 4) << " ± "
        << Significant(q.sigma, 3) << " (truth " << Significant(TruthOf(truth, p.dof, q.name), 4)
        << ")" << (q.held ? " held" : "");
    }
    if (const auto e = it.params.find(p.dof); e != it.params.end()) {
      o << "\n      all:";
      for (const auto& x : e->second) {
        o << " " << x.name << " " << Significant(x.value, 4) << "±" << Significant(x.sigma, 2)
          << "[" << static_cast<int>(x.state) << "]";
      }
    }
    o << "\n      " << p.consistency.text;
    for (const auto& why : p.doubts) o << "\n      doubt: " << why;
  }
  for (const auto& n : it.notes) o << "\n      note: " << n;
  return o.str();
}

}  // namespace

LoopCaseOutcome RunLoopCase(const std::string& name, const model::Truth& truth,
                            const model::Pool& pool, std::uint64_t seed) {
  const auto t0 = std::chrono::steady_clock::now();
  LoopCaseOutcome c;
  c.name = name;
  for (const auto& [dof, params] : truth.dofs) c.dofs.push_back(dof);
  planner::LoopOptions lo;
  lo.seed = seed;
  lo.step.dofs = c.dofs;
  planner::ScheduleOptions so = lo.step.ScheduleAtTarget();
  so.dofs = c.dofs;
  const planner::PoolVerdict verdict = planner::JudgePool(truth.vehicle, pool, so);
  c.hosted = verdict.hosted;
  c.hostability = verdict.hostability;
  c.verdict = text::VerdictSentence(verdict, pool);
  for (const auto& d : verdict.dofs) {
    c.reach += std::string(c.reach.empty() ? "" : "; ") + std::string(model::DofName(d.dof)) + " " +
               d.reach.parameter + " n " + Significant(d.reach.trials, 3) + " ('" + d.reach.trial +
               "' after " + Significant(d.reach.now_percent, 3) +
               "%: " + Significant(d.reach.per_trial_percent, 3) + "% per trial, needs " +
               Significant(d.reach.needed_percent, 3) + "%)";
  }
  planner::VerdictOptions at_truth;
  at_truth.need_checks = -1;
  at_truth.judge_points = false;
  c.hosted_at_truth =
      planner::JudgePool(planner::VehicleOfTruth(truth), pool, so, nullptr, at_truth).hosted;
  // UUVPLAN_VERBOSE=1: the verdict's reason per DOF, then each trial, its DOF's estimates of
  // interest and their trust.
  const bool verbose = std::getenv("UUVPLAN_VERBOSE") != nullptr;
  for (const auto& d : verdict.dofs) {
    if (verbose) {
      std::cout << "  verdict " << model::DofName(d.dof) << ": "
                << text::DofReason(verdict, d, pool) << "\n";
    }
  }
  planner::LoopResult r = planner::RunLoop(truth, pool, lo, [&](const auto& it) {
    if (verbose) std::cout << IterationText(truth, it) << std::endl;
  });
  planner::ReadLoopEnd(verdict, &r);  // as `uuvplan loop` reads it
  c.status = r.status;
  c.message = text::LoopEndMessage(r, verdict, pool);
  c.trials = static_cast<int>(r.iterations.size());
  c.pool_time_s = r.pool_time;
  switch (c.hostability) {
    // All, at the target: the loop neither ends infeasible nor stuck short of the target.
    case planner::Hostability::kAll:
      c.agree =
          r.status != planner::LoopStatus::kInfeasible && r.status != planner::LoopStatus::kStuck;
      break;
    case planner::Hostability::kNone:
      c.agree = r.status != planner::LoopStatus::kConverged;
      break;
    case planner::Hostability::kPart:
      c.agree = true;
      break;  // measured below
  }
  if (r.converged) c.interest = InterestChecks(truth, r.progress);
  if (!r.iterations.empty()) c.every = EveryCheck(truth, r.iterations.back());
  c.most_repeats = planner::MostUninformativeRepeats(r.iterations);
  c.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

void LoopTally::Add(const LoopCaseOutcome& c, int max_repeats) {
  ++cases;
  hosted += c.hosted ? 1 : 0;
  agree += c.agree ? 1 : 0;
  if (c.hostability == planner::Hostability::kAll) hosted_agree += c.agree ? 1 : 0;
  if (c.hostability == planner::Hostability::kNone) {
    ++none;
    refused_agree += c.agree ? 1 : 0;
  }
  if (c.hostability == planner::Hostability::kPart) {
    ++part;
    part_converged += c.status == planner::LoopStatus::kConverged ? 1 : 0;
    part_outside += c.status == planner::LoopStatus::kInfeasible ? 1 : 0;
  }
  ++at_truth[c.hosted_at_truth ? 1 : 0][c.status == planner::LoopStatus::kConverged ? 1 : 0];
  if (!c.agree) {
    failures.push_back(c.name + ": the verdict says " +
                       std::string(planner::HostabilityName(c.hostability)) +
                       " but the loop ended " + std::string(planner::LoopStatusName(c.status)));
  }
  if (c.status == planner::LoopStatus::kConverged) {
    ++converged;
    for (const auto& e : c.interest) {
      ++interest;
      within3 += e.within3 ? 1 : 0;
    }
    for (const auto& e : c.every) {
      ++every;
      every_within3 += e.within3 ? 1 : 0;
    }
  }
  most_repeats = std::max(most_repeats, c.most_repeats);
  if (c.most_repeats > max_repeats) {
    failures.push_back(c.name + ": a design ran " + std::to_string(c.most_repeats) +
                       " times without new information");
  }
}

bool LoopTally::Pass() const {
  // ≥ 95% of the parameters of converged vehicles within 3σ.
  const bool coverage = interest == 0 || within3 >= 0.95 * interest;
  return failures.empty() && coverage;
}

std::string CaseLine(const LoopCaseOutcome& c) {
  std::ostringstream o;
  o << c.name << " [";
  for (std::size_t i = 0; i < c.dofs.size(); ++i) {
    o << (i ? " " : "") << model::DofName(c.dofs[i]);
  }
  o << "]: verdict " << planner::HostabilityName(c.hostability) << ", at the truth "
    << (c.hosted_at_truth ? "hosted" : "NOT hosted") << ", loop "
    << planner::LoopStatusName(c.status) << " after " << c.trials << " trial(s), pool time "
    << Significant(c.pool_time_s / 60.0, 3) << " min, wall " << Significant(c.wall_s, 3)
    << " s, most uninformative repeats " << c.most_repeats << (c.agree ? "" : "  DISAGREE");
  for (const auto& e : c.interest) {
    o << "\n    " << model::DofName(e.dof) << " " << e.name << " = " << Significant(e.value, 4)
      << " ± " << Significant(e.sigma, 3) << " (truth " << Significant(e.truth, 4) << ", "
      << Significant(e.z, 3) << "σ)" << (e.within3 ? "" : "  > 3σ");
  }
  const auto inside = std::count_if(c.every.begin(), c.every.end(),
                                    [](const EstimateCheck& e) { return e.within3; });
  o << "\n    every estimated parameter within 3σ: " << inside << "/" << c.every.size();
  for (const auto& e : c.every) {
    if (!e.within3)
      o << " (" << model::DofName(e.dof) << " " << e.name << ": " << Significant(e.z, 3) << "σ)";
  }
  o << "\n    reach: " << c.reach;
  if (c.status != planner::LoopStatus::kConverged) o << "\n    reason: " << c.message;
  return o.str();
}

std::string TallyText(const LoopTally& t) {
  std::ostringstream o;
  o << "cases " << t.cases << ", verdict all/part/none " << t.hosted << "/" << t.part << "/"
    << t.none << ", verdict and loop agree " << t.agree << "/" << t.cases
    << " (all: neither infeasible nor stuck " << t.hosted_agree << "/" << t.hosted
    << "; part: converged " << t.part_converged << ", infeasible outside the hostable part "
    << t.part_outside << ", other " << t.part - t.part_converged - t.part_outside
    << "; none: not converged " << t.refused_agree << "/" << t.none << "), converged "
    << t.converged << "; verdict at the truth hosted: converged " << t.at_truth[1][1] << "/"
    << t.at_truth[1][0] + t.at_truth[1][1] << ", not hosted: converged " << t.at_truth[0][1] << "/"
    << t.at_truth[0][0] + t.at_truth[0][1] << "; parameters of interest within 3σ " << t.within3
    << "/" << t.interest;
  if (t.interest > 0) o << " (" << Significant(100.0 * t.within3 / t.interest, 3) << "%)";
  o << "; every estimated parameter within 3σ " << t.every_within3 << "/" << t.every;
  if (t.every > 0) o << " (" << Significant(100.0 * t.every_within3 / t.every, 3) << "%)";
  o << "; most runs of one design without new information " << t.most_repeats;
  for (const auto& f : t.failures) o << "\n  FAIL " << f;
  return o.str();
}

}  // namespace uuvplan::testing
