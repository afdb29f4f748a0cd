// Seeded virtual campaigns of the coupled horizontal model: the ASV of cases/asv with a random
// coupling truth, run through ref 003 Table I's combined modes in the virtual pool. Shared by
// tests/ident/joint_ls_test.cc and the full-size validation program
// tests/validation/coupled_validation.cc.
#pragma once

#include <cstdint>
#include <vector>

#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::testing {

/// `base` (cases/asv/truth.yaml) with the horizontal parameters drawn from `seed`: m_u, m_v, m_r
/// uniform in the vehicle's a priori inertia bounds (added mass 5–100%), so the Coriolis coupling
/// m_v·v·r, −m_u·u·r, (m_u − m_v)·u·v takes any sign and size a vehicle may have; k and kq the base
/// values times a factor log-uniform in [0.5, 2]; bias uniform within ±2% of 300 N (±2% of
/// 300 N·m in yaw), a pool's tether or current.
model::Truth RandomCoupledTruth(const model::Truth& base, std::uint64_t seed);

/// Three zero-mean sine trials of `duration_s` (surge+yaw, sway+yaw, surge+sway+yaw) at
/// incommensurate frequencies, within the ASV's thrust (at most 88 N of 120 N per thruster).
std::vector<model::CombinedTrialDesign> CombinedModeDesigns(double duration_s);

/// The logs of `designs` run on `truth`, trial i from model::StreamSeed(seed, i).
std::vector<model::TrialLog> RunCoupledCampaign(
    const model::Truth& truth, const std::vector<model::CombinedTrialDesign>& designs,
    std::uint64_t seed);

}  // namespace uuvplan::testing
