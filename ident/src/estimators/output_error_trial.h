// Internal to the output error (output_error.h): one trial's measurements on a common time
// grid, the z columns of its initial state, and the grid its simulation reports on.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/times_view.h"

namespace uuvplan::ident::internal {

// One trial's measurements on a common time grid.
struct TrialProblem {
  const TrialData* trial = nullptr;
  // The force the simulation is driven by: the trial's own, or its average over coarse pieces
  // (AveragedInput, the coarse stage's).
  std::shared_ptr<const model::Excitation> averaged_input;
  model::TrialConditions conditions() const {
    model::TrialConditions c = trial->conditions();
    if (averaged_input) c.input = averaged_input.get();
    return c;
  }
  model::TimesView breakpoints() const {
    return averaged_input ? averaged_input->Breakpoints() : trial->breakpoints();
  }
  // The sorted union of the used sample times: owned, or the trial's own sample times when one
  // sensor is used sample by sample (not copied: 8 bytes a sample).
  std::vector<double> times_owned;
  const SharedTimes* times_ref = nullptr;
  model::TimesView times() const { return times_ref ? times_ref->view() : times_owned; }
  // One sensor's measurements: measurement k is at times[at(k)], value y(k), weight w(k)
  // (1/σ, √n/σ for a bin). The index is not stored when it is k itself (one sensor), nor the
  // weights when they are all equal (unbinned), nor the values when they are the trial's own
  // samples: 20 bytes a measurement.
  struct Measurements {
    std::vector<int> at_index;  // empty: measurement k is at times[k]
    std::vector<double> y_owned;
    const std::vector<double>* y_ref = nullptr;  // the trial's samples, when not binned
    std::vector<double> w;                       // empty: every weight is w_all
    double w_all = 1.0;
    std::size_t size() const { return y_ref ? y_ref->size() : y_owned.size(); }
    double y(std::size_t k) const { return y_ref ? (*y_ref)[k] : y_owned[k]; }
    int at(std::size_t k) const { return at_index.empty() ? static_cast<int>(k) : at_index[k]; }
    double weight(std::size_t k) const { return w.empty() ? w_all : w[k]; }
  };
  Measurements pos, vel;
  TrialInitialState init;
  int z_chi0 = -1, z_xi0 = -1;  // indices in z
  int r_offset = 0;             // first residual of this trial
  // Dense samples: the simulation's output grid (empty: simulate at `times`). Sample time t
  // lies in interval g, grid[g] <= t <= grid[g + 1], the first such g (IntervalCursor).
  std::vector<double> grid;
  struct Hermite {
    double h00, h10, h01, h11, u;  // cubic Hermite basis at the time (h10, h11 times h)
  };
  // The basis of time t in grid interval g, computed when read (stored, it would take 40 bytes
  // a sample: 40 MB of a 10⁶-sample trial).
  double U(double t, int g) const {
    const double h = grid[g + 1] - grid[g];
    return h > 0 ? std::clamp((t - grid[g]) / h, 0.0, 1.0) : 0.0;
  }
  Hermite Weights(double t, int g) const {
    const double h = grid[g + 1] - grid[g];
    const double u = U(t, g);
    return {(1 + 2 * u) * (1 - u) * (1 - u), h * u * (1 - u) * (1 - u), u * u * (3 - 2 * u),
            h * u * u * (u - 1), u};
  }
  int num_residuals() const { return static_cast<int>(pos.size() + vel.size()); }
  // The state a one-sensor trial measures: 0 position, 1 velocity.
  int sensor() const { return pos.size() > 0 ? 0 : 1; }
  // One sensor, on the grid or at its own times without a sensor delay to differentiate: its
  // rows can be made while the simulation runs (Problem::Evaluate streams them).
  bool streamable(const model::DofModel& model) const {
    return (pos.size() == 0 || vel.size() == 0) &&
           (!grid.empty() || model.sensor_delay_index() < 0);
  }
};

// The grid interval of increasing sample times, found by a forward cursor (the first g with
// t <= grid[g + 1], the last interval for times beyond it).
class IntervalCursor {
 public:
  explicit IntervalCursor(const std::vector<double>& grid) : grid_(grid) {}
  int operator()(double t) {
    while (g_ + 2 < grid_.size() && grid_[g_ + 1] < t) ++g_;
    return static_cast<int>(g_);
  }

 private:
  const std::vector<double>& grid_;
  std::size_t g_ = 0;
};

// The trial's problem: its measurements (binned to o.bin_s unless one sensor is used sample by
// sample), its initial state (`initial`'s entry for the trial, else guessed from the data) and
// its output grid (o.grid_s); the z and residual indices are left for the caller to assign.
// With `average_input_s` > 0 the force is averaged over pieces that long (AveragedInput).
// Nothing when the trial has no sensor the options use.
std::optional<TrialProblem> MakeTrialProblem(const model::DofModel& model, const TrialData& d,
                                             const std::vector<TrialInitialState>* initial,
                                             const OutputErrorOptions& o,
                                             double average_input_s = 0.0);

}  // namespace uuvplan::ident::internal
