// The campaign file (contract §Campaign, docs/formats.md): the vehicle, the pool and the
// trials in the order they were run, each with its log; and its writer.
#include "uuvplan/io/campaign_yaml.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign_checks.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/new_directory.h"
#include "uuvplan/io/output_claim.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the campaign file

namespace {

// The trial's default mapping: named, or the vehicle's only mapping on the trial's DOF.
std::string TrialMapping(const MapValue& m, Dof dof, const Vehicle& vehicle) {
  std::vector<std::string> names;
  for (int i : vehicle.MappingsOf(dof)) names.push_back(vehicle.mappings[i].name);
  const Value v = m.Optional("mapping");
  if (v.absent() && names.size() == 1) return names.front();
  if (v.absent()) {
    m.self().Fail("missing required key 'mapping' (the vehicle has " +
                  std::to_string(names.size()) + " " + std::string(DofName(dof)) + " mappings" +
                  (names.empty() ? "" : ": " + Join(names)) + ")");
  }
  const std::string name = v.node().IsScalar() ? v.node().Scalar() : "";
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    v.Expected(names.empty()
                   ? "a mapping on " + std::string(DofName(dof)) + ", but the vehicle has none"
                   : "a " + std::string(DofName(dof)) + " mapping of the vehicle (" + Join(names) +
                         ")");
  }
  return name;
}

// A trial's log must hold its DOF's nominal force and a measured position or velocity.
void CheckTrialColumns(const TrialEntry& trial, const Value& where) {
  const std::string dof(DofName(trial.dof));
  const std::string need = " (a " + dof + " trial needs force_" + dof +
                           " or every thruster's cmd_<thruster>, and pos_" + dof + " or vel_" +
                           dof + ")";
  const auto has_sample = [](const std::vector<double>& c) {
    return std::any_of(c.begin(), c.end(), [](double x) { return !std::isnan(x); });
  };
  const auto& force = trial.log.force[Index(trial.dof)];
  if (force.empty()) where.Fail(trial.file + " has no 'force_" + dof + "' column" + need);
  if (!has_sample(force)) where.Fail(trial.file + ": column 'force_" + dof + "' has no value");
  const auto& pos = trial.log.position[Index(trial.dof)];
  const auto& vel = trial.log.velocity[Index(trial.dof)];
  if (pos.empty() && vel.empty()) {
    where.Fail(trial.file + " has no 'pos_" + dof + "' or 'vel_" + dof + "' column" + need);
  }
  if (!has_sample(pos) && !has_sample(vel)) {
    where.Fail(trial.file + ": columns 'pos_" + dof + "' and 'vel_" + dof + "' have no value");
  }
}

TrialEntry ParseTrial(const Value& v, const Vehicle& vehicle, const TrialEntry* previous) {
  const MapValue m(v, "a trial {file, dof, mapping, ballast_steps, use, start}");
  m.AllowOnly({"file", "dof", "mapping", "ballast_steps", "use", "start"});
  TrialEntry trial;
  const Value file = m.Required("file");
  trial.path = ReadableFile(file);
  trial.file = file.node().Scalar();
  trial.dof = DofValue(m.Required("dof"));
  trial.mapping = TrialMapping(m, trial.dof, vehicle);
  if (const Value x = m.Optional("ballast_steps"); !x.absent()) {
    trial.ballast_steps = WholeNonNegative(x);
  }
  if (const Value x = m.Optional("use"); !x.absent()) {
    trial.use =
        Choice(x, {TrialUseName(TrialUse::kFit), TrialUseName(TrialUse::kValidate)}, "a use") == 0
            ? TrialUse::kFit
            : TrialUse::kValidate;
  }
  if (const Value x = m.Optional("start"); !x.absent()) {
    trial.start = AnyNumber(x);
    trial.has_start = true;
    // Trials are listed in the order they were run (contract §Campaign).
    if (previous != nullptr && previous->has_start && trial.start < previous->start) {
      x.Expected("a start >= the previous trial's " + ShortestNumber(previous->start) +
                 " s (trials are listed in the order they were run)");
    }
  }
  trial.log = ReadTrialOf(trial.path, vehicle, trial.dof, trial.mapping);
  CheckTrialColumns(trial, v);
  return trial;
}

}  // namespace

// A campaign directory stands for its campaign.yaml.
Campaign ReadCampaign(const std::string& given) {
  const std::string path = std::filesystem::is_directory(given)
                               ? (std::filesystem::path(given) / "campaign.yaml").string()
                               : given;
  return Guarded(path, [&] {
    const MapValue m =
        LoadYamlMap(path, "a campaign (vehicle, pool, trials)", "a map of campaign keys");
    m.AllowOnly({"vehicle", "pool", "trials"});
    Campaign campaign;
    campaign.path = path;
    const Value vehicle = m.Required("vehicle");
    campaign.vehicle = ReadVehicle(ReadableFile(vehicle));
    campaign.vehicle_file = vehicle.node().Scalar();
    if (const Value pool = m.Optional("pool"); !pool.absent()) {
      campaign.pool = ReadPool(ReadableFile(pool));
      campaign.pool_file = pool.node().Scalar();
    }
    const Value trials = m.Required("trials");
    for (const Value& item : List(trials, "a list of trials {file, dof, mapping, ...}")) {
      const TrialEntry* previous = campaign.trials.empty() ? nullptr : &campaign.trials.back();
      campaign.trials.push_back(ParseTrial(item, campaign.vehicle, previous));
      CheckCampaignTrial(campaign, campaign.trials.size() - 1, item);
    }
    CheckCampaignWork(campaign, trials);
    return campaign;
  });
}

void WriteCampaignYaml(const std::string& path, const Campaign& campaign) {
  if (campaign.vehicle_file.empty()) {
    throw std::invalid_argument("WriteCampaignYaml " + path + ": no vehicle file");
  }
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "vehicle" << YAML::Value << campaign.vehicle_file;
  if (campaign.pool_file) out << YAML::Key << "pool" << YAML::Value << *campaign.pool_file;
  out << YAML::Key << "trials" << YAML::Value << YAML::BeginSeq;
  for (const TrialEntry& trial : campaign.trials) {
    if (trial.file.empty()) {
      throw std::invalid_argument("WriteCampaignYaml " + path + ": trial without file");
    }
    out << YAML::BeginMap;
    out << YAML::Key << "file" << YAML::Value << trial.file;
    out << YAML::Key << "dof" << YAML::Value << std::string(DofName(trial.dof));
    if (!trial.mapping.empty()) out << YAML::Key << "mapping" << YAML::Value << trial.mapping;
    out << YAML::Key << "ballast_steps" << YAML::Value << trial.ballast_steps;
    out << YAML::Key << "use" << YAML::Value << std::string(TrialUseName(trial.use));
    if (trial.has_start) out << YAML::Key << "start" << YAML::Value << ShortestNumber(trial.start);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  if (!out.good()) {
    throw std::invalid_argument("WriteCampaignYaml " + path + ": " + out.GetLastError());
  }
  WriteFileAtomically(path, std::string(out.c_str()) + "\n");
}

namespace {

namespace fs = std::filesystem;

void WriteCampaignFiles(const fs::path& tmp, const Campaign& campaign, const Vehicle& vehicle,
                        const std::vector<std::string>& trial_comments) {
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    const TrialEntry& e = campaign.trials[i];
    fs::create_directories((tmp / e.file).parent_path());
    WriteTrialLog((tmp / e.file).string(), e.log,
                  i < trial_comments.size() ? trial_comments[i] : "");
  }
  WriteVehicleYaml((tmp / "vehicle.yaml").string(), vehicle);
  WriteCampaignYaml((tmp / "campaign.yaml").string(), campaign);
}

}  // namespace

void CheckNewCampaignDirectory(const std::string& dir) { CheckNewDirectory(dir, "--out"); }

Campaign WriteCampaign(const std::string& dir, Campaign campaign, const Vehicle& vehicle,
                       const std::vector<std::string>& trial_comments) {
  const OutputClaim claim(dir);  // shared with the caller's (SimulateCampaign)
  CheckNewCampaignDirectory(dir);
  const fs::path out = DirectoryPath(dir);
  // Everything is written to a temporary sibling directory first, then renamed into place,
  // so a campaign is written whole or not at all.
  const fs::path tmp = NewSiblingDirectory(out, dir);
  std::error_code ec;
  campaign.path = (out / "campaign.yaml").string();
  campaign.vehicle_file = "vehicle.yaml";
  for (TrialEntry& e : campaign.trials) e.path = (out / e.file).string();
  try {
    fs::create_directories(tmp / "trials", ec);
    if (ec) throw InputError(dir, "cannot create directory: " + ec.message());
    WriteCampaignFiles(tmp, campaign, vehicle, trial_comments);
  } catch (...) {
    fs::remove_all(tmp, ec);  // ours alone
    throw;
  }
  MoveIntoPlace(tmp, out, dir, "a campaign");
  return campaign;
}

}  // namespace uuvplan::io
