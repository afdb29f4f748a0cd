// The built-in effects (contract §diagnose, plus thrust_map). Each entry: the physics, its
// parameters (units, null value, admissible range), where it acts and how diagnosis proposes
// it (starting values scaled by the data); how a finding of it reads is the text layer's
// (text/finding_text.h). Order matters: it is the order in which the effects' parameters enter
// theta (dof_model.h).
#include <cmath>
#include <limits>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/force_term.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model::internal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// "" when `q` is "<mapping>.<pos|neg>" with a mapping of the vehicle on `dof`.
std::string EtaQualifier(std::string_view q, Dof dof, const Vehicle& vehicle) {
  const std::size_t dot = q.rfind('.');
  const std::string mapping(q.substr(0, dot == std::string_view::npos ? 0 : dot));
  const std::string_view direction = dot == std::string_view::npos ? "" : q.substr(dot + 1);
  const int index = vehicle.MappingIndex(mapping);
  if (index >= 0 && vehicle.mappings[index].dof == dof &&
      (direction == "pos" || direction == "neg")) {
    return "";
  }
  std::vector<std::string> names;
  for (int i : vehicle.MappingsOf(dof)) names.push_back(vehicle.mappings[i].name);
  return "'<mapping>.pos' or '<mapping>.neg' with a " + std::string(DofName(dof)) +
         " mapping of the vehicle (" + Join(names) + ")";
}

// "" when `q` is two velocity letters.
std::string VelocityPair(std::string_view q, Dof, const Vehicle&) {
  const auto letter = [](char c) {
    return std::string_view("uvwpqr").find(c) != std::string_view::npos;
  };
  return q.size() == 2 && letter(q[0]) && letter(q[1])
             ? ""
             : "two velocity letters of u v w p q r (e.g. 'vr')";
}

// c_ab·a·b is a force (N, or N·m on a rotation): c_ab is in the force's unit over a's and b's
// (m/s for u v w, rad/s for p q r), e.g. N·s²/m² for uv on heave, N·m·s²/rad² for rq on yaw.
std::string CouplingUnit(std::string_view q, Dof dof) {
  const auto metres = [&](std::size_t i) {
    return i < q.size() && std::string_view("uvw").find(q[i]) != std::string_view::npos;
  };
  const int lengths = metres(0) + metres(1);
  return std::string(ForceUnit(dof)) + "·s²/" +
         (lengths == 2   ? "m²"
          : lengths == 1 ? "(m·rad)"
                         : "rad²");
}

// An entry: its contract name, the physics in one line, where it acts and its parameter
// families (the families' details and how diagnosis proposes it are the caller's).
EffectEntry Entry(std::string name, std::string physics, EffectSite site,
                  std::vector<ParameterFamily> parameters) {
  EffectEntry e;
  e.name = std::move(name);
  e.physics = std::move(physics);
  e.site = site;
  e.parameters = std::move(parameters);
  return e;
}

// `p` as diagnosis's proposals: none when it adds no parameter.
std::vector<Proposal> Proposals(const Proposal& p) {
  if (p.start.empty()) return {};
  return {p};
}

// One proposal adding parameter `name` at `start`, unless the structure has it.
std::vector<Proposal> SingleIfAbsent(const ProposalEvidence& c, const char* name, double start) {
  if (c.Has(name)) return {};
  Proposal p;
  p.start.push_back({name, start});
  return {p};
}

// η < 1 (ref 000 eq. 3, Table I): the thrust of a mapping and direction that is not in open
// water, one η per such direction present in the data.
EffectEntry InstallationLoss() {
  EffectEntry e =
      Entry("installation_loss",
            "η < 1: propeller–hull / propeller–propeller interaction for a mapping and direction",
            EffectSite::kStandardTerm,
            {{param::kEtaPrefix, "installation coefficient of <mapping>.<pos|neg>", "1", "1", 1.0,
              0.0, 2.0}});
  ParameterFamily& eta = e.parameters[0];
  eta.lower_open = true;
  eta.expected = "an installation coefficient in (0, 2]";
  // CHOSEN: an installation can lose thrust (Table I: 0.55–0.89) but gains at most
  // a little (a duct or a wall effect); an estimate above 1.2 is a fit absorbing another error.
  eta.physical_upper = 1.2;
  eta.file_key = "eta";
  eta.check_qualifier = EtaQualifier;
  e.propose = [](const ProposalEvidence& c) {
    Proposal p;
    for (const auto& [mapping, dir] : c.closed_thrust_directions) {
      const std::string name = EtaName(mapping, dir);
      if (!c.Has(name)) p.start.push_back({name, 1.0});
    }
    return Proposals(p);
  };
  return e;
}

// Drag differs with the direction of motion: (k, kq) for ξ ≥ 0, (k_neg, kq_neg) for ξ < 0.
EffectEntry AsymmetricDrag() {
  EffectEntry e =
      Entry("asymmetric_drag", "drag differs between positive and negative motion (k±, kq±)",
            EffectSite::kStandardTerm,
            {{param::kLinearDragNeg, "linear drag for negative motion", "N·s/m", "N·m·s/rad", 0.0,
              0.0, kInf},
             {param::kQuadraticDragNeg, "quadratic drag for negative motion", "N·s²/m²",
              "N·m·s²/rad²", 0.0, 0.0, kInf}});
  e.parameters[0].defaults_to = param::kLinearDrag;  // symmetric unless given
  e.parameters[1].defaults_to = param::kQuadraticDrag;
  e.propose = [](const ProposalEvidence& c) {
    if (c.Has(param::kLinearDragNeg) || c.Has(param::kQuadraticDragNeg))
      return std::vector<Proposal>{};
    Proposal p;
    // k_neg / kq_neg are compared with k / kq, not with 0: their null is the symmetric value.
    const std::pair<const char*, const char*> sides[] = {
        {param::kLinearDragNeg, param::kLinearDrag},
        {param::kQuadraticDragNeg, param::kQuadraticDrag}};
    for (const auto& [negative, positive] : sides) {
      if (!c.Has(positive)) continue;
      p.null[negative] = c.Value(positive, 0.0);
      p.start.push_back({negative, p.null[negative]});
    }
    return Proposals(p);
  };
  return e;
}

// T·dφ_a/dt = u − φ_a: the thrust follows the command through a first-order lag.
EffectEntry ThrusterLag() {
  EffectEntry e =
      Entry("thruster_lag", "thrust follows the command through first-order actuator dynamics",
            EffectSite::kActuator,
            {{param::kLag, "time constant T of the thrust", "s", "s", 0.0, 0.0, kInf, 0.1}});
  e.parameters[0].lower_open = true;
  e.parameters[0].fit_lower = 0.0;  // T > 0: the lag divides by it
  e.parameters[0].fit_lower_open = true;
  e.propose = [](const ProposalEvidence& c) {
    return SingleIfAbsent(c, param::kLag, 0.1 * c.time_constant_s);
  };
  return e;
}

// u0 = sign(φ)·max(|φ| − d, 0): no thrust for small commands.
EffectEntry Deadzone() {
  EffectEntry e =
      Entry("deadzone", "no thrust for small commanded force", EffectSite::kActuator,
            {{param::kDeadzone, "width d of the dead band", "N", "N·m", 0.0, 0.0, kInf}});
  e.parameters[0].fit_lower = 0.0;
  e.propose = [](const ProposalEvidence& c) {
    return SingleIfAbsent(c, param::kDeadzone, 0.02 * c.max_force);
  };
  return e;
}

// −c_a·sqrt(|φ_a|)·ξ (ref 000 eq. 5 with |n| ∝ sqrt|φ|, v_a = ξ).
EffectEntry AdvanceSpeedLoss() {
  EffectEntry e = Entry("advance_speed_loss",
                        "thrust falls with the speed of advance (τ = c·n|n| − c_s·|n|·v_a)",
                        EffectSite::kForceTerm,
                        {{param::kAdvanceLoss, "advance-speed loss c_a", "N^½·s/m", "(N·m)^½·s/rad",
                          0.0, 0.0, kInf}});
  e.make_term = [](Dof, const std::vector<std::string>&) { return MakeAdvanceLossTerm(); };
  e.propose = [](const ProposalEvidence& c) { return SingleIfAbsent(c, param::kAdvanceLoss, 0.0); };
  return e;
}

// Σ c_ab·a·b over velocity letters (ref 003 3-DOF model: surge v·r and r², yaw u·r).
EffectEntry Coupling() {
  EffectEntry e =
      Entry("coupling",
            "motion in another DOF drives this one (e.g. surge speed × yaw rate terms of the "
            "3-DOF model)",
            EffectSite::kForceTerm,
            {{param::kCouplingPrefix, "coefficient c_ab of the force c_ab·a·b", "N·s²/m²",
              "N·m·s²/rad²", 0.0, -kInf, kInf}});
  e.parameters[0].file_key = "coefficients";
  e.parameters[0].check_qualifier = VelocityPair;
  e.parameters[0].unit_of = CouplingUnit;
  e.reads_other_motion = true;
  e.make_term = [](Dof dof, const std::vector<std::string>& parameters) {
    std::vector<std::string> pairs;
    for (const std::string& p : parameters) pairs.emplace_back(Qualifier(p));
    return MakeCouplingTerm(dof, pairs);
  };
  e.propose = [](const ProposalEvidence& c) {
    std::vector<Proposal> out;
    const std::vector<char>& letters = c.velocity_letters;
    const char own = VelocityLetter(c.dof);
    for (std::size_t i = 0; i < letters.size(); ++i) {
      for (std::size_t j = i; j < letters.size(); ++j) {
        if (letters[i] == own && letters[j] == own) continue;  // ξ² is quadratic drag
        const std::string pair{letters[i], letters[j]};
        const std::string name = param::kCouplingPrefix + pair;
        if (c.Has(name)) continue;
        Proposal p;
        p.detail = pair;
        p.start.push_back({name, 0.0});
        out.push_back(p);
      }
    }
    return out;
  };
  return e;
}

// y(t) = x(t − τ): the measurement lags the motion.
EffectEntry SensorDelay() {
  EffectEntry e =
      Entry("sensor_delay", "the measurement lags the motion by a fixed time", EffectSite::kSensor,
            {{param::kSensorDelay, "delay τ of the measurement", "s", "s", 0.0, 0.0, kInf}});
  e.parameters[0].fit_lower = 0.0;  // the measurement cannot precede the motion
  e.propose = [](const ProposalEvidence& c) {
    return SingleIfAbsent(c, param::kSensorDelay, 0.05 * c.time_constant_s);
  };
  return e;
}

// drift·t_c·φ_a: the thrust changes slowly over the campaign clock t_c (battery).
EffectEntry ParameterDrift() {
  EffectEntry e =
      Entry("parameter_drift",
            "a parameter changes slowly during the campaign (e.g. thrust falling with battery)",
            EffectSite::kForceTerm,
            {{param::kDrift, "relative change of thrust per second of campaign", "1/s", "1/s", 0.0,
              -kInf, kInf}});
  e.needs_campaign_clock = true;
  e.make_term = [](Dof, const std::vector<std::string>&) { return MakeDriftTerm(); };
  e.propose = [](const ProposalEvidence& c) {
    // Drift needs trials spread over the campaign clock.
    return c.campaign_clock ? SingleIfAbsent(c, param::kDrift, 0.0) : std::vector<Proposal>{};
  };
  return e;
}

// u = u0·(|u0|/u_ref)^p: a thrust map wrong in shape (notes/pitfalls.md).
EffectEntry ThrustMap() {
  EffectEntry e = Entry(
      "thrust_map", "the thrust map is wrong in shape: the delivered force is u0·(|u0|/u_ref)^p",
      EffectSite::kActuator,
      {{param::kThrustExponent, "exponent p of the delivered force's shape", "1", "1", 0.0, -1.0,
        kInf}});
  e.parameters[0].lower_open = true;
  e.parameters[0].expected = "a number > -1 (the delivered force must grow with the command)";
  // 1 + p ≥ 0.05 keeps a fit off the flat map, where m, drag and p cannot be told apart.
  e.parameters[0].fit_lower = -0.95;
  e.parameters[0].fit_lower_open = true;
  e.settings = {{"reference", param::kThrustReference}};
  e.propose = [](const ProposalEvidence& c) {
    // The shape shows only across command levels: at a single |φ| it is a pure scale (absorbed
    // by m, k, kq, bias). Levels spanning less than a factor 1.5 are not tested.
    if (c.Has(param::kThrustExponent) || !(c.max_force > 0 && c.min_force < c.max_force / 1.5)) {
      return std::vector<Proposal>{};
    }
    Proposal p;
    p.start.push_back({param::kThrustExponent, 0.0});
    p.settings[param::kThrustReference] = c.max_force;  // η, m, k, kq keep their meaning there
    return std::vector<Proposal>{p};
  };
  return e;
}

}  // namespace

std::vector<EffectEntry> BuiltInEffects() {
  return {InstallationLoss(), AsymmetricDrag(), ThrusterLag(),    Deadzone(), AdvanceSpeedLoss(),
          Coupling(),         SensorDelay(),    ParameterDrift(), ThrustMap()};
}

}  // namespace uuvplan::model::internal
