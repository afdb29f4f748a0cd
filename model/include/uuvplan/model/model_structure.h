// Which parameters a DOF's model has: the standard model of the contract plus any effects,
// as a list of names of the parameter vocabulary (parameter.h, effects.h). A DofModel is built
// from a Vehicle and a ModelStructure; identification, planning and diagnosis change the
// structure, never the equations.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct Vehicle;
struct DofParameters;

struct ModelStructure {
  Dof dof = Dof::kSurge;
  /// Every parameter besides m (always there), e.g. {"k", "kq", "bias", "eta.front.neg", "lag"}.
  std::vector<std::string> parameters = {"k", "kq", "bias"};
  /// Settings of effects that are not estimated, e.g. "thrust_reference" (N or N·m).
  std::map<std::string, double> settings;

  bool Has(std::string_view parameter) const;
  /// The parameters whose name starts with `prefix` (a qualified family: "eta.").
  std::vector<std::string> WithPrefix(std::string_view prefix) const;
  /// The parameters of effect `effect` (effects.h) in this structure.
  std::vector<std::string> OfEffect(std::string_view effect) const;
  bool HasEffect(std::string_view effect) const { return !OfEffect(effect).empty(); }
  /// The parameters `effect` declares, in this structure.
  std::vector<std::string> Of(const struct EffectEntry& effect) const;
  void Add(const std::string& parameter);  ///< no-op when present
  void Remove(std::string_view parameter);
  /// A setting's value, or `fallback`.
  double Setting(const std::string& key, double fallback) const;

  /// The standard structure of the contract: m, k, kq, bias, bias_step when `ballast`,
  /// and eta of every non-open-water direction of each of `mappings_used`.
  static ModelStructure Standard(const Vehicle& vehicle, Dof dof,
                                 const std::vector<std::string>& mappings_used, bool ballast);
};

/// `base` extended by every parameter and setting of `written` (a model a vehicle file gives:
/// its effects, as `diagnose --write-vehicle` writes them) that it lacks; m, bias_step and η
/// stay as `base` has them (they follow the campaign's ballast and mappings). `added`, when
/// given, receives the parameters added.
ModelStructure WithWrittenEffects(ModelStructure base, const DofParameters& written,
                                  std::vector<std::string>* added = nullptr);

}  // namespace uuvplan::model
