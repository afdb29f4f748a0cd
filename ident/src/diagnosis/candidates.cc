// Test stage: each effect of the table proposes extensions of the current structure, scaled by
// what the data show (its time constant, force range, thrust directions, measured DOFs).
#include <algorithm>
#include <cmath>
#include <limits>

#include "diagnosis_internal.h"
#include "uuvplan/ident/stats/chi_square.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::diagnosis {

namespace {

using model::Dof;

double TypicalSpeed(const Trials& trials) {
  std::vector<double> s;
  for (const TrialData* t : trials) {
    for (double v : t->velocity_estimate.value) {
      if (std::isfinite(v)) s.push_back(std::abs(v));
    }
  }
  return s.empty() ? 0.0 : model::Median(std::move(s));
}

// Smallest |φⁿ| above 1% of the largest.
double MinForceLevel(const Trials& trials, double fmax) {
  double fmin = fmax;
  for (const TrialData* t : trials) {
    for (double f : t->force) {
      if (std::abs(f) > 0.01 * fmax) fmin = std::min(fmin, std::abs(f));
    }
  }
  return fmin;
}

// (mapping, direction) pairs of the nominal force present in the trials, not in open water.
std::vector<std::pair<std::string, model::Direction>> ClosedThrustDirections(
    const model::Vehicle& vehicle, const Trials& trials) {
  std::set<std::pair<std::string, model::Direction>> seen;
  for (const TrialData* t : trials) {
    double fmax = 0.0;
    for (double f : t->force) fmax = std::max(fmax, std::abs(f));
    for (std::size_t i = 0; i < t->force.size(); ++i) {
      const int m = i < t->mapping.size() ? t->mapping[i] : -1;
      if (m < 0 || std::abs(t->force[i]) <= 1e-6 * fmax) continue;
      const auto dir = t->force[i] > 0 ? model::Direction::kPos : model::Direction::kNeg;
      if (!vehicle.mappings[m].IsOpenWater(dir)) seen.insert({vehicle.mappings[m].name, dir});
    }
  }
  return {seen.begin(), seen.end()};
}

// Velocity letters measured in every trial (the own DOF's always, first).
std::vector<char> AvailableLetters(Dof dof, const Trials& trials) {
  std::vector<char> letters = {model::VelocityLetter(dof)};
  for (Dof d : model::kAllDofs) {
    if (d == dof || trials.empty()) continue;
    const bool all = std::all_of(trials.begin(), trials.end(),
                                 [&](const TrialData* t) { return t->aux && t->aux->Has(d); });
    if (all) letters.push_back(model::VelocityLetter(d));
  }
  return letters;
}

// Trials spread over the campaign clock (drift needs them).
bool SpansCampaignClock(const Trials& trials, bool campaign_clock) {
  double t0 = 1e300, t1 = -1e300;
  for (const TrialData* t : trials) {
    t0 = std::min(t0, t->start_time);
    t1 = std::max(t1, t->start_time + t->duration);
  }
  return campaign_clock && trials.size() >= 2 && t1 - t0 > 0;
}

model::ProposalEvidence EvidenceOf(const model::Vehicle& vehicle, const StructureFit& base,
                                   const Trials& trials, bool campaign_clock) {
  model::ProposalEvidence c;
  c.dof = base.structure.dof;
  c.parameters = &base.structure.parameters;
  c.values = &base.values;
  const double m = c.Value(model::param::kMass, 1.0);
  const double speed = std::max(TypicalSpeed(trials), 1e-3);
  const double kl = c.Value(model::param::kLinearDrag, 0.0) +
                    2 * c.Value(model::param::kQuadraticDrag, 0.0) * speed;
  c.time_constant_s = kl > 0 ? m / kl : 1.0;
  c.max_force = MaxForce(trials);
  c.min_force = MinForceLevel(trials, c.max_force);
  c.closed_thrust_directions = ClosedThrustDirections(vehicle, trials);
  c.velocity_letters = AvailableLetters(c.dof, trials);
  c.campaign_clock = SpansCampaignClock(trials, campaign_clock);
  return c;
}

}  // namespace

double MaxForce(const Trials& trials) {
  double fmax = 0.0;
  for (const TrialData* t : trials) {
    for (double f : t->force) fmax = std::max(fmax, std::abs(f));
  }
  return fmax;
}

std::vector<Candidate> CandidatesFor(const std::string& name, const model::Vehicle& vehicle,
                                     const StructureFit& base, const Trials& trials,
                                     bool campaign_clock) {
  std::vector<Candidate> out;
  const model::EffectEntry* effect = model::Effects().Find(name);
  if (!effect || !effect->propose) return out;
  for (model::Proposal& p : effect->propose(EvidenceOf(vehicle, base, trials, campaign_clock))) {
    Candidate c{effect, p, base.structure, {}};
    for (const auto& [parameter, start] : p.start) {
      c.structure.Add(parameter);
      c.added.push_back(parameter);
    }
    for (const auto& [key, value] : p.settings) c.structure.settings[key] = value;
    out.push_back(std::move(c));
  }
  return out;
}

// "" when every parameter of `ext` lies in its family's admissible range (model/parameter.h),
// else the first that does not, e.g. "kq_neg = -453.4 N·s²/m² (expected a number >= 0)". A
// parameter already outside it in `base` is the standard model's problem, not the extension's.
std::string NonPhysical(const StructureFit& base, const StructureFit& ext) {
  for (const ParameterEstimate& e : ext.oe.estimates) {
    const model::ParameterFamily* family = model::FamilyOf(e.name);
    if (!family || family->Admissible(e.value)) continue;
    const auto b = base.values.find(e.name);
    if (b != base.values.end() && !family->Admissible(b->second)) continue;
    return e.name + " = " + model::Significant(e.value, 4) + " " +
           model::Unit(e.name, ext.structure.dof) + " (expected " + family->Expected() + ")";
  }
  return "";
}

// Likelihood ratio D = 2·(C₀ − C₁)/s₁², s₁² = 2·C₁/(N − P₁), ~ χ²(Δp) under "no effect"
// (diagnosis.h); max_z: the new parameter farthest from its null value, in σ (a Wald z, from
// the curvature of the cost where the fit ended).
CandidateTest Test(const Candidate& c, const StructureFit& base, const StructureFit& ext,
                   int round) {
  CandidateTest t;
  t.effect = c.effect->name;
  t.dof = c.structure.dof;
  t.detail = c.proposal.detail;
  t.round = round;
  t.added_parameters = static_cast<int>(c.added.size());
  if (!ext.oe.ok() || !base.oe.ok()) {
    t.detail += (t.detail.empty() ? "" : "; ") + std::string("fit failed: ") + ext.oe.message;
    return t;
  }
  const int n = ext.oe.num_residuals;
  const double s2 = 2.0 * ext.oe.cost / std::max(1, n - ext.free_parameters);
  const double d = 2.0 * (base.oe.cost - ext.oe.cost) / s2;
  t.statistic = std::max(0.0, d);
  // The extension contains the current model (its new parameters at their null values), so at
  // its optimum C₁ ≤ C₀. A fit that ends above C₀ by more than its own convergence tolerance
  // (a Gauss–Newton step of 0.1σ: 0.01 in D) stopped elsewhere: payload60 yaw's thruster lag
  // went from 0.062 s to T = 0.0072 s = h/2.79, the RK4 step's stability limit, where the
  // simulation is hypersensitive to T (σ = 4e-6 s, "z = 1865") and C₁ − C₀ = +0.27. The σ of
  // such a point says nothing about the effect: no z, and the test says why.
  if (d < -0.01) {
    t.max_z = std::numeric_limits<double>::quiet_NaN();
    t.detail += (t.detail.empty() ? "" : "; ") +
                std::string("the extension's fit ends worse than the model it extends (D = ") +
                model::Significant(d, 3) + " < 0: not at its optimum), no z";
    t.non_physical = NonPhysical(base, ext);
    return t;
  }
  // A parameter held at its bound in `base` may be free again in `ext` (FitPhysical decides
  // per fit): the test counts every parameter `ext` frees.
  const int freed = std::max(t.added_parameters, ext.free_parameters - base.free_parameters);
  t.p_value = ChiSquareSurvival(t.statistic, freed);
  for (const std::string& name : c.added) {
    const int k = FindEstimate(ext.oe.estimates, name);
    if (k < 0) continue;
    const auto& e = ext.oe.estimates[k];
    const auto null = c.proposal.null.find(name);
    const double null_value = null != c.proposal.null.end() ? null->second : model::NullValue(name);
    if (e.sigma > 0) t.max_z = std::max(t.max_z, std::abs(e.value - null_value) / e.sigma);
  }
  t.non_physical = NonPhysical(base, ext);
  for (const std::string& name : ext.held_at_bound) {
    t.detail += (t.detail.empty() ? "" : "; ") + name + " held at its bound " +
                model::Significant(ext.held.at(name), 4);
  }
  return t;
}

}  // namespace uuvplan::ident::diagnosis
