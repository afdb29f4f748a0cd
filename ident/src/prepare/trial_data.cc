#include "uuvplan/ident/prepare/trial_data.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "options_check.h"
#include "uuvplan/ident/prepare/other_motion.h"
#include "uuvplan/ident/prepare/start_at_rest.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

using model::Dof;
using model::Index;

// A log column `y` at `times` as a signal: the rows with a value at or after t = 0 (the first
// force row, log time `offset`), times shifted there, compacted in the vectors given (moved
// from a log the caller gave up, a million-row log is not held twice while it is read; else
// copies).
Signal KeptSamples(std::vector<double> times, std::vector<double> y, double offset) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (std::isnan(y[i]) || times[i] < offset) continue;  // before t = 0: no force logged
    times[k] = times[i] - offset;
    y[k++] = y[i];
  }
  times.resize(k);
  y.resize(k);
  if (2 * k < y.capacity()) {  // a sparse column (a 10 Hz sensor in a 100 Hz log)
    times.shrink_to_fit();
    y.shrink_to_fit();
  }
  Signal s;
  s.t = std::move(times);
  s.t.CompactUniform(offset);  // a log on a uniform decimal clock: its times not stored
  s.y = std::move(y);
  return s;
}

// The measurement columns of a trial's log, as signals (KeptSamples), copied from the log or taken
// from it when the caller gives it up (`owned`, the same log): the times are moved into the
// last column read that needs them.
class LogColumns {
 public:
  /// `dof`: the trial's own (the only DOF whose position is read; every DOF's velocity is).
  LogColumns(const model::TrialLog& log, model::TrialLog* owned, Dof dof, double offset)
      : log_(log), owned_(owned), offset_(offset) {
    times_users_ = log.HasPosition(dof) ? 1 : 0;
    for (Dof d : model::kAllDofs) times_users_ += log.HasVelocity(d) ? 1 : 0;
  }
  Signal Read(model::LogColumnKind columns, Dof d) {
    const std::vector<double>& col = (log_.*columns)[Index(d)];
    if (col.empty()) return Signal{};
    const bool last = --times_users_ == 0;
    if (!owned_) return KeptSamples(log_.t, col, offset_);
    return KeptSamples(last ? std::move(owned_->t) : owned_->t,
                       std::move((owned_->*columns)[Index(d)]), offset_);
  }

 private:
  const model::TrialLog& log_;
  model::TrialLog* owned_;
  double offset_;
  int times_users_ = 0;
};

double MedianRate(const Signal& s) {
  if (s.size() < 2) return 1.0;
  const double h = MedianStep(s.t, 0, s.size());
  return h > 0 ? 1.0 / h : 1.0;
}

}  // namespace

bool TrialDataOptions::IsValid(std::string* error) const {
  const bool window_ok =
      sg_window == 0 || (sg_window > 0 && sg_window % 2 == 1 && sg_window >= sg_order + 2);
  return Require(sg_order >= 1 && sg_order <= 8 && window_ok,
                 "TrialDataOptions: sg_order in [1, 8]; sg_window 0 (auto) or odd >= order + 2",
                 error) &&
         Require(gap_factor > 1 && force_tolerance >= 0,
                 "TrialDataOptions: gap_factor > 1 and force_tolerance >= 0", error) &&
         outliers.IsValid(error);
}

LogAuxVelocities::LogAuxVelocities(Dof own, std::array<Signal, model::kNumDofs> velocities)
    : own_(own), velocities_(std::move(velocities)) {}

// Linear interpolation as Interpolate(), from the interval found last by this thread for this
// log (a simulation asks at increasing times: one or two comparisons instead of a binary search;
// the value does not depend on the hint). thread_local: diagnosis fits candidates in parallel on
// the same trials.
void LogAuxVelocities::At(double t, std::array<double, model::kNumDofs>* v) const {
  thread_local const LogAuxVelocities* owner = nullptr;
  thread_local std::array<std::size_t, model::kNumDofs> hint{};
  if (owner != this) {
    owner = this;
    hint.fill(0);
  }
  for (int d = 0; d < model::kNumDofs; ++d) {
    if (d == Index(own_)) continue;
    const Signal& s = velocities_[d];
    if (s.empty()) {
      (*v)[d] = 0.0;
      continue;
    }
    std::size_t& i = hint[d];
    if (t <= s.t.front() || t >= s.t.back()) {
      (*v)[d] = t <= s.t.front() ? s.y.front() : s.y.back();
      continue;
    }
    if (i + 1 >= s.t.size() || s.t[i] > t) i = 0;
    if (!(t < s.t[i + 1])) {  // the interval of Interpolate: t[i] <= t < t[i + 1]
      if (i + 2 < s.t.size() && t < s.t[i + 2]) {
        ++i;
      } else {
        i = static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin()) - 1;
      }
    }
    const double w = (t - s.t[i]) / (s.t[i + 1] - s.t[i]);
    (*v)[d] = s.y[i] + w * (s.y[i + 1] - s.y[i]);
  }
}

namespace {

// The longest step between force rows, or from the last one to the trial's end (a force log
// that stops before the measurements), kept when it is longer than 1 s and 10 median steps
// (TrialData::force_gap_t0).
void FindForceGap(TrialData* d) {
  const SharedTimes& t = d->force_t;
  if (t.size() < 3) return;
  // The median row step; of a uniform clock, any of its steps (they differ by a rounding).
  double median = t[1] - t[0];
  if (!t.uniform()) {
    std::vector<double> steps(t.size() - 1);  // one copy (a second was the prep's peak)
    for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
    median = model::Median(std::move(steps));  // and the copy freed
  }
  double t0 = 0.0, t1 = 0.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (t[i + 1] - t[i] > t1 - t0) t0 = t[i], t1 = t[i + 1];
  }
  if (d->duration - t.back() > t1 - t0) t0 = t.back(), t1 = d->duration;
  if (t1 - t0 > std::max(1.0, 10.0 * median)) d->force_gap_t0 = t0, d->force_gap_t1 = t1;
}

// The logged force of the DOF and the mapping in force on each row (zero-order hold,
// notes/pitfalls.md), as the trial's excitation; the command steps (force_jumps).
void ReadForce(const model::TrialEntry& e, const model::Vehicle& vehicle, const std::string& where,
               TrialData* d) {
  const model::TrialLog& log = e.log;
  const std::string dof_name(model::DofName(d->dof));
  if (!log.HasForce(d->dof)) {
    throw model::InputError(
        where, "no column force_" + dof_name + ": expected the nominal force of the trial's DOF");
  }
  const int default_mapping = e.mapping.empty() ? -1 : vehicle.MappingIndex(e.mapping);
  if (!e.mapping.empty() && default_mapping < 0) {
    throw model::InputError(
        where, "mapping '" + e.mapping + "' is not a mapping of vehicle '" + vehicle.name + "'");
  }
  std::vector<int> name_to_vehicle(log.mapping_names.size(), -1);
  for (std::size_t i = 0; i < log.mapping_names.size(); ++i) {
    name_to_vehicle[i] = vehicle.MappingIndex(log.mapping_names[i]);
    if (name_to_vehicle[i] < 0) {
      throw model::InputError(where, "column 'mapping': '" + log.mapping_names[i] +
                                         "' is not a mapping of vehicle '" + vehicle.name + "'");
    }
  }
  const auto& fcol = log.force[Index(d->dof)];
  std::vector<char> used(vehicle.mappings.size(), 0);
  // Sized once (grown by doubling they held up to twice their rows for the whole identification).
  const auto rows = static_cast<std::size_t>(
      std::count_if(fcol.begin(), fcol.end(), [](double f) { return !std::isnan(f); }));
  std::vector<double> force_t;
  // A force on every row: its times are the log's, held as their clock where they are one (no
  // vector of them on the way).
  const bool every_row = rows == fcol.size();
  if (!every_row) force_t.reserve(rows);
  d->force.reserve(rows);
  d->mapping.reserve(rows);
  for (std::size_t i = 0; i < fcol.size(); ++i) {
    if (std::isnan(fcol[i])) continue;
    int m = default_mapping;
    if (!log.mapping.empty() && log.mapping[i] >= 0) m = name_to_vehicle[log.mapping[i]];
    if (!every_row) force_t.push_back(log.t[i] - d->time_offset);
    d->force.push_back(fcol[i]);
    d->mapping.push_back(m);
    if (m >= 0) used[m] = 1;
  }
  if (every_row) {
    d->force_t = SharedTimes::Of(
        rows, [&](std::size_t i) { return log.t[i] - d->time_offset; }, d->time_offset);
  } else {
    d->force_t = std::move(force_t);
    d->force_t.CompactUniform(d->time_offset);
  }
  if (d->force.empty()) {
    throw model::InputError(where, "column force_" + dof_name +
                                       " has no value (all cells empty or NaN): expected the "
                                       "nominal force of every command row");
  }
  for (std::size_t m = 0; m < used.size(); ++m) {
    if (used[m]) d->mappings_used.push_back(vehicle.mappings[m].name);
  }
  FindForceGap(d);
  // The rows are final here: the hold reads them in place (d's arrays move with it).
  d->input = model::MakeHeldExcitationOver(d->force_t.view(), d->force, d->mapping, d->duration);
  const auto [fmin, fmax] = std::minmax_element(d->force.begin(), d->force.end());
  const double range = *fmax - *fmin;
  for (std::size_t i = 1; i < d->force.size(); ++i) {
    if (d->mapping[i] != d->mapping[i - 1] ||
        std::abs(d->force[i] - d->force[i - 1]) > 0.05 * range) {
      d->force_jumps.push_back(d->force_t[i]);
    }
  }
}

// Headings may be wrapped to (−π, π] (logs built in memory, e.g. by the virtual pool, are not
// unwrapped by a reader): undo every step larger than π. Idempotent.
void UnwrapHeading(Signal* pos, TrialData* d) {
  double offset = 0.0;
  int jumps = 0;
  for (std::size_t i = 1; i < pos->size(); ++i) {
    const double step = pos->y[i] + offset - pos->y[i - 1];
    if (std::abs(step) > M_PI) {
      offset -= 2.0 * M_PI * std::round(step / (2.0 * M_PI));
      ++jumps;
    }
    pos->y[i] += offset;
  }
  if (jumps > 0)
    d->notes.push_back({TrialNoteKind::kHeadingUnwrapped, {}, {static_cast<double>(jumps)}});
}

// The share of a record's samples in motion (not exactly 0) that repeat the previous value
// exactly: a sensor logged faster than it updates. tartan-pool-2022's DVL: 22–78% per chunk;
// its gyro and bluerov-yaw-2016's: 0% and 2–10% (float32 rates); a simulated sensor: 0%.
double HeldFraction(const Signal& s) {
  std::size_t moving = 0, repeats = 0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (s.y[i] == 0.0) continue;
    ++moving;
    repeats += s.y[i] == s.y[i - 1];
  }
  return moving == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(moving);
}
constexpr double kHeldRecord = 0.15;  // between the gyros' ≤ 10% and the DVL's ≥ 22%

// One measurement with its outliers excluded (reported in `outliers`), and its noise σ:
// `declared` when positive, else estimated from the differences (`estimated`).
struct CleanOutput {
  std::vector<Outlier>* outliers;
  double* sigma;
  double* estimated;
};

Signal Clean(Signal s, double declared, const char* what, const TrialDataOptions& o,
             const CleanOutput& out, TrialData* d) {
  if (s.size() < 3) return Signal{};
  if (o.remove_outliers) {
    // Command steps (and the start, where the trial's force is switched on) put a kink in
    // the motion: predictions do not reach across them, and velocities, whose slope jumps
    // there (a lagged thruster rounds the kink over its lag), are not tested next to them.
    CommandSteps steps{d->force_jumps, 0.0};
    steps.t.push_back(0.0);
    std::sort(steps.t.begin(), steps.t.end());
    const double h = (s.t.back() - s.t.front()) / std::max<std::size_t>(1, s.size() - 1);
    OutlierOptions test = o.outliers;
    if (std::string(what) == "velocity") {
      steps.protect_radius = (o.outliers.half_window + 1) * h;
      // A held record is a staircase whose edges no polynomial predicts: the plain quadratic
      // test, which excludes them (tartan's DVL; docs/identification.md §7). A smooth record
      // keeps the truncation allowance, as positions do.
      if (HeldFraction(s) > kHeldRecord) test.truncation_allowance = 0.0;
    }
    *out.outliers = DetectOutliers(s, test, declared, &steps);
    if (!out.outliers->empty()) {
      d->notes.push_back(
          {TrialNoteKind::kOutliersExcluded,
           {what},
           {static_cast<double>(out.outliers->size()), out.outliers->front().t + d->time_offset,
            out.outliers->front().residual}});
      s = RemoveSamples(s, *out.outliers);
    }
  }
  *out.estimated = NoiseSigmaFromDifferences(s);
  *out.sigma = declared > 0 ? declared : *out.estimated;
  if (declared > 0 && *out.estimated > 0 && (*out.estimated > 3 * declared)) {
    d->notes.push_back({TrialNoteKind::kNoiseAboveDeclared, {what}, {*out.estimated, declared}});
  }
  return s;
}

// The DOF's position and velocity samples as logged (NaN rows and rows before t = 0 left out),
// and whether the log has their columns at all.
struct Measurements {
  Signal position, velocity;
  bool position_column = false, velocity_column = false;
};

Measurements ReadMeasurements(const model::TrialLog& log, LogColumns* columns,
                              const std::string& where, TrialData* d) {
  const Dof dof = d->dof;
  const std::string dof_name(model::DofName(dof));
  Measurements m;
  m.position_column = log.HasPosition(dof);
  m.velocity_column = log.HasVelocity(dof);
  Signal& pos = m.position;
  pos = columns->Read(&model::TrialLog::position, dof);
  if (model::IsRotational(dof)) UnwrapHeading(&pos, d);
  m.velocity = columns->Read(&model::TrialLog::velocity, dof);
  if (pos.size() < 3 && m.velocity.size() < 3) {
    const bool any_column = m.position_column || m.velocity_column;
    throw model::InputError(where, any_column
                                       ? "columns pos_" + dof_name + "/vel_" + dof_name +
                                             " have fewer than 3 samples (all NaN?): expected "
                                             "measurements of the trial's DOF"
                                       : "no column pos_" + dof_name + " or vel_" + dof_name +
                                             ": expected a measurement of the trial's DOF");
  }
  return m;
}

// The DOF's position and velocity samples, cleaned; unusable columns and gaps reported.
void CleanMeasurements(Measurements m, const model::Vehicle& vehicle, const TrialDataOptions& o,
                       TrialData* d) {
  const Dof dof = d->dof;
  const std::string dof_name(model::DofName(dof));
  const auto sensors = vehicle.sensors.find(dof);
  const model::DofSensors* spec = sensors == vehicle.sensors.end() ? nullptr : &sensors->second;
  d->position = Clean(std::move(m.position), spec && spec->position ? spec->position->sigma : -1.0,
                      "position", o,
                      {&d->position_outliers, &d->position_sigma, &d->position_sigma_estimated}, d);
  d->velocity = Clean(std::move(m.velocity), spec && spec->velocity ? spec->velocity->sigma : -1.0,
                      "velocity", o,
                      {&d->velocity_outliers, &d->velocity_sigma, &d->velocity_sigma_estimated}, d);
  // A column that is present but empty (all NaN) is not used; the other measurement carries
  // the trial, and the caller is told which column was ignored.
  if (m.position_column && !d->has_position()) d->unusable_columns.push_back("pos_" + dof_name);
  if (m.velocity_column && !d->has_velocity()) d->unusable_columns.push_back("vel_" + dof_name);
  for (const std::string& c : d->unusable_columns) {
    d->notes.push_back({TrialNoteKind::kUnusableColumn, {c}, {}});
  }
  const Signal& main = d->has_velocity() ? d->velocity : d->position;
  d->gaps = FindGaps(main.t, o.gap_factor);
  if (!d->gaps.empty()) {
    double longest = 0.0;
    for (const Gap& g : d->gaps) longest = std::max(longest, g.t1 - g.t0);
    const char* signal = d->has_velocity() ? "velocity" : "position";
    d->notes.push_back(
        {TrialNoteKind::kGaps, {signal}, {static_cast<double>(d->gaps.size()), longest}});
  }
}

// Samples in the longest stretch of `t` without a gap (the filter does not cross gaps).
int LongestRun(model::TimesView t, const std::vector<Gap>& gaps) {
  std::ptrdiff_t longest = 0;
  auto begin = t.begin();
  for (const Gap& g : gaps) {  // in time order (FindGaps)
    const auto next = std::lower_bound(begin, t.end(), g.t1);
    longest = std::max(longest, next - begin);
    begin = next;
  }
  return static_cast<int>(std::max(longest, t.end() - begin));
}

// The filter's window: the option's, else the rate's (SavitzkyGolayWindow) shortened to the
// longest stretch without a gap where that holds the filter's order + 2 points, so that the
// window recorded (TrialData::sg_window, whose half span sets the rows the estimators keep)
// is the one the filter used. A window set longer than every stretch cannot be honoured (the
// filter would fit one polynomial to the whole stretch, and the estimators would drop every
// row as too near its ends): an input error. (A stretch too short for any window leaves the
// fits without rows: a failed fit that says so.)
int FilterWindow(const TrialDataOptions& o, const Signal& main, const std::string& what,
                 double time_scale, const std::string& where, const std::vector<Gap>& gaps) {
  const int run = LongestRun(main.t, gaps);
  const int fits = run % 2 == 1 ? run : run - 1;  // the longest odd window the data holds
  if (o.sg_window > run) {
    throw model::InputError(
        where, "velocity filter window (--sg-window) of " + std::to_string(o.sg_window) +
                   " points, but the longest stretch of " + what + " samples without a gap has " +
                   std::to_string(run) + ": expected at most " + std::to_string(fits));
  }
  if (o.sg_window > 0) return o.sg_window;
  const int rate_window = SavitzkyGolayWindow(MedianRate(main), time_scale);
  return fits >= o.sg_order + 2 ? std::min(rate_window, fits) : rate_window;
}

// Velocity estimate (ref 000 §IV-D: Savitzky–Golay, 4th order, 21–41 points): the smoothed
// measured velocity, or the derivative of the smoothed position.
void EstimateVelocity(const TrialDataOptions& o, const std::string& where, TrialData* d) {
  const double time_scale = InputTimeScale(d->force_t, d->force);
  SavitzkyGolayOptions sg;
  sg.order = o.sg_order;
  sg.gap_factor = o.gap_factor;
  if (d->has_velocity()) {
    sg.window = FilterWindow(o, d->velocity, "velocity", time_scale, where, d->gaps);
    d->velocity_estimate = SavitzkyGolay(d->velocity, sg);
    // The smoothed velocity is the estimate (derivative = acceleration, unused here).
    d->velocity_estimate.second_derivative = {};
    d->velocity_from_position = false;
    d->initial_velocity = d->velocity_estimate.value.front();
    if (d->has_position()) {
      SavitzkyGolayOptions sp = sg;
      sp.window = ChosenWindow(o.sg_window, MedianRate(d->position), time_scale);
      // In double (ForEachSmoothed): a stored SmoothedSignal rounds its values to float, 6e-8 of
      // a position's size (0.3 m on UTM coordinates).
      d->initial_position = std::nan("");
      ForEachSmoothed(d->position, sp, [d](const SmoothedSample& p) {
        if (p.i == 0) d->initial_position = p.value;
      });
    } else {
      d->initial_position = std::nan("");
    }
  } else {
    sg.window = FilterWindow(o, d->position, "position", time_scale, where, d->gaps);
    // The estimate is the position's filter one derivative up; the smoothed positions
    // themselves are not kept.
    d->velocity_estimate = SavitzkyGolayRate(d->position, sg, &d->initial_position);
    const double v0 = d->velocity_estimate.value.front();
    d->initial_velocity = std::isfinite(v0) ? v0 : 0.0;
    d->position_noise_ar1 = PositionNoiseAr1(d->position, sg, d->position_sigma);
    d->velocity_from_position = true;
  }
  d->sg_window = sg.window;
  d->sg_options = sg;
  const TrialStart start = JudgeStart(*d);
  d->starts_at_rest = start.at_rest;
  if (d->starts_at_rest) {
    d->initial_velocity = 0.0;
  } else if (std::isfinite(start.velocity)) {
    d->initial_velocity = start.velocity;
  }
}

// Other DOFs' velocities (coupling).
void ReadAuxVelocities(LogColumns* columns, TrialData* d) {
  std::array<Signal, model::kNumDofs> aux;
  bool any_aux = false;
  for (Dof other : model::kAllDofs) {
    if (other == d->dof) continue;
    aux[Index(other)] = columns->Read(&model::TrialLog::velocity, other);
    any_aux = any_aux || !aux[Index(other)].empty();
  }
  if (any_aux) d->aux = std::make_unique<LogAuxVelocities>(d->dof, std::move(aux));
}

// The log time of the trial's t = 0: its first row with a force value. The zero-order hold
// starts there; measurements logged before it (tartan chunk_00: 4.6 s of navigation before
// the first wrench row, a recorder backlog) had no logged force, and holding the first
// command back over them would invent it: they are not used, and a note says so. A log
// without a force value starts at its first row (ReadForce then names the empty column).
double FirstForceTime(const model::TrialLog& log, Dof dof, TrialData* d) {
  const auto& f = log.force[Index(dof)];
  std::size_t i = 0;
  while (i < f.size() && std::isnan(f[i])) ++i;
  if (i == 0 || i >= f.size()) return log.t.front();
  d->notes.push_back({TrialNoteKind::kBeforeFirstForce, {}, {log.t[i] - log.t.front(), log.t[i]}});
  return log.t[i];
}

}  // namespace

TrialData PrepareTrial(const model::TrialEntry& e, int index, const model::Vehicle& vehicle,
                       const TrialDataOptions& o, model::TrialLog* given_up) {
  const model::TrialLog& log = e.log;
  const std::string where = e.path.empty() ? e.file : e.path;
  TrialData d;
  d.index = index;
  d.name = e.file;
  d.path = e.path;
  d.dof = e.dof;
  d.use = e.use;
  d.ballast_steps = e.ballast_steps;
  if (log.t.empty()) throw model::InputError(where, "no data rows");
  d.time_offset = FirstForceTime(log, e.dof, &d);
  for (TrialNote& n : OtherDofMotion(log, e.dof, d.time_offset)) d.notes.push_back(std::move(n));
  d.start_time = e.start + d.time_offset;
  d.duration = log.t.back() - d.time_offset;
  ReadForce(e, vehicle, where, &d);
  LogColumns columns(log, given_up, e.dof, d.time_offset);
  Measurements m = ReadMeasurements(log, &columns, where, &d);
  ReadAuxVelocities(&columns, &d);
  std::vector<std::string> log_notes = log.notes;
  if (given_up) *given_up = model::TrialLog{};  // `log` is gone from here on
  CleanMeasurements(std::move(m), vehicle, o, &d);
  EstimateVelocity(o, where, &d);
  for (std::string& n : log_notes) d.notes.push_back({TrialNoteKind::kLog, {std::move(n)}, {}});
  return d;
}

std::vector<ForcePiece> ConstantForcePieces(const TrialData& d, double tol, double min_duration) {
  std::vector<ForcePiece> pieces;
  if (d.force.empty()) return pieces;
  ForcePiece open{0.0, d.duration, d.force[0], d.mapping[0]};
  const auto keep_if_long = [&](double t1) {
    open.t1 = t1;
    if (open.t1 - open.t0 >= min_duration) pieces.push_back(open);
  };
  for (std::size_t i = 1; i < d.force.size(); ++i) {
    const double f = d.force[i];
    const int m = d.mapping[i];
    const double scale =
        std::max({std::abs(f), std::abs(open.force), 1e-9 / std::max(tol, 1e-300)});
    if (open.mapping == m && std::abs(f - open.force) <= tol * scale) continue;
    keep_if_long(d.force_t[i]);
    open = {d.force_t[i], d.duration, f, m};
  }
  keep_if_long(d.duration);
  return pieces;
}

double FilterHalfSpan(const TrialData& d) {
  const SmoothedSignal& v = d.velocity_estimate;
  if (v.size() < 2) return 0.0;
  const double step = (v.t.back() - v.t.front()) / (v.size() - 1);
  return 0.5 * (d.sg_window - 1) * step;
}

bool NearForceJump(const TrialData& d, double t, double half_span) {
  const auto it = std::lower_bound(d.force_jumps.begin(), d.force_jumps.end(), t - half_span);
  return it != d.force_jumps.end() && *it <= t + half_span;
}

std::vector<std::pair<std::size_t, std::size_t>> SmoothRuns(const TrialData& d,
                                                            bool split_at_force_jumps) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  const SmoothedSignal& v = d.velocity_estimate;
  const double half = FilterHalfSpan(d);
  std::size_t begin = 0;
  bool open = false;
  std::size_t next_jump = 0;
  // NearForceJump(d, t, half) with a forward cursor (t increases): the first jump >= t − half.
  std::size_t near_jump = 0;
  const std::vector<double>& jumps = d.force_jumps;
  for (std::size_t i = 0; i < v.size(); ++i) {
    while (near_jump < jumps.size() && jumps[near_jump] < v.t[i] - half) ++near_jump;
    const bool near = near_jump < jumps.size() && jumps[near_jump] <= v.t[i] + half;
    const bool usable = !v.edge[i] && std::isfinite(v.value[i]) && (!split_at_force_jumps || !near);
    // A jump between the previous usable sample and this one also ends the run.
    bool crossed = false;
    while (next_jump < d.force_jumps.size() && d.force_jumps[next_jump] <= v.t[i]) {
      crossed = true;
      ++next_jump;
    }
    const bool run_starts = std::binary_search(v.run_starts.begin(), v.run_starts.end(), i);
    const bool new_run = open && (run_starts || (split_at_force_jumps && crossed));
    if (open && (!usable || new_run)) {
      out.push_back({begin, i});
      open = false;
    }
    if (usable && !open) {
      begin = i;
      open = true;
    }
  }
  if (open) out.push_back({begin, v.size()});
  return out;
}

double EstimatedVelocity(const TrialData& d, double t) {
  return Interpolate(d.velocity_estimate.t, d.velocity_estimate.value, t);
}

double VelocityNoiseSigma(const TrialData& trial) {
  const SmoothedSignal& v = trial.velocity_estimate;
  const double sigma = trial.velocity_from_position ? trial.position_sigma : trial.velocity_sigma;
  if (!(sigma > 0)) return 0.0;
  if (!trial.velocity_from_position) return v.value_gain * sigma;
  if (trial.position_noise_ar1 > 0 && !v.derivative_weights.empty()) {
    return sigma * std::sqrt(std::max(
                       0.0, Ar1QuadraticForm(v.derivative_weights, trial.position_noise_ar1)));
  }
  return v.derivative_gain * sigma;
}

}  // namespace uuvplan::ident
