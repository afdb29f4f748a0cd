// The virtual vehicles of the papers (cases/romeo, cases/vsor, cases/uris truth files) and trial
// designs of the kinds the papers ran on them: ROMEO (ref 000: heave with five ballast steps and
// η = 0.56, yaw and surge with their mappings in both directions, the §IV-D sines), VSOR (seed
// 002 Table 4 sines, yaw), URIS (ref 004 §5: steps and PRBS in surge, yaw, pitch).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "uuvplan/io/io.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::ident::testing {

/// The truth file of a case under cases/ (cases/romeo, cases/vsor, cases/uris).
inline model::Truth CaseTruth(const std::string& name) {
  return io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + name + "/truth.yaml");
}

inline model::TrialDesign Segments(const std::string& id, model::Dof dof,
                                   const std::string& mapping,
                                   const std::vector<std::pair<double, double>>& legs,
                                   int ballast = 0) {
  model::TrialDesign d;
  d.id = id;
  d.dof = dof;
  d.kind = model::TrialKind::kSegments;
  d.mapping = mapping;
  d.ballast_steps = ballast;
  for (const auto& [force, duration] : legs) {
    d.segments.push_back({force, duration, ""});
    d.duration += duration;
  }
  return d;
}

inline model::TrialDesign Sine(const std::string& id, model::Dof dof, const std::string& mapping,
                               double offset, double amplitude, double period, double duration) {
  model::TrialDesign d;
  d.id = id;
  d.dof = dof;
  d.kind = model::TrialKind::kSine;
  d.mapping = mapping;
  d.offset = offset;
  d.amplitude = amplitude;
  d.omega = 2 * M_PI / period;
  d.duration = duration;
  return d;
}

/// ROMEO surge: back-and-forth steady legs with each mapping (forward and backward motion,
/// ref 000 Table IV) and the §IV-D inertia sine (offset 35 N, amplitude 25 N, period 26 s,
/// surge front).
inline std::vector<model::TrialDesign> RomeoSurgeDesigns() {
  using model::Dof;
  return {Segments("surge_front", Dof::kSurge, "surge-front",
                   {{10, 60}, {-12, 60}, {25, 45}, {-28, 45}, {45, 40}, {-50, 40}}),
          Segments("surge_rear", Dof::kSurge, "surge-rear",
                   {{-10, 60}, {14, 60}, {-25, 45}, {34, 45}, {-45, 40}, {60, 40}}),
          Segments("surge_all", Dof::kSurge, "horizontal-all-surge",
                   {{14, 60}, {-12, 60}, {34, 45}, {-31, 45}, {60, 40}, {-55, 40}}),
          Sine("surge_sine", Dof::kSurge, "surge-front", 35, 25, 26, 130)};
}

/// ROMEO heave (ref 000 Fig. 4, eq. 20): five trials with 0..4 ballast steps, up and down legs.
inline std::vector<model::TrialDesign> RomeoHeaveDesigns() {
  std::vector<model::TrialDesign> out;
  for (int i = 0; i < 5; ++i) {
    out.push_back(Segments("heave_" + std::to_string(i), model::Dof::kHeave, "vertical-all",
                           {{30, 40}, {-30, 40}, {60, 30}, {-60, 30}}, i));
  }
  return out;
}

/// ROMEO yaw: steady legs of both signs with the three yaw mappings (ref 000 Fig. 11,
/// Table III) and the §IV-D sine (offset −5, amplitude 4 N·m, period 24 s, yaw-fr-rl).
inline std::vector<model::TrialDesign> RomeoYawDesigns() {
  using model::Dof;
  const std::vector<std::pair<double, double>> legs = {{3, 30},  {-3, 30}, {6, 25},
                                                       {-6, 25}, {9, 25},  {-9, 25}};
  return {Segments("yaw_flrr", Dof::kYaw, "yaw-fl-rr", legs),
          Segments("yaw_frrl", Dof::kYaw, "yaw-fr-rl", legs),
          Segments("yaw_all", Dof::kYaw, "horizontal-all-yaw", legs),
          Sine("yaw_sine", Dof::kYaw, "yaw-fr-rl", -5, 4, 24, 96)};
}

/// VSOR yaw (ref 002 Table 4): sines with offset > amplitude (periods 8–30 s), and one trial
/// of reversed legs so that the installation coefficient of negative torque is excited.
inline std::vector<model::TrialDesign> VsorDesigns() {
  using model::Dof;
  return {Sine("yaw2_p30", Dof::kYaw, "yaw-ht1-ht7", 45, 30, 30, 90),
          Sine("yaw2_p16", Dof::kYaw, "yaw-ht1-ht7", 45, 30, 16, 64),
          Sine("yaw3_p8", Dof::kYaw, "yaw-ht1-ht7", 70, 45, 8, 48),
          Segments("yaw_reverse", Dof::kYaw, "yaw-ht1-ht7",
                   {{-20, 10}, {20, 10}, {-50, 10}, {50, 10}, {-80, 10}})};
}

/// A PRBS-like sequence of `n` legs of ±amplitude around `offset` with random durations in
/// [min_s, max_s] (ref 004 §5.2 used steps and PRBS), deterministic for `seed`.
inline std::vector<std::pair<double, double>> Prbs(double offset, double amplitude, int n,
                                                   double min_s, double max_s, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dur(min_s, max_s);
  std::vector<std::pair<double, double>> legs;
  for (int i = 0; i < n; ++i)
    legs.push_back({offset + (i % 2 == 0 ? amplitude : -amplitude), dur(rng)});
  return legs;
}

/// URIS trials: steps and PRBS per DOF (ref 004 §5.2).
inline std::vector<model::TrialDesign> UrisDesigns() {
  using model::Dof;
  return {Segments("surge_steps", Dof::kSurge, "surge-x", {{3, 20}, {-3, 20}, {6, 20}, {-6, 20}}),
          Segments("surge_prbs", Dof::kSurge, "surge-x", Prbs(0, 4, 16, 2, 8, 11)),
          Segments("yaw_steps", Dof::kYaw, "yaw-x", {{0.3, 10}, {-0.3, 10}, {0.6, 10}, {-0.6, 10}}),
          Segments("yaw_prbs", Dof::kYaw, "yaw-x", Prbs(0, 0.4, 16, 1, 5, 12)),
          Segments("pitch_steps", Dof::kPitch, "pitch-z",
                   {{0.15, 10}, {-0.15, 10}, {0.3, 10}, {-0.3, 10}}),
          Segments("pitch_prbs", Dof::kPitch, "pitch-z", Prbs(0, 0.2, 16, 1, 5, 13))};
}

}  // namespace uuvplan::ident::testing
