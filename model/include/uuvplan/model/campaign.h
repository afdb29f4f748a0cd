// A campaign (contract §Campaign): a vehicle, optionally a pool, and the trials in the order
// they were run, each with its log.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

enum class TrialUse { kFit, kValidate };
/// The name of a trial's use in the campaign file and in results: fit | validate.
inline constexpr EnumNames<TrialUse, 2> kTrialUseNames{
    {{{TrialUse::kFit, "fit"}, {TrialUse::kValidate, "validate"}}}};
inline std::string_view TrialUseName(TrialUse use) { return kTrialUseNames.Name(use); }

struct TrialEntry {
  std::string file;  ///< as written in the campaign (relative to it)
  std::string path;  ///< resolved path
  Dof dof = Dof::kSurge;
  std::string mapping;    ///< default mapping of the trial
  int ballast_steps = 0;  ///< known equal ballast steps added (heave weight tests)
  TrialUse use = TrialUse::kFit;
  double start = 0.0;  ///< start time on the campaign clock (s)
  bool has_start = false;
  TrialLog log;
};

struct Campaign {
  std::string path;
  std::string vehicle_file;
  Vehicle vehicle;
  std::optional<std::string> pool_file;
  std::optional<Pool> pool;
  std::vector<TrialEntry> trials;
};

}  // namespace uuvplan::model
