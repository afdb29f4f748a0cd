// The physical effects beyond the standard 1-DOF model (contract §diagnose): one table, each
// entry declaring its name, the physics, its parameters (with units, null value and admissible
// range), where it acts in the model (its own force term, a standard term, the actuator path
// or the sensor) and how diagnosis may propose it. Simulation, identification, planning and
// diagnosis all read this table; adding an effect is one entry (effect_table.cc) plus its
// force term, its finding's sentence (text/finding_text.h) and tests (docs/architecture.md,
// "How to add an effect").
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/force_term.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/parameter.h"

namespace uuvplan::model {

/// Where an effect acts on the DOF model (dof_model.h).
enum class EffectSite {
  kForceTerm,     ///< a force term of its own, built by the entry's make_term
  kStandardTerm,  ///< its parameters enter a standard term (η in thrust, k_neg in drag)
  kActuator,      ///< the actuator path between command and force (dof_model_kernel.h)
  kSensor,        ///< the measurement of the position (simulator.h)
};

/// What diagnosis knows of the data and of the current fit when it proposes an effect.
struct ProposalEvidence {
  Dof dof = Dof::kSurge;
  const std::vector<std::string>* parameters = nullptr;   ///< of the current structure
  const std::map<std::string, double>* values = nullptr;  ///< current estimates
  double time_constant_s = 1.0;  ///< m / (k + 2·kq·|ξ|) at the typical speed
  double max_force = 0.0;        ///< largest |φⁿ| in the data (N or N·m)
  double min_force = 0.0;        ///< smallest |φⁿ| above 1% of the largest
  /// Mapping and direction of φⁿ present in the data, for thrust not in open water there.
  std::vector<std::pair<std::string, Direction>> closed_thrust_directions;
  std::vector<char> velocity_letters;  ///< measured in every trial, the own DOF's first
  bool campaign_clock = false;         ///< every trial has a start, and they span some time

  bool Has(std::string_view parameter) const;
  double Value(std::string_view parameter, double fallback) const;
};

/// One way diagnosis may extend a structure with an effect.
struct Proposal {
  std::string detail;  ///< e.g. the coupling pair; empty for most
  /// The new parameters, in the order they enter theta, and their starting values.
  std::vector<std::pair<std::string, double>> start;
  std::map<std::string, double> settings;  ///< structure settings it needs (thrust_reference)
  /// Null values of the new parameters that are not the family's (asymmetric drag: the
  /// symmetric value).
  std::map<std::string, double> null;
};

/// A setting of an effect in a truth file that is not a parameter (thrust_map's reference
/// force): read from `file_key`, stored as the structure setting `setting`; required, > 0.
struct EffectSetting {
  std::string_view file_key;
  std::string_view setting;
};

struct EffectEntry {
  std::string name;     ///< contract name, e.g. "thruster_lag"
  std::string physics;  ///< one line, the contract's table
  EffectSite site = EffectSite::kForceTerm;
  std::vector<ParameterFamily> parameters;
  bool diagnosable = true;  ///< diagnosis may propose it
  /// It shows only across trials on the campaign clock (diagnosis says so when there is none).
  bool needs_campaign_clock = false;
  /// Truth file: settings beyond the parameters, and whether the effect's settings also give
  /// the other DOFs' motion during the trials (`motion`, for terms that read it).
  std::vector<EffectSetting> settings;
  bool reads_other_motion = false;
  /// kForceTerm: the term, given the DOF and the structure's parameters of this effect.
  std::function<std::unique_ptr<ForceTerm>(Dof, const std::vector<std::string>&)> make_term;
  /// Diagnosis: the extensions of the current structure it proposes (none: not applicable).
  std::function<std::vector<Proposal>(const ProposalEvidence&)> propose;

  bool Owns(std::string_view parameter) const;
};

/// The effect table. Built-in entries first (effect_table.cc); an extension may register more
/// (a test registers a toy effect through ScopedEffect).
class EffectTable {
 public:
  const std::vector<EffectEntry>& entries() const { return entries_; }
  /// The entry named `name`, or nullptr.
  const EffectEntry* Find(std::string_view name) const;
  /// The entry that declares `parameter`, or nullptr (standard parameters have none).
  const EffectEntry* OwnerOf(std::string_view parameter) const;
  /// Every effect name, for messages: "installation_loss, asymmetric_drag, ...".
  std::string NameList() const;
  /// The names of the entries diagnosis may propose, in table order.
  std::vector<std::string> Diagnosable() const;

  void Register(EffectEntry entry);
  void Unregister(std::string_view name);

 private:
  friend const EffectTable& Effects();
  friend class ScopedEffect;
  static EffectTable& Mutable();
  std::vector<EffectEntry> entries_;
};

/// The table (built-in entries on first use).
const EffectTable& Effects();

/// Registers an entry for the lifetime of the object (tests, extensions).
class ScopedEffect {
 public:
  explicit ScopedEffect(EffectEntry entry);
  ~ScopedEffect();
  ScopedEffect(const ScopedEffect&) = delete;
  ScopedEffect& operator=(const ScopedEffect&) = delete;

 private:
  std::string name_;
};

namespace internal {
/// The built-in entries, in the order their parameters enter theta (effect_table.cc).
std::vector<EffectEntry> BuiltInEffects();
}  // namespace internal

}  // namespace uuvplan::model
