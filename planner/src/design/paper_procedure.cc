// Ref 000's procedure on ROMEO as virtual trials (paper_procedure.h).
#include "uuvplan/planner/design/paper_procedure.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "loop/next_trial_policy.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/sine_design.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

using model::Dof;

struct Leg {
  std::string mapping;
  double force = 0.0;
  double duration = 0.0;
};

// Travel from rest after T of the linear first-order response with time constant tau towards
// speed v: v·(T - tau·(1 - exp(-T/tau))).
double TravelFromRest(double v, double tau, double T) {
  return std::abs(v) * (T - tau * (1.0 - std::exp(-T / tau)));
}

// The steady legs of one mapping (both directions it can hold), alternating direction at each
// level (ref 000 §IV-D: "forwards and backwards"; Fig. 4: up and down).
std::vector<Leg> MappingLegs(const model::Vehicle& v, const model::Pool& pool, Dof dof, int mi,
                             double k, double kq, const PaperProcedureOptions& o,
                             std::vector<std::string>* notes) {
  const std::string& name = v.mappings[mi].name;
  const double vmax = model::IsRotational(dof) ? o.max_rotation_rate : o.max_translation_speed;
  const double m_max = v.InertiaBounds(dof)[1];
  const double available = pool.FreeTravel(dof);
  std::array<ForceRange, 2> range = {DirectionForceRange(v, mi, +1),
                                     DirectionForceRange(v, mi, -1)};
  std::vector<Leg> legs;
  for (int j = 1; j <= o.levels; ++j) {
    const double speed = vmax * j / o.levels;
    for (int s = 0; s < 2; ++s) {
      const int sign = s == 0 ? +1 : -1;
      const ForceRange& r = range[s];
      if (!r.feasible) {
        if (j == 1) {
          notes->push_back(std::string(model::DofName(dof)) + ": mapping " + name +
                           " cannot hold " + (sign > 0 ? "positive" : "negative") + " forces (" +
                           r.reason + "): no legs that way");
        }
        continue;
      }
      // Ref 000 eq. 7 with eta = 1 and no bias (what the pool team knows before the runs).
      double f = k * speed + kq * speed * speed;
      if (f < r.min_abs || f > r.max_abs) {
        const double c = std::clamp(f, r.min_abs, r.max_abs);
        notes->push_back(
            std::string(model::DofName(dof)) + ": " + name + " level " + std::to_string(j) +
            " needs " + model::Significant(f, 3) + " " + std::string(model::ForceUnit(dof)) +
            ", outside what its thrusters give [" + model::Significant(r.min_abs, 3) + ", " +
            model::Significant(r.max_abs, 3) + "]: " + model::Significant(c, 3) + " used");
        f = c;
      }
      const double xi = SteadySpeed(k, kq, f);
      const double tau = TimeConstant(m_max, LinearisedDrag(k, kq, xi));
      double T = o.settle_time_constants * tau + o.hold_s;
      if (std::isfinite(available) && TravelFromRest(xi, tau, T) > o.travel_fraction * available) {
        // Bisection on the monotone travel for the time that uses the allowed travel.
        double lo = 0.0, hi = T;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (TravelFromRest(xi, tau, mid) > o.travel_fraction * available ? hi : lo) = mid;
        }
        T = lo;
      }
      legs.push_back({name, sign * f, std::round(T * 10.0) / 10.0});
    }
  }
  return legs;
}

// Chains legs into trials of at most `max_s` (a single leg is a steady trial).
std::vector<model::TrialDesign> PackLegs(Dof dof, const std::string& id_prefix,
                                         const std::vector<Leg>& legs, double max_s, int ballast) {
  std::vector<model::TrialDesign> out;
  std::vector<Leg> cur;
  auto flush = [&]() {
    if (cur.empty()) return;
    model::TrialDesign d;
    d.id = id_prefix + "-" + std::to_string(out.size() + 1);
    d.dof = dof;
    d.mapping = cur.front().mapping;
    d.ballast_steps = ballast;
    for (const Leg& l : cur) d.duration += l.duration;
    if (cur.size() == 1) {
      d.kind = model::TrialKind::kSteady;
      d.force = cur.front().force;
    } else {
      d.kind = model::TrialKind::kSegments;
      for (const Leg& l : cur) d.segments.push_back({l.force, l.duration, l.mapping});
    }
    out.push_back(std::move(d));
    cur.clear();
  };
  double t = 0.0;
  for (const Leg& l : legs) {
    if (!cur.empty() && t + l.duration > max_s) {
      flush();
      t = 0.0;
    }
    cur.push_back(l);
    t += l.duration;
  }
  flush();
  return out;
}

// The mapping of `dof` that is open water in direction `sign` (ref 000 Table I), or -1.
int OpenWaterMapping(const model::Vehicle& v, Dof dof, int sign) {
  for (int i : v.MappingsOf(dof)) {
    const model::OpenWater ow = v.mappings[i].open_water;
    if (ow == model::OpenWater::kBoth ||
        ow == (sign > 0 ? model::OpenWater::kPositive : model::OpenWater::kNegative)) {
      return i;
    }
  }
  return -1;
}

}  // namespace

bool PaperProcedureOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (levels < 1) return fail("PaperProcedureOptions::levels must be >= 1");
  if (!(max_translation_speed > 0) || !(max_rotation_rate > 0)) {
    return fail("PaperProcedureOptions: the largest steady speeds must be > 0");
  }
  if (!(settle_time_constants > 0) || !(hold_s >= 0)) {
    return fail("PaperProcedureOptions: settle_time_constants > 0 and hold_s >= 0 required");
  }
  if (!(travel_fraction > 0 && travel_fraction <= 1)) {
    return fail("PaperProcedureOptions::travel_fraction must be in (0, 1]");
  }
  if (heave_experiments < 1) return fail("PaperProcedureOptions::heave_experiments must be >= 1");
  if (!(sine_max_duration_s > 0)) return fail("PaperProcedureOptions::sine_max_duration_s > 0");
  return planner.IsValid(error) && identify.IsValid(error) && progress.IsValid(error);
}

std::vector<model::TrialDesign> PaperProcedureDesigns(const model::Vehicle& v,
                                                      const model::Pool& pool, Dof dof,
                                                      const PaperProcedureOptions& o,
                                                      std::vector<std::string>* notes) {
  std::vector<std::string> scratch;
  if (notes == nullptr) notes = &scratch;
  const std::string name(model::DofName(dof));
  std::vector<std::string> mappings;
  for (int i : v.MappingsOf(dof)) mappings.push_back(v.mappings[i].name);
  if (mappings.empty()) {
    throw model::InputError("vehicle '" + v.name + "'", "no " + name + " mapping");
  }
  // A priori drag: the vehicle's dofs.<dof>.drag (else model::DragOf's thrust-scaled fallback).
  const model::DofModel full(v, model::ModelStructure::Standard(v, dof, mappings, false));
  const ParameterBox box = APrioriBox(v, dof, full.parameter_names(), o.planner.box, notes);
  const double k = box.Nominal("k"), kq = box.Nominal("kq");

  std::vector<model::TrialDesign> out;
  // 1. Steady runs, ref 000 §III-A.
  if (dof == Dof::kHeave) {
    std::vector<Leg> legs;
    for (int i : v.MappingsOf(dof)) {
      auto l = MappingLegs(v, pool, dof, i, k, kq, o, notes);
      legs.insert(legs.end(), l.begin(), l.end());
    }
    for (int b = 0; b < o.heave_experiments; ++b) {
      auto t = PackLegs(dof, "paper-heave-ballast" + std::to_string(b), legs,
                        o.planner.max_trial_duration_s, b);
      out.insert(out.end(), t.begin(), t.end());
    }
  } else {
    for (int i : v.MappingsOf(dof)) {
      auto legs = MappingLegs(v, pool, dof, i, k, kq, o, notes);
      auto t =
          PackLegs(dof, "paper-" + v.mappings[i].name, legs, o.planner.max_trial_duration_s, 0);
      out.insert(out.end(), t.begin(), t.end());
    }
  }
  // 2. The sine of ref 000 §IV-D.
  model::TrialDesign s;
  s.dof = dof;
  s.kind = model::TrialKind::kSine;
  int mi = -1;
  if (dof == Dof::kSurge) {
    mi = OpenWaterMapping(v, dof, +1);  // "with only the front thrusters"
    s.offset = 35.0;
    s.amplitude = 25.0;
    s.omega = 2 * M_PI / 26.0;
  } else if (dof == Dof::kYaw) {
    mi = OpenWaterMapping(v, dof, -1);  // "only rear-left and front-right thrusters"
    s.offset = -5.0;
    s.amplitude = 4.0;
    s.omega = 2 * M_PI / 24.0;
  } else {
    notes->push_back(name + ": seed 000 ran no sine on " + name +
                     ": the inertia comes from the steady runs' transients only");
    return out;
  }
  if (mi < 0) {
    notes->push_back(name + ": no open-water mapping for the seed's sine: none run");
    return out;
  }
  s.id = "paper-" + name + "-sine";
  s.mapping = v.mappings[mi].name;
  std::vector<std::string> ctx_notes;
  std::unique_ptr<DofPlanningProblem> ctx =
      DofPlanningProblem::APriori(v, pool, dof, o.planner, &ctx_notes);
  s.duration = LongestFittingDuration(*ctx, s, o.sine_max_duration_s);
  s.duration = std::floor(s.duration * 10.0) / 10.0;
  notes->push_back(name + ": seed 000 sine " + model::Significant(s.offset, 3) + " + " +
                   model::Significant(s.amplitude, 3) + "·sin(2π t/" +
                   model::Significant(2 * M_PI / s.omega, 3) + " s) in " + s.mapping + " for " +
                   model::Significant(s.duration, 3) + " s (" +
                   model::Significant(s.duration * s.omega / (2 * M_PI), 3) +
                   " periods, the longest the pool allows up to " +
                   model::Significant(o.sine_max_duration_s, 3) + " s)");
  out.push_back(std::move(s));
  return out;
}

PaperProcedureResult RunPaperProcedure(const model::Truth& truth, const model::Pool& pool,
                                       const PaperProcedureOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw model::InputError("paper procedure options", error);
  const std::vector<Dof> dofs = internal::DofsOrTruths(truth, o.dofs);
  PaperProcedureResult r;
  std::map<Dof, std::vector<model::TrialDesign>> per_dof;
  std::vector<model::TrialDesign> all;
  for (Dof d : dofs) {
    auto designs = PaperProcedureDesigns(truth.vehicle, pool, d, o, &r.notes);
    std::vector<std::string> ctx_notes;
    std::unique_ptr<DofPlanningProblem> ctx =
        DofPlanningProblem::APriori(truth.vehicle, pool, d, o.planner, &ctx_notes);
    for (const auto& design : designs) {
      PlannedTrial t;
      t.design = design;
      TrialCheck check = ctx->Check(design);
      t.travel = check.travel;
      t.thrust_min = check.thrust_min;
      r.trials.push_back(t);
      r.checks.push_back(std::move(check));
      all.push_back(design);
    }
    per_dof[d] = std::move(designs);
  }
  model::VirtualCampaignOptions virtual_pool;
  virtual_pool.seed = o.seed;
  virtual_pool.command_rate_hz = o.command_rate_hz;
  virtual_pool.pause_s = o.planner.pause_s;
  virtual_pool.unwrap_headings = true;  // as reading the logs would
  virtual_pool.pool = pool;
  r.campaign = model::BuildVirtualCampaign(truth, all, virtual_pool);
  r.pool_time = PoolTime(all, o.planner.pause_s);
  for (const auto& [d, designs] : per_dof)
    r.dof_pool_time[d] = PoolTime(designs, o.planner.pause_s);
  ident::IdentifyOptions io = o.identify;
  io.dofs = dofs;
  r.estimates = ident::Identify(r.campaign, io);
  for (Dof d : dofs) {
    r.progress.push_back(EvaluateProgress(truth.vehicle, d, r.estimates.Find(d),
                                          static_cast<int>(per_dof[d].size()), o.progress));
  }
  return r;
}

}  // namespace uuvplan::planner
