// Measure stage: the gain of an extension is the free-run velocity MAE (ref 002 eq. 37) it
// saves on data it was not fitted to. A split that cannot score both models (no held-out
// trial, a fold without trials, a free run that cannot be simulated) gives no gain, and says
// why: a NaN is never folded into a number.
#include <algorithm>
#include <cmath>
#include <set>

#include "diagnosis_internal.h"
#include "parallel.h"
#include "uuvplan/ident/score.h"

namespace uuvplan::ident::diagnosis {

namespace {

// Scores `before` and `after` on `held_out` (`samples` velocity samples); false (and `why`)
// when either cannot be scored.
bool ScorePair(const StructureFit& before, const StructureFit& after, const Trials& held_out,
               double step_s, double* mae_before, double* mae_after, std::string* why,
               int* samples = nullptr) {
  std::string b, a;
  *mae_before = PooledVelocityMae(*before.model, before.oe.theta, held_out, step_s, &b, samples);
  *mae_after = PooledVelocityMae(*after.model, after.oe.theta, held_out, step_s, &a);
  if (!b.empty()) *why = "the current model: " + b;
  if (!a.empty()) *why = "the extension: " + a;
  return b.empty() && a.empty();
}

// The (mapping, direction) pairs a trial drives with at least a tenth of its largest force, e.g.
// "2+;3-;" (the installation coefficients it informs); "open " first when one of them is in
// open water (η = 1 by the contract: it fixes the scale of the thrust).
std::string ThrustKey(const model::Vehicle& vehicle, const TrialData& t) {
  double fmax = 0.0;
  for (double f : t.force) fmax = std::max(fmax, std::abs(f));
  std::set<std::pair<int, bool>> seen;
  bool open = false;
  for (std::size_t i = 0; i < t.force.size(); ++i) {
    if (!(std::abs(t.force[i]) >= 0.1 * fmax) || fmax == 0.0) continue;
    const int m = i < t.mapping.size() ? t.mapping[i] : -1;
    const bool pos = t.force[i] > 0;
    seen.insert({m, pos});
    if (m >= 0) {
      open = open ||
             vehicle.mappings[m].IsOpenWater(pos ? model::Direction::kPos : model::Direction::kNeg);
    }
  }
  std::string key = open ? "open " : "";
  for (const auto& [m, pos] : seen) key += std::to_string(m) + (pos ? "+;" : "-;");
  return key;
}

// K folds (K = min(trials, kMaxFolds)): the fit trials grouped by the thrust they drive
// (ThrustKey; trials with open-water thrust first, then each group in order of first
// appearance) and dealt in turn, so that trials driving the same (mapping, direction) pairs
// land in different folds and every training set keeps what informs each installation
// coefficient and the thrust's scale. With few trials this is leave-one-trial-out.
std::vector<Trials> DealFolds(const model::Vehicle& vehicle, const Trials& fit) {
  constexpr std::size_t kMaxFolds = 10;
  std::vector<std::string> keys(fit.size()), order;
  for (std::size_t i = 0; i < fit.size(); ++i) keys[i] = ThrustKey(vehicle, *fit[i]);
  for (int open = 1; open >= 0; --open) {
    for (const std::string& key : keys) {
      const bool is_open = key.rfind("open ", 0) == 0;
      if (is_open == (open == 1) && std::find(order.begin(), order.end(), key) == order.end()) {
        order.push_back(key);
      }
    }
  }
  std::vector<Trials> folds(std::min(fit.size(), kMaxFolds));
  std::size_t dealt = 0;
  for (const std::string& key : order) {
    for (std::size_t i = 0; i < fit.size(); ++i) {
      if (keys[i] == key) folds[dealt++ % folds.size()].push_back(fit[i]);
    }
  }
  return folds;
}

// `full`'s structure fitted on `fold`. A parameter the fold does not inform (an η of a mapping
// and direction only the held-out trials drive) is held at its value in `current`, or at its
// null value when new: both models then predict that part alike, and the gain measures the
// rest. `current` is the current model fitted on the same fold, never on the full data: a
// value fitted with the held-out trials would predict them with their own information
// (payload60 sway, the fold holding out the one backward-thrust trial: the dead zone and the
// bias cannot be told apart without it, the bias was held at the full fit's 0.396 N, which
// had absorbed that trial's loss, and the held-out gain of the dead zone came out at 19.8%).
StructureFit FoldFit(const model::Vehicle& vehicle, const StructureFit& full,
                     const StructureFit& current, const Trials& fold,
                     const OutputErrorOptions& oe) {
  StructureFit f =
      FitStructure(vehicle, full.structure, fold, full.values, full.dropped, oe, full.held);
  if (f.oe.ok() || f.oe.not_identifiable.empty()) return f;
  Values held = full.held;
  for (const std::string& name : f.oe.not_identifiable) {
    const auto c = current.values.find(name);
    held[name] = c != current.values.end() ? c->second : model::NullValue(name);
  }
  return FitStructure(vehicle, full.structure, fold, full.values, full.dropped, oe, held);
}

// One fold held out: both models fitted on the other trials and scored on it.
struct FoldScore {
  double before = 0, after = 0;
  int samples = 0;
  std::string unscored;
};

FoldScore ScoreFold(const model::Vehicle& vehicle, const StructureFit& before,
                    const StructureFit& after, const std::vector<Trials>& folds, std::size_t k,
                    const OutputErrorOptions& oe) {
  FoldScore s;
  Trials train;
  for (std::size_t j = 0; j < folds.size(); ++j) {
    if (j != k) train.insert(train.end(), folds[j].begin(), folds[j].end());
  }
  const StructureFit fb = FoldFit(vehicle, before, before, train, oe);
  const StructureFit fa = FoldFit(vehicle, after, fb, train, oe);
  const std::string fold = "fold " + std::to_string(k + 1) + " of " + std::to_string(folds.size());
  if (!fb.oe.ok() || !fa.oe.ok()) {
    s.unscored = fold + ": the " + (fb.oe.ok() ? "extension's" : "current model's") +
                 " fit on the other folds failed (" + (fb.oe.ok() ? fa : fb).oe.message + ")";
    return s;
  }
  std::string why;
  if (!ScorePair(fb, fa, folds[k], oe.step_s, &s.before, &s.after, &why, &s.samples)) {
    s.unscored = fold + ": " + why;
  }
  return s;
}

// K-fold cross-validation across the fit trials: each fold scored by the models fitted on the
// others (in parallel); the fold MAEs pooled with the fold's samples as weights.
void CrossValidate(const model::Vehicle& vehicle, const StructureFit& before,
                   const StructureFit& after, const Trials& fit, const OutputErrorOptions& oe,
                   int threads, DiagnosisGain* g) {
  if (fit.size() < 2) {
    g->unscored = "cross-validation needs at least 2 fit trials";
    return;
  }
  const std::vector<Trials> folds = DealFolds(vehicle, fit);
  std::vector<FoldScore> scores(folds.size());
  ParallelFor(folds.size(), threads,
              [&](std::size_t k) { scores[k] = ScoreFold(vehicle, before, after, folds, k, oe); });
  double sum_b = 0, sum_a = 0;
  int n = 0;
  for (const FoldScore& s : scores) {
    if (!s.unscored.empty()) {
      g->unscored = s.unscored;
      return;
    }
    sum_b += s.before * s.samples;
    sum_a += s.after * s.samples;
    n += s.samples;
    g->after_by_unit.push_back({s.after, s.samples});
  }
  g->before = sum_b / n;
  g->after = sum_a / n;
  g->scored = n > 0;
  if (!g->scored) g->unscored = "no held-out velocity sample";
}

}  // namespace

// On the validate trials, or by 2-fold cross-validation when none is marked.
DiagnosisGain HeldOutGain(const model::Vehicle& vehicle, const StructureFit& before,
                          const StructureFit& after, const Trials& fit, const Trials& validate,
                          const OutputErrorOptions& oe, int threads) {
  DiagnosisGain g;
  g.before = g.after = g.relative = std::nan("");
  if (!validate.empty()) {
    g.on = "validate";
    std::string why;
    g.scored = ScorePair(before, after, validate, oe.step_s, &g.before, &g.after, &why);
    if (!g.scored) g.unscored = "validate trials: " + why;
    if (g.scored) g.after_by_unit = PerTrialMae(after, validate, oe.step_s);
  } else {
    g.on = "cross-validation";
    CrossValidate(vehicle, before, after, fit, oe, threads, &g);
  }
  if (g.scored && !(g.before > 0)) {
    g.scored = false;
    g.unscored = "the current model's held-out error is 0: nothing to gain";
  }
  if (g.scored) g.relative = (g.before - g.after) / g.before;
  return g;
}

std::vector<std::pair<double, int>> PerTrialMae(const StructureFit& f, const Trials& trials,
                                                double step_s) {
  std::vector<std::pair<double, int>> out;
  for (const TrialData* t : trials) {
    std::string why;
    int n = 0;
    const double mae = PooledVelocityMae(*f.model, f.oe.theta, {t}, step_s, &why, &n);
    out.push_back({mae, n});
  }
  return out;
}

void PairedDifference(const std::vector<std::pair<double, int>>& a,
                      const std::vector<std::pair<double, int>>& b, double* delta, double* sigma) {
  *delta = *sigma = std::nan("");
  const std::size_t units = a.size();
  double n = 0.0;
  for (const auto& x : a) n += x.second;
  if (units == 0 || units != b.size() || !(n > 0)) return;
  double d = 0.0;
  for (std::size_t t = 0; t < units; ++t) d += a[t].second / n * (a[t].first - b[t].first);
  double ss = 0.0;
  for (std::size_t t = 0; t < units; ++t) {
    const double w = a[t].second / n;
    ss += w * w * std::pow(a[t].first - b[t].first - d, 2);
  }
  *delta = d;
  if (units > 1) *sigma = std::sqrt(units / (units - 1.0) * ss);
}

}  // namespace uuvplan::ident::diagnosis
