// Test support for diagnosis: draws a random vehicle, sensors, noise, a trial set and
// ONE hidden effect (or none) of random but identifiable magnitude, and runs it through the
// virtual pool. The code under test sees only the campaign it produces (vehicle + logs); the
// truth stays here.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::testing {

struct HiddenEffectCase {
  model::Truth truth;
  model::Dof dof = model::Dof::kSurge;
  std::vector<model::TrialDesign> trials;
  std::vector<model::TrialUse> use;  ///< per trial
  std::optional<std::string> effect;
  /// True values of the hidden effect's parameters, by vocabulary name (effects.h).
  std::map<std::string, double> effect_params;
  double time_constant_s = 0.0;  ///< m / k_L at the typical speed
  double typical_force = 0.0;    ///< N or N·m
};

/// A random case with `effect` hidden (none: clean data), reproducible from `seed`.
HiddenEffectCase DrawHiddenEffectCase(std::optional<std::string> effect, std::uint64_t seed);

/// Runs the case's trials in the virtual pool (in memory, no files): the campaign a pool team
/// would bring back. The vehicle in it is the truth's vehicle (what the user would write).
model::Campaign RunHiddenEffectCase(const HiddenEffectCase& c, std::uint64_t seed);

/// Diagnosis options for a case: the RK4 step follows the case's time constant (t_c/20 keeps
/// the RK4 error below 1e-6 of the response), which is what a user would choose too.
ident::DiagnoseOptions DiagnoseOptionsFor(const HiddenEffectCase& c);

/// Whether a diagnosis named exactly the hidden effect (nothing on clean data), and whether the
/// hidden parameters lie within 3σ of their truth.
struct Verdict {
  bool correct = false;
  bool within_3_sigma = false;
  std::string found;  ///< the effects named, for messages
};
Verdict Judge(const HiddenEffectCase& c, const ident::DiagnosisResult& r);

}  // namespace uuvplan::testing
