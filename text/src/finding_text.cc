// Each effect's finding sentence (finding_text.h). The group errors quoted are the breakdown's
// own figures (SignedPercent), so that a sentence reads the table's number, not a rounding of
// it that can read "0%" or turn -0.6% into "1%".
#include "uuvplan/text/finding_text.h"

#include <cmath>
#include <map>
#include <utility>

#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/quantity_text.h"

namespace uuvplan::text {
namespace {

using model::ErrorBreakdown;
using model::ErrorGroup;
using model::Significant;

// |r| as a whole percentage ("6%").
std::string WholePercent(double r) { return model::Decimals(std::abs(100.0 * r), 0) + "%"; }

// "<cause> (the standard simulation's speed error <where>: +38.0%)", or the cause alone without
// a group. The group's error is quoted as evidence beside the cause, not as its symptom: the
// standard model's m, drag and bias are fitted to the data and absorb part of an effect, so
// the error there can be small or even of the other sign (docs/diagnosis.md §2).
std::string GroupSentence(const ErrorGroup* g, const std::string& where, const std::string& cause) {
  if (!g) return cause;
  return cause + " (the standard simulation's speed error " + where + ": " +
         SignedPercent(g->relative) + ")";
}

// η < 1 (ref 000 eq. 3, Table I). The η that departs most from 1 names the mapping and
// direction. The fitted η says how much thrust is missing; the standard model's speed error
// there can be much smaller, when its m, drag and bias absorb part of the loss (ref 000 Fig. 6:
// the heave weight), so it is quoted second.
std::string InstallationLoss(const FindingQuotes& f) {
  const ident::ParameterEstimate* worst = nullptr;
  for (const auto& p : f.params) {
    if (!worst || std::abs(p.value - 1) > std::abs(worst->value - 1)) worst = &p;
  }
  if (!worst) return std::string("installation loss");
  const std::string name(model::Qualifier(worst->name));  // "<mapping>.<pos|neg>"
  const std::string mapping = name.substr(0, name.rfind('.'));
  const std::string sign = name.substr(name.rfind('.') + 1) == "neg" ? "negative" : "positive";
  std::string s = "thrust " + sign + " in mapping " + mapping + " delivers " +
                  Significant(std::abs(100 * (1 - worst->value)), 3) + " ± " +
                  Significant(100 * worst->sigma, 2) + "%" +
                  (worst->value <= 1 ? " less" : " more") + " than the open-water model";
  if (const ErrorGroup* g =
          model::Labeled(f.breakdown.by_thrust, "thrust " + sign + " in " + mapping)) {
    s += " (with eta = 1 the standard simulation's speed error there: " +
         SignedPercent(g->relative) + ", its m, drag and bias absorbing part of the loss)";
  }
  return s;
}

std::string AsymmetricDrag(const FindingQuotes& f) {
  const ErrorGroup* g = model::Largest(f.breakdown.by_motion);
  return GroupSentence(g, g ? "in " + g->label : "", "drag differs between the two directions");
}

std::string ThrusterLag(const FindingQuotes& f) {
  std::string s = "the response to every change of thrust comes late and smoothed";
  // The cross-correlation resolves whole samples only; a lag below that, or a lead (the
  // standard model's m and drag absorbed more than the lag), is not evidence of it.
  if (f.breakdown.lag_s > 0) s += " (" + MeasuredShiftText(f.breakdown) + ")";
  return s;
}

std::string Deadzone(const FindingQuotes& f) {
  return GroupSentence(model::Labeled(f.breakdown.by_command, ErrorBreakdown::kSmallCommands),
                       "for small commands", "no thrust below a threshold");
}

std::string AdvanceSpeedLoss(const FindingQuotes& f) {
  const ErrorGroup* g = model::Largest(f.breakdown.by_speed);
  return GroupSentence(g, g ? "at " + g->label : "", "thrust falls with the speed of advance");
}

// The coupled horizontal model of ref 003 names the Coriolis pair of each DOF.
std::string Coupling(const FindingQuotes& f) {
  std::string s = "errors follow the motion of other degrees of freedom (" + f.detail.substr(0, 1) +
                  "·" + f.detail.substr(1, 1) + ")";
  const model::CoriolisTerm coriolis = model::CoriolisTermOf(f.breakdown.dof);
  if (!coriolis.pair.empty() && f.detail == coriolis.pair) {
    s += ": the Coriolis term of seed 003's coupled surge–sway–yaw model (its coefficient is " +
         coriolis.coefficient +
         "); identify the three DOFs together with `uuvplan identify --model coupled`";
  }
  return s;
}

// The fitted delay is the finding; the breakdown's shift (against the standard model, whose m
// and drag absorb part of a delay) is quoted beside it with its own meaning, as it may differ in
// size and even in sign.
std::string SensorDelay(const FindingQuotes& f) {
  std::string s = "every measurement comes a fixed time after the motion it measures";
  for (const auto& p : f.params) {
    if (p.name == "sensor_delay") s += " (fitted: " + ValueSigma(p.value, p.sigma, "s", 2, 2) + ")";
  }
  return s + "; before the delay was modelled, " + MeasuredShiftText(f.breakdown);
}

// The relative change of thrust per second of campaign, over the span of the campaign clock.
std::string ParameterDrift(const FindingQuotes& f) {
  const double per_s = f.params.empty() ? 0.0 : f.params[0].value;
  const double sigma_s = f.params.empty() ? 0.0 : f.params[0].sigma;
  const double span_h = f.breakdown.campaign_span_h;
  std::string s = "the thrust " + std::string(per_s >= 0 ? "grows" : "falls") + " by " +
                  WholePercent(per_s * 3600.0 * span_h) + " from the first to the last trial (" +
                  model::Decimals(span_h, 2) + " h apart, " +
                  Significant(std::abs(100.0 * per_s * 3600.0), 3) + " ± " +
                  Significant(100.0 * sigma_s * 3600.0, 2) + "% per hour)";
  if (span_h > 24.0) {
    s += ". The trials are days apart: ballast, battery or thrust map may differ between "
         "sessions; if each session used its own command amplitude, a thrust map wrong in "
         "shape looks the same (compare one amplitude across sessions)";
  }
  return s;
}

// u = u0·(|u0|/u_ref)^p: at a fifth of the largest command the force is 0.2^p of nominal.
std::string ThrustMap(const FindingQuotes& f) {
  const double p = f.params.empty() ? 0.0 : f.params[0].value;
  const double sigma = f.params.empty() ? 0.0 : f.params[0].sigma;
  const double fifth = std::pow(0.2, p) - 1.0;
  std::string s = "the delivered force grows as |nominal force|^(" + Significant(1.0 + p, 3) +
                  " ± " + Significant(sigma, 2) + ")" +
                  ", not in proportion to the thrust table's force: at a fifth of the largest "
                  "nominal force it is " +
                  WholePercent(fifth) + (fifth >= 0 ? " above" : " below") +
                  " what the thrust map says";
  if (const ErrorGroup* g =
          model::Labeled(f.breakdown.by_command, ErrorBreakdown::kSmallCommands)) {
    s += " (the standard simulation's speed error for small commands: " +
         SignedPercent(g->relative) + ")";
  }
  return s + ": the thrust map is wrong in shape";
}

std::map<std::string, FindingSentenceRule>& Rules() {
  static std::map<std::string, FindingSentenceRule> rules = {
      {"installation_loss", InstallationLoss},
      {"asymmetric_drag", AsymmetricDrag},
      {"thruster_lag", ThrusterLag},
      {"deadzone", Deadzone},
      {"advance_speed_loss", AdvanceSpeedLoss},
      {"coupling", Coupling},
      {"sensor_delay", SensorDelay},
      {"parameter_drift", ParameterDrift},
      {"thrust_map", ThrustMap}};
  return rules;
}

// An effect without a sentence: its physics from the table, else its name.
std::string GenericSentence(const std::string& effect) {
  const model::EffectEntry* entry = model::Effects().Find(effect);
  return entry && !entry->physics.empty() ? entry->physics : effect;
}

}  // namespace

std::string MeasuredShiftText(const ErrorBreakdown& b) {
  const std::string what = "measured velocity ";
  const std::string against = " the standard model's simulation";
  if (!(std::abs(b.lag_s) > 0)) return what + "and" + against + " align within a sample";
  return what + (b.lag_s > 0 ? "lags" : "leads") + against + " by " +
         ValueSigma(std::abs(b.lag_s), b.lag_sigma_s, "s", 2, 2);
}

ScopedFindingSentence::ScopedFindingSentence(std::string effect, FindingSentenceRule rule)
    : effect_(std::move(effect)) {
  Rules()[effect_] = std::move(rule);
}

ScopedFindingSentence::~ScopedFindingSentence() { Rules().erase(effect_); }

std::string FindingSentence(const ident::Finding& f, const model::ErrorBreakdown& breakdown) {
  const auto rule = Rules().find(f.effect);
  std::string s = rule != Rules().end() ? rule->second({f.params, breakdown, f.detail})
                                        : GenericSentence(f.effect);
  for (const ident::CorrectedThrustMap& m : f.thrust_maps) {
    s += "; " + m.mapping + ": the delivered thrust is " + m.shape + " (|command|^" +
         Significant(m.command_exponent, 3) + " ± " + Significant(m.command_exponent_sigma, 2) +
         ")";
  }
  return s;
}

std::string FindingSentence(const ident::DiagnosisResult& result, const ident::Finding& f) {
  for (const model::ErrorBreakdown& b : result.breakdowns) {
    if (b.dof == f.dof) return FindingSentence(f, b);
  }
  model::ErrorBreakdown none;
  none.dof = f.dof;
  return FindingSentence(f, none);
}

}  // namespace uuvplan::text
