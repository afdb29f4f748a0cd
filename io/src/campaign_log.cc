// A logged trial appended to its campaign (campaign_log.h).
#include "uuvplan/io/campaign_log.h"

#include <algorithm>
#include <filesystem>

#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

namespace fs = std::filesystem;

namespace {

// Throws unless `id` names a new trial file of the campaign.
void CheckNewId(const model::Campaign& campaign, const std::string& id, const std::string& file,
                const fs::path& dir) {
  if (id.empty() || id.find_first_of("/\\") != std::string::npos || id[0] == '.') {
    throw model::InputError("--trial " + id,
                            "expected a trial id without '/' (it names "
                            "trials/<id>.csv)");
  }
  for (const model::TrialEntry& t : campaign.trials) {
    if (t.file == file || fs::path(t.path).lexically_normal() == (dir / file).lexically_normal()) {
      throw model::InputError(campaign.path + ": trials",
                              "trial " + id + " is already logged (" + file + ")");
    }
  }
  if (fs::exists(dir / file)) {
    throw model::InputError((dir / file).string(),
                            "exists but is not in the campaign; choose another --trial id");
  }
}

// The log, read through the vehicle (ReadTrialOf); throws, naming the input CSV or the flag,
// unless it can be a trial of `dof` in `mapping`.
model::TrialLog CheckedLog(const model::Vehicle& vehicle, const LoggedTrial& trial) {
  std::vector<std::string> names;
  for (const model::ThrustMapping& m : vehicle.mappings) {
    if (m.dof == trial.dof) names.push_back(m.name);
  }
  const std::string dof(model::DofName(trial.dof));
  if (!trial.mapping.empty() &&
      std::find(names.begin(), names.end(), trial.mapping) == names.end()) {
    throw model::InputError("--mapping " + trial.mapping, "expected a mapping of the vehicle on " +
                                                              dof + ": " + model::Join(names));
  }
  if (trial.mapping.empty() && names.size() != 1) {
    throw model::InputError("--mapping", "required: the vehicle has " +
                                             std::to_string(names.size()) + " mappings on " + dof +
                                             " (" + model::Join(names) + ")");
  }
  const std::string mapping = trial.mapping.empty() ? names.front() : trial.mapping;
  model::TrialLog log = ReadTrialOf(trial.csv, vehicle, trial.dof, mapping);
  if (!log.HasForce(trial.dof)) {
    throw model::InputError(trial.csv, "no force_" + dof +
                                           " column: expected the nominal force "
                                           "of the trial's DOF (--dof " +
                                           dof + ") or every thruster's cmd_<thruster>");
  }
  if (!log.HasPosition(trial.dof) && !log.HasVelocity(trial.dof)) {
    throw model::InputError(trial.csv, "no pos_" + dof + " or vel_" + dof + " column");
  }
  return log;
}

}  // namespace

model::Campaign AppendLoggedTrial(const std::string& campaign_path, const LoggedTrial& trial,
                                  const LogCheck& check) {
  model::Campaign campaign = ReadCampaign(campaign_path);
  const fs::path yaml = campaign.path;
  const fs::path dir = yaml.parent_path().empty() ? fs::path(".") : yaml.parent_path();
  const std::string file = "trials/" + trial.id + ".csv";
  CheckNewId(campaign, trial.id, file, dir);
  const model::TrialLog log = CheckedLog(campaign.vehicle, trial);
  if (check) check(log);
  model::TrialEntry entry;
  entry.file = file;
  entry.dof = trial.dof;
  entry.mapping = trial.mapping;
  entry.ballast_steps = trial.ballast_steps;
  entry.use = trial.use;
  entry.has_start = trial.start.has_value();
  entry.start = trial.start.value_or(0.0);
  campaign.trials.push_back(entry);
  const std::string text = ReadFileText(trial.csv);  // the input is only read
  std::error_code ec;
  fs::create_directories(dir / "trials", ec);
  WriteFileAtomically((dir / file).string(), text);
  // The new campaign.yaml beside the old one, read back whole, then renamed over it.
  const fs::path next = dir / ("." + yaml.filename().string() + ".log-" + trial.id);
  try {
    WriteCampaignYaml(next.string(), campaign);
    ReadCampaign(next.string());
  } catch (const model::InputError& e) {
    fs::remove(next, ec);
    fs::remove(dir / file, ec);
    // The fault as it would read in campaign.yaml with the trial logged (not the scratch file).
    std::string message = e.what();
    for (std::size_t at; (at = message.find(next.string())) != std::string::npos;) {
      message.replace(at, next.string().size(), yaml.string());
    }
    throw model::InputError(trial.csv,
                            "not logged (" + yaml.string() + " is unchanged): with it, " + message);
  } catch (...) {
    fs::remove(next, ec);
    fs::remove(dir / file, ec);
    throw;
  }
  fs::rename(next, yaml, ec);
  if (ec) {
    fs::remove(next, ec);
    fs::remove(dir / file, ec);
    throw model::InputError(yaml.string(), "cannot replace it: " + ec.message());
  }
  return ReadCampaign(yaml.string());
}

}  // namespace uuvplan::io
