// The design–identify loop (design_loop.h): identification by ident::Identify, a priori trials
// by PlanSchedule, sequential trials by DesignNextTrial, virtual trials by RunVirtualTrial.
#include "uuvplan/planner/design_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/virtual_pool.h"
#include "uuvplan/planner/thrust_limits.h"

namespace uuvplan::planner {
namespace {

using model::Dof;

bool StartsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

std::string Fmt(double v, int precision = 3) {
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

// splitmix64, as model::SimulateCampaign mixes the seed of trial i: the loop's trial i gets the
// noise `uuvplan simulate` would give it.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The trial's id as a campaign names it: the file stem ("trials/surge-sine.csv" → "surge-sine").
std::string EntryId(const model::TrialEntry& e) {
  return std::filesystem::path(e.file).stem().string();
}

bool Plannable(const model::Vehicle& v, Dof dof) {
  const auto s = v.sensors.find(dof);
  const bool sensed = s != v.sensors.end() && (s->second.position || s->second.velocity);
  return sensed && !v.MappingsOf(dof).empty();
}

void RequirePlannable(const model::Vehicle& v, Dof dof, const std::string& where) {
  const std::string name(model::DofName(dof));
  if (v.MappingsOf(dof).empty()) {
    throw model::InputError(where, "vehicle '" + v.name + "' has no thrust mapping on " + name +
                                       ": the loop cannot excite it (add a mapping, or drop " +
                                       "--dof " + name + ")");
  }
  const auto s = v.sensors.find(dof);
  if (s == v.sensors.end() || (!s->second.position && !s->second.velocity)) {
    throw model::InputError(where, "vehicle '" + v.name + "' has no " + name + " sensor (sensors." +
                                       name + "): nothing to identify it from");
  }
}

// State shared by the steps of one loop (or the single step of `next`): the a priori schedule
// of each DOF, planned once.
struct Planner {
  const model::Vehicle& vehicle;
  const model::Pool& pool;
  const DesignLoopOptions& options;
  std::map<Dof, ScheduleResult> schedules;

  const ScheduleResult& APriori(Dof dof) {
    auto it = schedules.find(dof);
    if (it != schedules.end()) return it->second;
    ScheduleOptions so = options.schedule;
    so.dofs = {dof};
    so.prior.clear();
    return schedules.emplace(dof, PlanSchedule(vehicle, pool, so)).first->second;
  }
};

struct Decision {
  NextStatus status = NextStatus::kInfeasible;
  std::string message;
  std::vector<DofProgress> progress;
  Dof dof = Dof::kSurge;
  std::string source;
  PlannedTrial trial;
  PredictedPrecision predicted;
  std::vector<std::string> notes;
};

// Estimates of a DOF as DesignNextTrial wants them (box centre, and prior information from the
// covariance, rows in `names` order): the values the data decided — estimated, or dropped to 0
// as insignificant. An estimate is left out (the design keeps the a priori value, without prior
// information on it) when it is insignificant (percentile error above `max_percent`: its ±2σ box
// would span zero) or physically implausible (m outside half the lower to twice the upper a
// priori inertia bound, negative drag, η outside (0, 1.5]): a diverged fit must not steer the
// design, e.g. to a time constant of milliseconds.
void DesignInputs(const model::Vehicle& vehicle, const ident::DofIdentification& id,
                  double max_percent, ParameterValues* estimates, std::vector<std::string>* names,
                  Eigen::MatrixXd* covariance, std::vector<std::string>* notes) {
  const auto bounds = vehicle.InertiaBounds(id.dof);
  auto plausible = [&](const std::string& n, double v) {
    if (n == model::param::kMass) return v >= 0.5 * bounds[0] && v <= 2.0 * bounds[1];
    if (n == model::param::kLinearDrag || n == model::param::kQuadraticDrag) return v >= 0.0;
    if (StartsWith(n, model::param::kEtaPrefix)) return v > 0.0 && v <= 1.5;
    return true;
  };
  std::vector<int> idx;
  for (std::size_t j = 0; j < id.params.size(); ++j) {
    const ident::ParameterEstimate& p = id.params[j];
    if (p.state == ident::ParameterState::kDropped) (*estimates)[p.name] = p.value;
    if (p.state != ident::ParameterState::kEstimated) continue;
    if (!(std::isfinite(p.sigma) && p.sigma > 0 && std::isfinite(p.value))) continue;
    const double percent = p.value != 0.0 ? 100.0 * p.sigma / std::abs(p.value)
                                          : std::numeric_limits<double>::infinity();
    const bool nuisance = p.name == model::param::kBias || p.name == model::param::kBiasStep;
    if (!plausible(p.name, p.value)) {
      notes->push_back(p.name + " = " + Fmt(p.value) +
                       " is implausible: the design keeps its a priori value");
      continue;
    }
    if (!nuisance && !(percent < max_percent)) {
      notes->push_back(p.name + " = " + Fmt(p.value) + " ± " + Fmt(p.sigma) +
                       " is insignificant: the design keeps its a priori value");
      continue;
    }
    (*estimates)[p.name] = p.value;
    names->push_back(p.name);
    idx.push_back(static_cast<int>(j));
  }
  const int n = static_cast<int>(idx.size());
  covariance->resize(n, n);
  const bool full = id.covariance.rows() == static_cast<int>(id.params.size()) &&
                    id.covariance.cols() == static_cast<int>(id.params.size());
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      if (full) {
        (*covariance)(a, b) = id.covariance(idx[a], idx[b]);
      } else {
        (*covariance)(a, b) = a == b ? id.params[idx[a]].sigma * id.params[idx[a]].sigma : 0.0;
      }
    }
  }
}

// (mapping, direction) of an installation coefficient "eta.<mapping>.<pos|neg>".
std::pair<std::string, int> EtaDirection(const std::string& name) {
  const std::string rest = name.substr(std::string(model::param::kEtaPrefix).size());
  const std::size_t dot = rest.rfind('.');
  return {rest.substr(0, dot), rest.substr(dot + 1) == "pos" ? +1 : -1};
}

int Sign(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// Whether a trial pushes in `sign` with `mapping` at some time (what excites that η).
bool Uses(const model::TrialDesign& d, const std::string& mapping, int sign) {
  switch (d.kind) {
    case model::TrialKind::kSteady:
      return d.mapping == mapping && Sign(d.force) == sign;
    case model::TrialKind::kSine:
      return d.mapping == mapping && (Sign(d.offset + std::abs(d.amplitude)) == sign ||
                                      Sign(d.offset - std::abs(d.amplitude)) == sign);
    case model::TrialKind::kSegments:
      for (const auto& s : d.segments) {
        if ((s.mapping.empty() ? d.mapping : s.mapping) == mapping && Sign(s.force) == sign) {
          return true;
        }
      }
      return false;
  }
  return false;
}

// The (mapping, direction) pairs a logged trial pushed in: the sign of its force_<dof> column
// on every row, with the row's mapping (the `mapping` column, else the trial's).
std::set<std::pair<std::string, int>> PushedDirections(const model::TrialEntry& e) {
  std::set<std::pair<std::string, int>> out;
  const auto& f = e.log.force[model::Index(e.dof)];
  for (std::size_t i = 0; i < f.size(); ++i) {
    const int s = Sign(f[i]);
    if (std::isnan(f[i]) || s == 0) continue;
    std::string m = e.mapping;
    if (i < e.log.mapping.size() && e.log.mapping[i] >= 0 &&
        e.log.mapping[i] < static_cast<int>(e.log.mapping_names.size())) {
      m = e.log.mapping_names[e.log.mapping[i]];
    }
    out.insert({m, s});
  }
  return out;
}

// The open-water directions of a DOF's mappings that its thrusters can hold: the reference of
// the installation coefficients (seed 000 §II-A: η must be known for at least one mapping).
std::vector<std::pair<std::string, int>> OpenWaterDirections(const model::Vehicle& v, Dof dof) {
  std::vector<std::pair<std::string, int>> out;
  for (int i : v.MappingsOf(dof)) {
    const model::ThrustMapping& m = v.mappings[i];
    if (m.IsOpenWater(model::Direction::kPos) && DirectionForceRange(v, i, +1).feasible) {
      out.push_back({m.name, +1});
    }
    if (m.IsOpenWater(model::Direction::kNeg) && DirectionForceRange(v, i, -1).feasible) {
      out.push_back({m.name, -1});
    }
  }
  return out;
}

std::string DirectionName(const std::pair<std::string, int>& d) {
  return d.first + (d.second > 0 ? " pushing positive" : " pushing negative");
}

// The next trial of one DOF, or a reason why there is none. In this order:
//   1. No trial of the DOF has pushed in an open-water direction yet: one that does — without
//      that reference the installation coefficients cannot be told from the inertia and the drag
//      (seed 000 §II-A, eq. 3 is homogeneous in θ), and the estimates of m and k absorb η.
//   2. An installation coefficient of interest is not estimated yet: a trial pushing in its
//      mapping and direction. The D criterion of DesignNextTrial does not ask for it by itself:
//      it scores the parameters a trial reaches, and refining m with another open-water sine can
//      score higher than opening a new direction.
//   For 1 and 2 the a priori schedule's first trial that does it is taken (seed 000 order),
//   else DesignNextTrial with its sine restricted to that mapping and direction.
//   3. Estimates not usable yet (m or the drag of interest insignificant): the a priori
//      schedule, in order (seed 000 §III: steady runs, then the sine).
//   4. DesignNextTrial on all the DOF's parameters (box = estimates ± 2σ, prior = C⁻¹).
bool PlanForDof(Planner& planner, const model::Campaign& campaign, const DofProgress& progress,
                const ident::DofIdentification* id, Decision* d, std::string* why) {
  const Dof dof = progress.dof;
  const std::string name(model::DofName(dof));
  std::set<std::string> run;
  std::set<std::pair<std::string, int>> pushed;
  for (const auto& e : campaign.trials) {
    if (e.dof != dof) continue;
    run.insert(EntryId(e));
    if (e.use == model::TrialUse::kFit) {
      for (const auto& p : PushedDirections(e)) pushed.insert(p);
    }
  }
  // The a priori schedule's trials not run yet (by id), in seed 000 order.
  const ScheduleResult& sched = planner.APriori(dof);
  std::vector<const PlannedTrial*> pending;
  for (const auto& t : sched.schedule.trials) {
    if (t.design.dof == dof && !run.count(t.design.id)) pending.push_back(&t);
  }
  std::vector<std::pair<std::string, int>> want;
  std::string want_why;
  const auto open_water = OpenWaterDirections(planner.vehicle, dof);
  const bool reference = std::any_of(open_water.begin(), open_water.end(),
                                     [&](const auto& p) { return pushed.count(p) > 0; });
  if (!reference && !open_water.empty()) {
    want = open_water;
    want_why = "no open-water run yet: the reference of the installation coefficients";
  } else {
    for (const auto& q : progress.interest) {
      if (!q.estimated && StartsWith(q.name, model::param::kEtaPrefix)) {
        want.push_back(EtaDirection(q.name));
      }
    }
    want_why = "its installation coefficient is not estimated yet";
  }
  ParameterValues estimates;
  std::vector<std::string> names;
  Eigen::MatrixXd covariance(0, 0);
  if (id != nullptr && id->status != ident::IdentifyStatus::kFailed) {
    std::vector<std::string> input_notes;
    DesignInputs(planner.vehicle, *id, planner.options.usable_percent, &estimates, &names,
                 &covariance, &input_notes);
    for (const auto& n : input_notes) d->notes.push_back(name + ": " + n);
  }
  auto take_apriori = [&](const PlannedTrial* t, const std::string& why_this) {
    d->dof = dof;
    d->source = "a priori schedule";
    d->trial = *t;
    // Predicted precision after this trial: its information over the a priori box plus the
    // prior information of the estimates so far (what DesignNextTrial reports for its trials).
    std::vector<std::string> ctx_notes;
    const std::unique_ptr<DofContext> ctx = DofContext::APriori(
        planner.vehicle, planner.pool, dof, planner.options.schedule.planner, &ctx_notes);
    PriorInformation prior;
    if (!names.empty()) prior = PriorInformation::FromCovariance(names, covariance);
    d->predicted =
        PredictPrecision(*ctx, TrialsInformation(*ctx, {*t}, names.empty() ? nullptr : &prior));
    d->notes.push_back(name + ": a priori trial '" + t->design.id + "' (" + why_this + ")");
    return true;
  };
  for (const auto& w : want) {
    for (const PlannedTrial* t : pending) {
      if (Uses(t->design, w.first, w.second)) {
        return take_apriori(t, DirectionName(w) + ": " + want_why);
      }
    }
  }
  if (!progress.usable && !pending.empty() && want.empty()) {
    return take_apriori(pending.front(), progress.trials == 0
                                             ? "no trial yet"
                                             : "estimates not usable yet: " + progress.worst +
                                                   " at " + Fmt(progress.worst_percent) + "%");
  }
  if (sched.status == PlanStatus::kInfeasible && progress.trials == 0) {
    *why = name + ": " + sched.message;
    return false;
  }
  NextTrialOptions no = planner.options.next;
  no.schedule = planner.options.schedule;
  no.schedule.dofs = {dof};
  no.schedule.prior.clear();
  // A fresh id: the DOF and the trial's number in the campaign, unique among its files.
  std::set<std::string> ids;
  for (const auto& e : campaign.trials) ids.insert(EntryId(e));
  int k = static_cast<int>(campaign.trials.size()) + 1;
  do {
    std::ostringstream os;
    os << name << "-next-" << (k < 10 ? "0" : "") << k;
    no.id = os.str();
    ++k;
  } while (ids.count(no.id));
  // Without any usable estimate the covariance is empty: no prior information, the a priori
  // box (PriorInformation::FromCovariance).
  const std::vector<std::string>& design_names = names;
  const Eigen::MatrixXd& design_covariance = covariance;
  auto design = [&](const NextTrialOptions& o, const std::string& what) {
    const NextTrialResult nt = DesignNextTrial(planner.vehicle, planner.pool, dof, estimates,
                                               design_names, design_covariance, o);
    for (const auto& n : nt.notes) d->notes.push_back(name + ": " + n);
    if (nt.status != DesignStatus::kOk) {
      d->notes.push_back(name + ": " + what + ": " + std::string(DesignStatusName(nt.status)) +
                         ": " + nt.message);
      *why = name + ": " + nt.message;
    }
    return nt;
  };
  auto accept = [&](const NextTrialResult& nt, const std::string& source) {
    d->dof = dof;
    d->source = source;
    d->trial = nt.trial;
    d->predicted = nt.predicted;
    return true;
  };
  for (const auto& w : want) {
    NextTrialOptions o = no;
    o.schedule.sine.mappings = {w.first};
    o.schedule.sine.sign = w.second;
    // An open-water direction needs no prior; another is no longer confounded with m once the
    // reference trials have informed m (the prior information of the design).
    o.schedule.sine.open_water_only = !reference;
    const std::string what = "sequential design for " + DirectionName(w);
    const NextTrialResult nt = design(o, what);
    if (nt.status == DesignStatus::kOk && Uses(nt.trial.design, w.first, w.second)) {
      d->notes.push_back(name + ": " + what + " (" + want_why + ")");
      return accept(nt, "sequential design");
    }
    if (nt.status == DesignStatus::kOk) {
      d->notes.push_back(name + ": " + what + " gave a trial that does not push that way");
    }
  }
  if (!progress.usable && !pending.empty()) {
    return take_apriori(pending.front(), "estimates not usable yet: " + progress.worst + " at " +
                                             Fmt(progress.worst_percent) + "%");
  }
  const NextTrialResult nt = design(no, "sequential design");
  if (nt.status == DesignStatus::kOk) return accept(nt, "sequential design");
  if (!pending.empty()) return take_apriori(pending.front(), "the sequential design failed");
  return false;
}

Decision Decide(Planner& planner, const model::Campaign& campaign, const std::vector<Dof>& dofs,
                const ident::IdentifyResult& estimates) {
  Decision d;
  for (Dof dof : dofs) {
    int trials = 0;
    for (const auto& e : campaign.trials) {
      if (e.dof == dof && e.use == model::TrialUse::kFit) ++trials;
    }
    d.progress.push_back(
        EvaluateProgress(planner.vehicle, dof, estimates.Find(dof), trials, planner.options));
  }
  std::vector<const DofProgress*> order;
  for (const auto& p : d.progress) {
    if (!p.converged) order.push_back(&p);
  }
  if (order.empty()) {
    d.status = NextStatus::kConverged;
    d.message = "every parameter of interest is below " + Fmt(planner.options.target_percent) +
                "% percentile error: no further trial needed";
    return d;
  }
  // Furthest above the target first; ties keep the order of `dofs`.
  std::stable_sort(order.begin(), order.end(), [](const DofProgress* a, const DofProgress* b) {
    return a->worst_percent > b->worst_percent;
  });
  std::vector<std::string> reasons;
  for (const DofProgress* p : order) {
    std::string why;
    if (PlanForDof(planner, campaign, *p, estimates.Find(p->dof), &d, &why)) {
      d.status = NextStatus::kTrial;
      std::ostringstream m;
      m << std::string(model::DofName(p->dof)) << " is furthest from the target (" << p->worst
        << " at "
        << (std::isfinite(p->worst_percent) ? Fmt(p->worst_percent) + "%"
                                            : std::string("not estimated yet"))
        << "): " << d.source << " trial '" << d.trial.design.id << "'";
      d.message = m.str();
      return d;
    }
    reasons.push_back(why);
  }
  d.status = NextStatus::kInfeasible;
  std::ostringstream m;
  m << "no trial can be planned for the DOFs still above the target:";
  for (const auto& r : reasons) m << " " << r << ";";
  d.message = m.str();
  return d;
}

std::vector<Dof> CampaignDofs(const model::Campaign& c) {
  std::vector<Dof> out;
  for (Dof dof : model::kAllDofs) {
    for (const auto& e : c.trials) {
      if (e.dof == dof && e.use == model::TrialUse::kFit) {
        out.push_back(dof);
        break;
      }
    }
  }
  return out;
}

// Identification of one DOF from its own trials (what Identify does per DOF), so that the loop
// re-identifies only the DOF that got a new trial. Input errors become a failed DOF.
ident::DofIdentification IdentifyDof(const model::Campaign& campaign, Dof dof,
                                     const ident::IdentifyOptions& options) {
  model::Campaign sub;
  sub.path = campaign.path;
  sub.vehicle_file = campaign.vehicle_file;
  sub.vehicle = campaign.vehicle;
  sub.pool_file = campaign.pool_file;
  sub.pool = campaign.pool;
  for (const auto& e : campaign.trials) {
    if (e.dof == dof) sub.trials.push_back(e);
  }
  ident::IdentifyOptions o = options;
  o.dofs = {dof};
  try {
    ident::IdentifyResult r = ident::Identify(sub, o);
    if (!r.dofs.empty()) return std::move(r.dofs.front());
    ident::DofIdentification f;
    f.dof = dof;
    f.status = ident::IdentifyStatus::kFailed;
    f.message = r.message;
    return f;
  } catch (const model::InputError& e) {
    ident::DofIdentification f;
    f.dof = dof;
    f.status = ident::IdentifyStatus::kFailed;
    f.message = std::string("identification refused the trials: ") + e.what();
    return f;
  }
}

}  // namespace

bool DesignLoopOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (!(target_percent > 0) || !std::isfinite(target_percent)) {
    return fail("DesignLoopOptions::target_percent = " + Fmt(target_percent) +
                ". Violated constraint: 0 < target_percent < inf");
  }
  if (!(usable_percent > 0)) {
    return fail("DesignLoopOptions::usable_percent = " + Fmt(usable_percent) +
                ". Violated constraint: usable_percent > 0");
  }
  return schedule.IsValid(error) && identify.IsValid(error);
}

bool LoopOptions::IsValid(std::string* error) const {
  if (budget < 1) {
    if (error)
      *error =
          "LoopOptions::budget = " + std::to_string(budget) + ". Violated constraint: budget >= 1";
    return false;
  }
  if (!(command_rate_hz > 0)) {
    if (error)
      *error =
          "LoopOptions::command_rate_hz = " + Fmt(command_rate_hz) + ". Violated constraint: > 0";
    return false;
  }
  return step.IsValid(error);
}

std::string_view NextStatusName(NextStatus s) {
  switch (s) {
    case NextStatus::kTrial:
      return "trial";
    case NextStatus::kConverged:
      return "converged";
    case NextStatus::kInfeasible:
      return "infeasible";
  }
  return "infeasible";
}

std::string_view LoopStatusName(LoopStatus s) {
  switch (s) {
    case LoopStatus::kConverged:
      return "converged";
    case LoopStatus::kBudgetSpent:
      return "budget_spent";
    case LoopStatus::kInfeasible:
      return "infeasible";
  }
  return "infeasible";
}

DofProgress EvaluateProgress(const model::Vehicle& vehicle, Dof dof,
                             const ident::DofIdentification* id, int trials,
                             const DesignLoopOptions& options) {
  DofProgress p;
  p.dof = dof;
  p.trials = trials;
  p.status = id == nullptr ? "no trial"
                           : std::string(ident::IdentifyStatusName(id->status)) +
                                 (id->message.empty() ? "" : ": " + id->message);
  auto get = [&](const std::string& name) {
    InterestParameter q;
    q.name = name;
    if (id == nullptr || id->status == ident::IdentifyStatus::kFailed) return q;
    const ident::ParameterEstimate* e = id->Param(name);
    if (e == nullptr || e->state != ident::ParameterState::kEstimated) return q;
    if (!(std::isfinite(e->sigma) && std::isfinite(e->value) && e->value != 0.0)) return q;
    q.estimated = true;
    q.value = e->value;
    q.sigma = e->sigma;
    q.percent = 100.0 * e->sigma / std::abs(e->value);
    return q;
  };
  p.interest.push_back(get(model::param::kMass));
  // Drag: "k (or kq where significant)".
  const InterestParameter kq = get(model::param::kQuadraticDrag);
  const ident::ParameterEstimate* kq_est = id ? id->Param(model::param::kQuadraticDrag) : nullptr;
  const bool kq_significant = kq.estimated && kq.percent < kInsignificantPercent &&
                              (kq_est == nullptr || kq_est->significant);
  p.interest.push_back(kq_significant ? kq : get(model::param::kLinearDrag));
  // Every η of the DOF's mappings in a direction the thrusters can hold (the planner's model).
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(dof)) mappings.push_back(vehicle.mappings[i].name);
  const model::DofModel full(vehicle,
                             model::ModelStructure::Standard(vehicle, dof, mappings, false));
  for (const auto& n : full.parameter_names()) {
    if (!StartsWith(n, model::param::kEtaPrefix)) continue;
    const auto [mapping, sign] = EtaDirection(n);
    const int mi = vehicle.MappingIndex(mapping);
    if (mi >= 0 && !DirectionForceRange(vehicle, mi, sign).feasible) continue;
    p.interest.push_back(get(n));
  }
  p.worst_percent = 0.0;
  for (const auto& q : p.interest) {
    if (q.percent > p.worst_percent || p.worst.empty()) {
      p.worst_percent = q.percent;
      p.worst = q.name;
    }
  }
  p.converged = p.worst_percent <= options.target_percent;
  p.usable = p.interest[0].percent < options.usable_percent &&
             p.interest[1].percent < options.usable_percent;
  return p;
}

NextStepResult NextStep(const model::Campaign& campaign, const model::Pool& pool,
                        const DesignLoopOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("next options", error);
  std::vector<Dof> dofs = options.dofs;
  if (dofs.empty()) dofs = CampaignDofs(campaign);
  if (dofs.empty()) {
    for (Dof dof : model::kAllDofs) {
      if (Plannable(campaign.vehicle, dof)) dofs.push_back(dof);
    }
  }
  const std::string where = campaign.vehicle_file.empty() ? campaign.path : campaign.vehicle_file;
  for (Dof dof : dofs) RequirePlannable(campaign.vehicle, dof, where);

  NextStepResult r;
  if (!CampaignDofs(campaign).empty()) {
    ident::IdentifyOptions io = options.identify;
    io.dofs.clear();
    r.estimates = ident::Identify(campaign, io);
  } else {
    r.estimates.status = ident::IdentifyStatus::kFailed;
    r.estimates.message = "no fit trial yet: nothing to identify";
  }
  Planner planner{campaign.vehicle, pool, options, {}};
  Decision d = Decide(planner, campaign, dofs, r.estimates);
  r.status = d.status;
  r.message = std::move(d.message);
  r.progress = std::move(d.progress);
  r.dof = d.dof;
  r.source = std::move(d.source);
  r.trial = std::move(d.trial);
  r.predicted = std::move(d.predicted);
  r.notes = std::move(d.notes);
  for (const auto& n : r.estimates.notes) r.notes.push_back("identify: " + n);
  return r;
}

double PoolTime(const std::vector<model::TrialDesign>& designs, double pause_s) {
  double t = 0.0;
  for (const auto& d : designs) t += d.duration;
  if (designs.size() > 1) t += pause_s * static_cast<double>(designs.size() - 1);
  return t;
}

model::TrialEntry RunVirtualEntry(const model::Truth& truth, const model::TrialDesign& design,
                                  int index, double start, std::uint64_t seed,
                                  double command_rate_hz) {
  model::VirtualPoolOptions vo;
  vo.seed = Mix(seed ^ Mix(static_cast<std::uint64_t>(index) + 1));
  vo.command_rate_hz = command_rate_hz;
  model::TrialEntry e;
  e.file = design.id.empty() ? "trial_" + std::to_string(index) : design.id;
  e.path = e.file;
  e.dof = design.dof;
  e.mapping = design.mapping;
  e.ballast_steps = design.ballast_steps;
  e.use = model::TrialUse::kFit;
  e.start = start;
  e.has_start = true;
  e.log = model::RunVirtualTrial(truth, design, start, vo);
  // The virtual pool wraps headings to (-pi, pi] as a compass does; reading the CSV unwraps.
  model::UnwrapAngles(&e.log);
  return e;
}

LoopResult RunLoop(const model::Truth& truth, const model::Pool& pool, const LoopOptions& options,
                   const std::function<void(const LoopIteration&)>& on_iteration) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("loop options", error);
  const model::Vehicle& vehicle = truth.vehicle;
  std::vector<Dof> dofs = options.step.dofs;
  if (dofs.empty()) {
    for (Dof dof : model::kAllDofs) {
      if (truth.dofs.count(dof)) dofs.push_back(dof);
    }
  }
  if (dofs.empty()) {
    throw model::InputError("truth", "no dofs.<dof>.params: the truth has nothing to identify");
  }
  for (Dof dof : dofs) {
    if (!truth.dofs.count(dof)) {
      throw model::InputError("truth", "missing dofs." + std::string(model::DofName(dof)) +
                                           ".params: the virtual vehicle cannot run " +
                                           std::string(model::DofName(dof)) + " trials");
    }
    RequirePlannable(vehicle, dof, "truth");
  }

  LoopResult result;
  model::Campaign& campaign = result.campaign;
  campaign.path = "<virtual>";
  campaign.vehicle_file = "<virtual>";
  campaign.vehicle = vehicle;
  campaign.pool = pool;
  ident::IdentifyResult& estimates = result.estimates;
  estimates.status = ident::IdentifyStatus::kFailed;
  estimates.message = "no trial yet";
  Planner planner{campaign.vehicle, pool, options.step, {}};
  const double pause = options.step.schedule.planner.pause_s;
  double clock = 0.0;
  std::map<Dof, std::vector<model::TrialDesign>> per_dof;

  for (;;) {
    const auto t0 = std::chrono::steady_clock::now();
    Decision d = Decide(planner, campaign, dofs, estimates);
    result.progress = d.progress;
    if (d.status == NextStatus::kConverged) {
      result.status = LoopStatus::kConverged;
      result.message = d.message;
      break;
    }
    if (d.status == NextStatus::kInfeasible) {
      result.status = LoopStatus::kInfeasible;
      result.message = d.message;
      break;
    }
    if (static_cast<int>(result.iterations.size()) >= options.budget) {
      result.status = LoopStatus::kBudgetSpent;
      std::ostringstream m;
      m << "trial budget of " << options.budget << " spent before the target of "
        << Fmt(options.step.target_percent) << "%:";
      for (const auto& p : d.progress) {
        if (!p.converged) {
          m << " " << model::DofName(p.dof) << " " << p.worst << " at "
            << (std::isfinite(p.worst_percent) ? Fmt(p.worst_percent) + "%" : "not estimated")
            << ";";
        }
      }
      m << " raise --budget or the target";
      result.message = m.str();
      break;
    }
    LoopIteration it;
    it.index = static_cast<int>(campaign.trials.size());
    it.dof = d.dof;
    it.source = d.source;
    it.trial = d.trial;
    // Ids are unique in a campaign (they name the log files): an a priori trial keeps its id.
    it.predicted = d.predicted;
    it.notes = d.notes;
    it.start = clock;
    campaign.trials.push_back(RunVirtualEntry(truth, d.trial.design, it.index, clock, options.seed,
                                              options.command_rate_hz));
    clock += d.trial.design.duration + pause;
    per_dof[d.dof].push_back(d.trial.design);
    result.pool_time = clock - pause;
    it.pool_time = result.pool_time;

    ident::DofIdentification id = IdentifyDof(campaign, d.dof, options.step.identify);
    for (const auto& w : id.warnings) {
      it.notes.push_back(std::string(model::DofName(d.dof)) + ": identify: " + w);
    }
    bool replaced = false;
    for (auto& x : estimates.dofs) {
      if (x.dof == d.dof) {
        x = std::move(id);
        replaced = true;
        break;
      }
    }
    if (!replaced) estimates.dofs.push_back(std::move(id));
    std::stable_sort(estimates.dofs.begin(), estimates.dofs.end(),
                     [](const auto& a, const auto& b) { return a.dof < b.dof; });
    estimates.status = ident::IdentifyStatus::kOk;
    for (const auto& x : estimates.dofs) {
      if (x.status == ident::IdentifyStatus::kFailed) {
        estimates.status = ident::IdentifyStatus::kFailed;
      } else if (x.status == ident::IdentifyStatus::kWarnings &&
                 estimates.status == ident::IdentifyStatus::kOk) {
        estimates.status = ident::IdentifyStatus::kWarnings;
      }
    }
    estimates.message = std::to_string(estimates.dofs.size()) + " DOF(s) identified from " +
                        std::to_string(campaign.trials.size()) + " trial(s)";
    for (const auto& x : estimates.dofs) it.params[x.dof] = x.params;
    for (Dof dof : dofs) {
      int trials = 0;
      for (const auto& e : campaign.trials) trials += e.dof == dof ? 1 : 0;
      it.progress.push_back(
          EvaluateProgress(vehicle, dof, estimates.Find(dof), trials, options.step));
    }
    it.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (on_iteration) on_iteration(it);
    result.iterations.push_back(std::move(it));
  }
  result.converged = result.status == LoopStatus::kConverged;
  for (const auto& [dof, designs] : per_dof) result.dof_pool_time[dof] = PoolTime(designs, pause);
  return result;
}

}  // namespace uuvplan::planner
