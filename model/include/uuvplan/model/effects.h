// The physical effects beyond the standard 1-DOF model (contract §diagnose), the names of the
// parameters each one adds to a DOF, and their settings in a truth file.
//
// Parameter vocabulary (one place; identification, planning and diagnosis all use it):
//   m, k, kq, bias, bias_step             standard model (seed 000 eq. 3, eq. 20)
//   eta.<mapping>.pos / .neg               installation_loss (seed 000 eq. 3, Table I)
//   k_neg, kq_neg                          asymmetric_drag: drag for xi < 0 (k, kq for xi >= 0)
//   lag                                    thruster_lag: time constant T (s), T·dphi_a/dt = u - phi_a
//   deadzone                               deadzone: width d, u = sign(phi)·max(|phi| - d, 0)
//   advance_loss                           advance_speed_loss: F = -c_a·sqrt(|phi_a|)·xi
//                                          (seed 000 eq. 5 with |n| ∝ sqrt(|phi|), v_a = xi)
//   coupling.<ab>                          coupling: F = c_ab·a·b, a, b velocity letters u v w p q r
//                                          (seed 003 3-DOF model: surge c_vr·v·r, c_rr·r², yaw c_ur·u·r)
//   sensor_delay                           sensor_delay: y(t) = x(t - tau) (s)
//   drift                                  parameter_drift: F = drift·t_c·phi_a, t_c campaign time (1/s)
//   thrust_exponent                        thrust_map: u ← u·(|u|/u_ref)^p, the delivered force of a
//                                          thrust map wrong in shape (notes/pitfalls.md; u_ref, the
//                                          force at which the map is right, is a setting)
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace uuvplan::model {

enum class Effect {
  kInstallationLoss,
  kAsymmetricDrag,
  kThrusterLag,
  kDeadzone,
  kAdvanceSpeedLoss,
  kCoupling,
  kSensorDelay,
  kParameterDrift,
  kThrustMap,
};

inline constexpr Effect kAllEffects[] = {
    Effect::kInstallationLoss, Effect::kAsymmetricDrag, Effect::kThrusterLag,
    Effect::kDeadzone,         Effect::kAdvanceSpeedLoss, Effect::kCoupling,
    Effect::kSensorDelay,      Effect::kParameterDrift,   Effect::kThrustMap};

/// The contract's names: installation_loss, asymmetric_drag, thruster_lag, deadzone,
/// advance_speed_loss, coupling, sensor_delay, parameter_drift; and thrust_map (an addition to
/// the contract's table).
std::string_view EffectName(Effect effect);
std::optional<Effect> ParseEffect(std::string_view name);

namespace param {
inline constexpr const char* kMass = "m";
inline constexpr const char* kLinearDrag = "k";
inline constexpr const char* kQuadraticDrag = "kq";
inline constexpr const char* kBias = "bias";
inline constexpr const char* kBiasStep = "bias_step";
inline constexpr const char* kLinearDragNeg = "k_neg";
inline constexpr const char* kQuadraticDragNeg = "kq_neg";
inline constexpr const char* kLag = "lag";
inline constexpr const char* kDeadzone = "deadzone";
inline constexpr const char* kAdvanceLoss = "advance_loss";
inline constexpr const char* kSensorDelay = "sensor_delay";
inline constexpr const char* kDrift = "drift";
inline constexpr const char* kThrustExponent = "thrust_exponent";
inline constexpr const char* kCouplingPrefix = "coupling.";
inline constexpr const char* kEtaPrefix = "eta.";
}  // namespace param

}  // namespace uuvplan::model
