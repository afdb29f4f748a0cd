// One trial of a campaign made ready for identification (contract §Trial log): the trial's own
// DOF's position and velocity samples with outliers excluded (and reported), gaps found, the
// logged force held between rows as the excitation (zero-order hold, notes/pitfalls.md), the
// mapping in force on each row as a vehicle mapping index, the other DOFs' measured velocities
// for coupling terms, and a smoothed velocity estimate (Savitzky–Golay, ref 000 §IV-D).
//
// Times are shifted so that the trial starts at t = 0: its first row with a force value (the
// zero-order hold starts there; measurements logged before it are not used, with a note);
// `start_time` is that instant on the campaign clock.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/ident/prepare/outliers.h"
#include "uuvplan/ident/prepare/steady_detection.h"
#include "uuvplan/ident/prepare/trial_note.h"
#include "uuvplan/ident/prepare/velocity_estimation.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/excitation.h"

namespace uuvplan::ident {

struct TrialDataOptions {
  /// Savitzky–Golay order; window 0 = chosen from the sampling rate (SavitzkyGolayWindow).
  int sg_order = 4;
  int sg_window = 0;
  double gap_factor = 3.0;  ///< a step longer than this × the median step is a gap
  bool remove_outliers = true;
  OutlierOptions outliers;
  /// Two logged forces closer than this (relative to the larger, or 1e-9 N absolute) are the
  /// same constant command (for constant-force pieces).
  double force_tolerance = 1e-6;
  bool IsValid(std::string* error) const;
};

/// Velocities of the other DOFs during a trial, linearly interpolated from the log's vel_<dof>
/// columns (model::AuxVelocities for coupling terms). DOFs without a column read 0.
class LogAuxVelocities final : public model::AuxVelocities {
 public:
  LogAuxVelocities(model::Dof own, std::array<Signal, model::kNumDofs> velocities);
  void At(double t, std::array<double, model::kNumDofs>* v) const override;
  bool Has(model::Dof d) const { return !velocities_[model::Index(d)].empty(); }
  const Signal& velocity(model::Dof d) const { return velocities_[model::Index(d)]; }

 private:
  model::Dof own_;
  std::array<Signal, model::kNumDofs> velocities_;
};

struct TrialData {
  int index = -1;    ///< in the campaign's trial list
  std::string name;  ///< file as written in the campaign
  std::string path;
  model::Dof dof = model::Dof::kSurge;
  model::TrialUse use = model::TrialUse::kFit;
  int ballast_steps = 0;
  double start_time = 0.0;   ///< campaign clock at t = 0 (s)
  double time_offset = 0.0;  ///< log time of t = 0, the first force row (s)
  double duration = 0.0;     ///< s

  Signal position;               ///< measured positions of the DOF, outliers removed
  Signal velocity;               ///< measured velocities of the DOF, outliers removed
  double position_sigma = -1.0;  ///< sensor noise used (declared, else estimated; <= 0 unknown)
  double velocity_sigma = -1.0;
  double position_sigma_estimated = -1.0;  ///< from the data (NoiseSigmaFromDifferences)
  double velocity_sigma_estimated = -1.0;

  /// Logged force rows (NaN rows dropped) and the vehicle mapping index in force on each; their
  /// times as a uniform clock when the log's are (SharedTimes::CompactUniform).
  SharedTimes force_t;
  std::vector<double> force;
  std::vector<int> mapping;
  std::unique_ptr<model::Excitation> input;  ///< zero-order hold of the rows
  std::unique_ptr<LogAuxVelocities> aux;     ///< null when no other vel_ column
  std::vector<std::string> mappings_used;    ///< vehicle mapping names seen
  /// Times of the large command changes (steps of more than 5% of the force range, and
  /// mapping changes): the filtered velocity is distorted within half a filter window of them.
  std::vector<double> force_jumps;
  /// The longest stretch without a force value, [t0, t1) in trial time, when it is longer than
  /// 1 s and 10 median row steps (NaN cells or missing rows): the last command is held across
  /// it (zero-order hold), which the data does not confirm. Empty (t1 <= t0) otherwise.
  double force_gap_t0 = 0.0, force_gap_t1 = 0.0;

  /// Velocity estimate: smoothed measured velocity if the DOF has a velocity column, else the
  /// Savitzky–Golay derivative of the positions (`velocity_from_position` says which); its
  /// `derivative` is the acceleration of the same local polynomials (`second_derivative` is
  /// not kept: empty).
  SmoothedSignal velocity_estimate;
  bool velocity_from_position = true;
  /// AR(1) coefficient of the position noise (PositionNoiseAr1 of the positions with the
  /// filter's window and order; 0 when the velocity is measured).
  double position_noise_ar1 = 0.0;
  int sg_window = 21;
  SavitzkyGolayOptions sg_options;  ///< the filter that made velocity_estimate (window = sg_window)
  /// Initial state from the data: Savitzky–Golay end polynomial at the first sample (position
  /// NaN without position samples).
  double initial_position = 0.0;
  double initial_velocity = 0.0;  ///< 0 when the trial starts at rest
  /// No initial velocity resolved from the first samples (start_at_rest.h).
  bool starts_at_rest = true;

  std::vector<Outlier> position_outliers, velocity_outliers;
  std::vector<Gap> gaps;
  std::vector<TrialNote> notes;  ///< what preparing it did (text/trial_notes_text.h)
  /// Measurement columns of the DOF present in the log but without usable values (all NaN or
  /// fewer than 3 samples), e.g. "vel_yaw": not used, and said so (Identify warns).
  std::vector<std::string> unusable_columns;

  bool has_position() const { return position.size() >= 3; }
  /// Where the held force or the mapping changes, ascending (input->Breakpoints()).
  model::TimesView breakpoints() const { return input->Breakpoints(); }
  bool has_velocity() const { return velocity.size() >= 3; }
  model::TrialConditions conditions() const {
    return model::TrialConditions{input.get(), ballast_steps, start_time, aux.get()};
  }
};

/// Prepares a trial of a campaign. Throws model::InputError (naming the file and column) when
/// the trial's DOF has no force column or no position/velocity sample, or when a mapping is
/// not a mapping of the vehicle.
/// `given_up`, when not null, is the entry's own log, which the caller gives up: its columns
/// are moved into the trial instead of copied, and it is left empty (model::TrialLog{}) before
/// the samples are cleaned and the velocity estimated (a long log is not held twice).
TrialData PrepareTrial(const model::TrialEntry& entry, int index, const model::Vehicle& vehicle,
                       const TrialDataOptions& options, model::TrialLog* given_up = nullptr);

/// Intervals of constant commanded force and mapping (for steady-state detection) that last at
/// least `min_duration` s (a force logged anew at every row has a piece a row, none of which
/// can hold a steady segment).
std::vector<ForcePiece> ConstantForcePieces(const TrialData& trial, double force_tolerance,
                                            double min_duration = 0.0);

/// Velocity estimate at time t (linear interpolation of velocity_estimate).
double EstimatedVelocity(const TrialData& trial, double t);

/// Standard deviation of the velocity estimate's noise (0 when the sensor σ is unknown): the
/// filter's gain times the sensor σ; for a position-derived velocity under AR(1) position
/// noise σ·√(wᵀΩw) with w the derivative weights (covariance.h, Ar1QuadraticForm) — AR(1)
/// noise of ρ = 0.9 has differences √10 times smaller than white noise of the same σ.
double VelocityNoiseSigma(const TrialData& trial);

/// Half the time span of the Savitzky–Golay window of the velocity estimate (s).
double FilterHalfSpan(const TrialData& trial);

/// True when t lies within `half_span` of a large command change (force_jumps).
bool NearForceJump(const TrialData& trial, double t, double half_span);

/// Index ranges [begin, end) of velocity_estimate samples usable by the integral methods:
/// inside one filter run, away from its edges, finite, and not within half a filter window of
/// a large command change (a run is split there: the filtered velocity is distorted across
/// the kink of the acceleration, and integrating through it would bias the regression).
/// `split_at_force_jumps` false keeps those samples (closed-loop commands step at every row).
std::vector<std::pair<std::size_t, std::size_t>> SmoothRuns(const TrialData& trial,
                                                            bool split_at_force_jumps = true);

}  // namespace uuvplan::ident
