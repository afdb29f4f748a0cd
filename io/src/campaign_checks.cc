#include "campaign_checks.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "uuvplan/io/plausibility.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/work_limits.h"

namespace uuvplan::io {

using model::Significant;

namespace {

// The same file, however it is written (a symbolic link, "./", "a/../").
std::string Identity(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

// Whether two files hold the same bytes (a log copied under another name).
bool SameContent(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  if (std::filesystem::file_size(a, ea) != std::filesystem::file_size(b, eb) || ea || eb) {
    return false;
  }
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  std::vector<char> ba(1 << 16), bb(1 << 16);
  while (fa && fb) {
    fa.read(ba.data(), ba.size());
    fb.read(bb.data(), bb.size());
    if (fa.gcount() != fb.gcount() ||
        !std::equal(ba.begin(), ba.begin() + fa.gcount(), bb.begin())) {
      return false;
    }
  }
  return fa.eof() && fb.eof();
}

void CheckNotRepeated(const model::Campaign& campaign, std::size_t index, const Value& item) {
  const std::string self = Identity(campaign.trials[index].path);
  for (std::size_t j = 0; j < index; ++j) {
    const bool same_file = Identity(campaign.trials[j].path) == self;
    if (!same_file && !SameContent(campaign.trials[j].path, campaign.trials[index].path)) continue;
    Implausible(Place(item.file(), item.line(), item.KeyPath("file")),
                std::string(same_file ? "the same log as" : "a copy of the log of") + " trials[" +
                    std::to_string(j) + "] ('" + campaign.trials[j].file +
                    "'): a trial fitted and validated on the same data, or counted twice, "
                    "makes the σ and the validation meaningless");
    return;
  }
}

// The median interval between the rows where `column` has a sample, from evenly spread
// intervals (util/median.h); NaN for fewer than 20 intervals (a hand-written log of a few rows
// says little about its sampling).
double MedianInterval(const std::vector<double>& t, const std::vector<double>& column) {
  const std::size_t n = std::min(t.size(), column.size());
  const auto values = static_cast<std::size_t>(
      std::count_if(column.begin(), column.begin() + static_cast<std::ptrdiff_t>(n),
                    [](double v) { return !std::isnan(v); }));
  const std::size_t stride = model::SpreadStride(values);
  std::vector<double> dt;
  dt.reserve(values / stride + 1);
  double last = std::nan("");
  std::size_t interval = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(column[i])) continue;
    if (!std::isnan(last) && interval++ % stride == 0) dt.push_back(t[i] - last);
    last = t[i];
  }
  return dt.size() < 20 ? std::nan("") : model::Median(std::move(dt));
}

// The sampling of the trial's own sensor against the rate the vehicle declares for it: within a
// factor 4 (a log may merge several streams; a ratio of 1000 is a time column in ms).
void CheckSampling(const model::Campaign& campaign, const model::TrialEntry& trial,
                   const Value& item) {
  const Place at(item.file(), item.line(), item.KeyPath("file"));
  const auto& log = trial.log;
  const double span = log.t.back() - log.t.front();
  if (span > plausible::kDuration.upper) {
    Implausible(at, trial.file + ": column 't' spans " + Significant(span, 4) +
                        " s, expected a trial of at most a day (is t in ms?)");
  }
  const auto sensors = campaign.vehicle.sensors.find(trial.dof);
  if (sensors == campaign.vehicle.sensors.end()) return;
  const int d = model::Index(trial.dof);
  const bool velocity = sensors->second.velocity && !log.velocity[d].empty();
  const std::optional<model::SensorSpec>& spec =
      velocity ? sensors->second.velocity : sensors->second.position;
  const std::vector<double>& column = velocity ? log.velocity[d] : log.position[d];
  if (!spec || column.empty()) return;
  const double ratio = MedianInterval(log.t, column) * spec->rate_hz;
  if (std::isnan(ratio) || (ratio > 0.25 && ratio < 4)) return;
  const std::string name =
      std::string(velocity ? "vel_" : "pos_") + std::string(DofName(trial.dof));
  if (ratio > 300 && ratio < 3000) {
    Implausible(at, trial.file + ": column 't' looks like milliseconds: '" + name +
                        "' is sampled every " + Significant(ratio / spec->rate_hz, 4) +
                        " 'seconds', the vehicle declares " + Significant(spec->rate_hz, 4) +
                        " Hz (t must be in s)");
    return;
  }
  Implausible(at, trial.file + ": '" + name + "' is sampled every " +
                      Significant(ratio / spec->rate_hz, 4) + " s, which does not fit the " +
                      Significant(spec->rate_hz, 4) + " Hz the vehicle declares (sensors." +
                      std::string(DofName(trial.dof)) + ")");
}

// Every logged force or torque within a thousand weights (× the largest size, for a torque).
void CheckForces(const model::Vehicle& vehicle, const model::TrialEntry& trial, const Value& item) {
  const double size = *std::max_element(vehicle.size.begin(), vehicle.size.end());
  for (model::Dof dof : model::kAllDofs) {
    const std::vector<double>& force = trial.log.force[model::Index(dof)];
    const double scale =
        plausible::kGravity * vehicle.mass * (model::IsRotational(dof) ? size : 1.0);
    for (std::size_t i = 0; i < force.size(); ++i) {
      if (plausible::kForceRatio.Holds(std::abs(force[i]) / scale) || std::isnan(force[i])) {
        continue;
      }
      const std::string unit(model::ForceUnit(dof));
      Implausible(Place(item.file(), item.line(), item.KeyPath("file")),
                  trial.file + ": column 'force_" + std::string(model::DofName(dof)) +
                      "' at t = " + model::ShortestNumber(trial.log.t[i]) + " s (data row " +
                      std::to_string(i + 1) + "): expected at most " +
                      Significant(plausible::kForceRatio.upper * scale, 3) + " " + unit + " (" +
                      Significant(plausible::kForceRatio.upper, 4) + " × the vehicle's weight, " +
                      Significant(scale, 3) + " " + unit +
                      (model::IsRotational(dof) ? " × its largest size" : "") + "), got " +
                      model::ShortestNumber(force[i]) + " " + unit);
      break;
    }
  }
}

}  // namespace

void CheckCampaignTrial(const model::Campaign& campaign, std::size_t index, const Value& item) {
  CheckNotRepeated(campaign, index, item);
  CheckSampling(campaign, campaign.trials[index], item);
  CheckForces(campaign.vehicle, campaign.trials[index], item);
}

void CheckCampaignWork(const model::Campaign& campaign, const Value& trials) {
  double rows = 0;
  for (const model::TrialEntry& trial : campaign.trials)
    rows += static_cast<double>(trial.log.size());
  if (rows > model::limits::kMaxCampaignRows) {
    trials.Fail(std::to_string(campaign.trials.size()) + " trials hold " + Significant(rows, 3) +
                " rows, more than the " + Significant(model::limits::kMaxCampaignRows, 3) +
                " a campaign may hold in memory: split it into campaigns");
  }
}

}  // namespace uuvplan::io
