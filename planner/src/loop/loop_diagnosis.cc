#include "loop/loop_diagnosis.h"

#include <algorithm>

#include "loop/next_trial_policy.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner::internal {
namespace {

// The effect is significant by the likelihood ratio on top of the diagnosis's final model (its
// last round's test): a look-alike the final model holds instead leaves nothing for it.
bool StillSignificant(const ident::DiagnosisResult& r, model::Dof dof, const std::string& key) {
  int last = -1;
  for (const auto& t : r.tests) {
    if (t.dof == dof) last = std::max(last, t.round);
  }
  return std::any_of(r.tests.begin(), r.tests.end(), [&](const ident::CandidateTest& t) {
    return t.dof == dof && t.round == last && t.significant &&
           ident::CandidateName(t.effect, t.detail) == key;
  });
}

// `model` with the parameters, σ and settings of the effects `kept` as `old` has them.
model::DofParameters WithKept(model::DofParameters model, const model::DofParameters& old,
                              const std::vector<std::string>& kept) {
  for (const std::string& key : kept) {
    const model::EffectEntry* e = model::Effects().Find(key.substr(0, key.find(' ')));
    if (e == nullptr) continue;
    for (const auto& [name, value] : old.params) {
      if (!e->Owns(name)) continue;
      model.params[name] = value;
      if (old.sigma.count(name)) model.sigma[name] = old.sigma.at(name);
    }
    for (const model::EffectSetting& s : e->settings) {
      const auto v = old.settings.find(std::string(s.setting));
      if (v != old.settings.end()) model.settings[v->first] = v->second;
    }
  }
  return model;
}

// The finding's parameters are all installation coefficients, which identification's standard
// structure estimates for every direction the thrusters do not drive in open water (and the
// written-model stage takes from the campaign's mappings, not from the file).
bool InStandardStructure(const ident::Finding& f) {
  return std::all_of(f.params.begin(), f.params.end(), [](const ident::ParameterEstimate& p) {
    return model::StartsWith(p.name, model::param::kEtaPrefix);
  });
}

const ident::DofIdentification* ExtendedOf(const ident::DiagnosisResult& r, model::Dof dof) {
  for (const auto& e : r.extended) {
    if (e.dof == dof) return &e;
  }
  return nullptr;
}

// Per effect the diagnosis accepted into `found`, every other significant candidate of the same
// round whose AIC gain comes within `gap` of it: the trials do not yet say which of the two the
// vehicle has.
std::vector<std::string> Ambiguities(const ident::DiagnosisResult& r, model::Dof dof,
                                     const std::set<std::string>& found, double gap) {
  std::vector<std::string> out;
  for (const ident::CandidateTest& chosen : r.tests) {
    if (chosen.dof != dof || !chosen.accepted ||
        !found.count(ident::CandidateName(chosen.effect, chosen.detail))) {
      continue;
    }
    for (const ident::CandidateTest& t : r.tests) {
      if (t.dof != dof || t.round != chosen.round || !t.significant ||
          found.count(ident::CandidateName(t.effect, t.detail))) {
        continue;
      }
      const double lead = chosen.AicGain() - t.AicGain();
      if (lead >= gap) continue;
      out.push_back("model not settled: the diagnosis chose " + chosen.effect + " over " +
                    t.effect + " with an AIC lead of " + model::Significant(lead, 2) +
                    " (settled from " + model::Significant(gap, 2) +
                    "; more trials, or one that separates them, decide)");
    }
  }
  return out;
}

}  // namespace

ModelChange AdoptFindings(const model::Campaign& campaign, model::Dof dof,
                          const ident::DiagnoseOptions& options, double settled_aic_gap,
                          WorkingModel* working) {
  ModelChange change;
  if (FitTrials(campaign, dof) < 2) return change;
  ident::DiagnoseOptions o = options;
  o.dofs = {dof};
  ident::DiagnosisResult r;
  try {
    r = ident::Diagnose(DofCampaign(campaign, working->vehicle, dof), o);
  } catch (const model::InputError& e) {
    change.note = std::string("diagnosis refused the trials: ") + e.what();
    return change;
  }
  if (r.not_diagnosed.count(dof)) {
    change.note = "not diagnosed: " + r.not_diagnosed.at(dof);
    return change;
  }
  std::set<std::string> found;
  std::set<std::string>& known = working->effects[dof];
  for (const ident::Finding& f : r.findings) {
    const std::string key = ident::CandidateName(f.effect, f.detail);
    if (f.dof != dof || InStandardStructure(f)) continue;
    found.insert(key);
    if (!known.count(key)) change.entered.push_back({f.effect, f.detail, f.params, f.gain});
  }
  // An effect in the model stays while the likelihood ratio still finds it significant on top of
  // the diagnosed model: it entered on significance and held-out gain, and one fold of new
  // trials that gains less must not drop it (a URIS lag left after a trial at one thrust level,
  // and m converged 20σ off).
  std::vector<std::string> kept;
  for (const std::string& k : known) {
    if (found.count(k)) continue;
    if (StillSignificant(r, dof, k)) {
      kept.push_back(k);
    } else {
      change.left.push_back(k);
    }
  }
  found.insert(kept.begin(), kept.end());
  working->doubts[dof] = Ambiguities(r, dof, found, settled_aic_gap);
  if (!change.changed()) return change;
  const ident::DofIdentification* extended = ExtendedOf(r, dof);
  if (found.empty() || extended == nullptr) {
    working->vehicle.models.erase(dof);
  } else {
    const model::DofParameters old = working->vehicle.models[dof];
    const model::DofParameters model = WithKept(ident::ModelOf(*extended), old, kept);
    if (const std::string problem = ident::Inadmissible(model); !problem.empty()) {
      return {{}, {}, "the diagnosed model was not adopted: it has " + problem};
    }
    working->vehicle.models[dof] = model;
  }
  known = found;
  return change;
}

}  // namespace uuvplan::planner::internal
