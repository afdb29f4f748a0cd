// Screen stage: where the free-run simulation goes wrong, by thrust direction and mapping, by
// direction of motion, by speed, by command size, by lag and by campaign time (diagnosis.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "diagnosis_internal.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::ident::diagnosis {

namespace {

struct Sample {
  double t, sim, meas, force;
  int mapping;
};

// Free-run velocity of a trial at its velocity-estimate times, from the data's initial state.
std::vector<double> FreeRunVelocity(const model::DofModel& model, const Eigen::VectorXd& theta,
                                    const TrialData& trial, double step_s) {
  const auto& ve = trial.velocity_estimate;
  if (ve.t.empty()) return {};
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.num_states());
  x0[0] = std::isfinite(trial.initial_position) ? trial.initial_position : 0.0;
  x0[1] = trial.initial_velocity;
  std::vector<double> times;
  for (double t : ve.t) times.push_back(std::max(0.0, t));
  std::sort(times.begin(), times.end());
  model::SimulationOptions so;
  so.step_s = step_s;
  const model::Trajectory tr =
      model::SimulateMeasured(model, theta, trial.conditions(), times, so, &x0);
  return std::vector<double>(tr.x.col(1).data(), tr.x.col(1).data() + times.size());
}

// Simulated and measured velocity with the command, away from the filter's edges.
std::vector<Sample> Samples(const model::DofModel& model, const Eigen::VectorXd& theta,
                            const TrialData& t, double step_s) {
  const std::vector<double> sim = FreeRunVelocity(model, theta, t, step_s);
  const auto& ve = t.velocity_estimate;
  std::vector<Sample> samples;
  for (std::size_t i = 0; i < sim.size(); ++i) {
    if (!std::isfinite(ve.value[i]) || (i < ve.edge.size() && ve.edge[i])) continue;
    double f = 0;
    int mi = -1;
    t.input->Sample(ve.t[i], &f, &mi);
    samples.push_back({ve.t[i], sim[i], ve.value[i], f, mi});
  }
  return samples;
}

// Σ|ξ_sim|, Σ|ξ_meas| and Σ|error| of a group of samples.
struct Accumulator {
  double sim = 0, meas = 0, abs_err = 0;
  int n = 0;
  void Add(const Sample& s) {
    sim += std::abs(s.sim);
    meas += std::abs(s.meas);
    abs_err += std::abs(s.sim - s.meas);
    ++n;
  }
};
using Groups = std::map<std::string, Accumulator>;

std::vector<model::ErrorGroup> ToGroups(const Groups& groups) {
  std::vector<model::ErrorGroup> out;
  for (const auto& [label, a] : groups) {
    if (a.n == 0 || a.meas <= 0) continue;
    out.push_back({label, a.sim / a.meas - 1.0, a.abs_err / a.n, a.n});
  }
  return out;
}

double MedianSpeed(const std::vector<std::vector<Sample>>& per_trial) {
  std::vector<double> speed;
  for (const auto& samples : per_trial) {
    for (const Sample& s : samples) speed.push_back(std::abs(s.meas));
  }
  std::sort(speed.begin(), speed.end());
  return speed.empty() ? 0.0 : speed[speed.size() / 2];
}

void AddGrouped(const model::Vehicle& vehicle, const std::vector<std::vector<Sample>>& per_trial,
                double fmax, const std::string& unit, ErrorBreakdown* b) {
  const double median_speed = MedianSpeed(per_trial);
  std::ostringstream sp;
  sp.precision(2);
  sp << std::fixed << median_speed << " " << unit;
  Groups thrust, motion, speed, command;
  for (const auto& samples : per_trial) {
    for (const Sample& s : samples) {
      if (s.mapping >= 0 && std::abs(s.force) > 1e-6 * fmax) {
        thrust[std::string("thrust ") + (s.force > 0 ? "positive" : "negative") + " in " +
               vehicle.mappings[s.mapping].name]
            .Add(s);
      }
      motion[s.meas >= 0 ? "positive motion" : "negative motion"].Add(s);
      speed[(std::abs(s.meas) > median_speed ? "speed above " : "speed below ") + sp.str()].Add(s);
      command[std::abs(s.force) < 0.2 * fmax ? ErrorBreakdown::kSmallCommands : "large commands"]
          .Add(s);
    }
  }
  b->by_thrust = ToGroups(thrust);
  b->by_motion = ToGroups(motion);
  b->by_speed = ToGroups(speed);
  b->by_command = ToGroups(command);
}

// Normalised cross-correlation of simulated and measured velocity of one trial, measurement at
// t against simulation at t − shift.
double CrossCorrelation(const std::vector<Sample>& ps, double shift) {
  double sxy = 0, sxx = 0, syy = 0;
  std::size_t i2 = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double ts = ps[i].t - shift;
    while (i2 + 1 < ps.size() && ps[i2 + 1].t <= ts) ++i2;
    if (ts < ps.front().t || ts > ps.back().t || i2 + 1 >= ps.size()) continue;
    const double w = (ts - ps[i2].t) / (ps[i2 + 1].t - ps[i2].t);
    const double sim = ps[i2].sim + w * (ps[i2 + 1].sim - ps[i2].sim);
    sxy += sim * ps[i].meas;
    sxx += sim * sim;
    syy += ps[i].meas * ps[i].meas;
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// The shift in [−2, 2] s with the best cross-correlation summed over `trials` (all when empty):
// the best of 0.05 s steps, refined by the parabola through it and its neighbours.
// corr[k][j]: trial j's correlation at shift 0.05·(k − 40).
double BestShift(const std::vector<std::vector<double>>& corr, std::size_t skip) {
  std::vector<double> total(corr.size(), 0.0);
  for (std::size_t k = 0; k < corr.size(); ++k) {
    for (std::size_t j = 0; j < corr[k].size(); ++j) {
      if (j != skip) total[k] += corr[k][j];
    }
  }
  const std::size_t best = std::max_element(total.begin(), total.end()) - total.begin();
  double shift = 0.05 * (static_cast<double>(best) - 40.0);
  if (best > 0 && best + 1 < total.size()) {
    const double a = total[best - 1], b = total[best], c = total[best + 1];
    const double curvature = a - 2 * b + c;
    if (curvature < 0) shift += 0.05 * 0.5 * (a - c) / curvature;
  }
  return shift;
}

// The lag (BestShift over every trial) and its jackknife σ over trials (Efron & Tibshirani,
// An Introduction to the Bootstrap, eq. 11.5): σ² = (n−1)/n·Σ(lag₋ⱼ − mean)², NaN for n < 2.
void AddLag(const std::vector<std::vector<Sample>>& per_trial, ErrorBreakdown* b) {
  std::vector<std::vector<double>> corr(81, std::vector<double>(per_trial.size()));
  for (int k = 0; k <= 80; ++k) {
    for (std::size_t j = 0; j < per_trial.size(); ++j) {
      corr[k][j] = CrossCorrelation(per_trial[j], 0.05 * (k - 40));
    }
  }
  b->lag_s = BestShift(corr, per_trial.size());
  const std::size_t n = per_trial.size();
  if (n < 2) {
    b->lag_sigma_s = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  std::vector<double> loo(n);
  double mean = 0.0;
  for (std::size_t j = 0; j < n; ++j) mean += (loo[j] = BestShift(corr, j)) / n;
  double ss = 0.0;
  for (double l : loo) ss += (l - mean) * (l - mean);
  b->lag_sigma_s = std::sqrt((n - 1.0) / n * ss);
}

// Least-squares slope of the trials' relative speed error over campaign time (per hour).
void AddDrift(const Trials& trials, const std::vector<std::vector<Sample>>& per_trial,
              ErrorBreakdown* b) {
  std::vector<std::pair<double, double>> points;  // (campaign time h, relative error)
  for (std::size_t k = 0; k < trials.size(); ++k) {
    Accumulator a;
    for (const Sample& s : per_trial[k]) a.Add(s);
    if (a.meas > 0) {
      points.push_back(
          {(trials[k]->start_time + 0.5 * trials[k]->duration) / 3600.0, a.sim / a.meas - 1.0});
    }
  }
  if (points.size() < 2) {
    b->drift_sigma_per_hour = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  double mt = 0, me = 0;
  for (auto [t, e] : points) {
    mt += t;
    me += e;
  }
  mt /= points.size();
  me /= points.size();
  double sxy = 0, sxx = 0;
  for (auto [t, e] : points) {
    sxy += (t - mt) * (e - me);
    sxx += (t - mt) * (t - mt);
  }
  b->drift_per_hour = sxx > 0 ? sxy / sxx : 0.0;
  // σ of a least-squares slope: s/√Sxx, s² = Σ residual² / (n − 2).
  double ss = 0.0;
  for (auto [t, e] : points) ss += std::pow(e - me - b->drift_per_hour * (t - mt), 2);
  b->drift_sigma_per_hour = points.size() > 2 && sxx > 0
                                ? std::sqrt(ss / (points.size() - 2.0) / sxx)
                                : std::numeric_limits<double>::quiet_NaN();
  const auto [first, last] = std::minmax_element(
      points.begin(), points.end(), [](const auto& a, const auto& c) { return a.first < c.first; });
  b->campaign_span_h = last->first - first->first;
}

}  // namespace

ErrorBreakdown Breakdown(const model::Vehicle& vehicle, const model::DofModel& model,
                         const Eigen::VectorXd& theta, const Trials& trials, double step_s,
                         bool campaign_clock) {
  ErrorBreakdown b;
  b.dof = model.dof();
  std::vector<std::vector<Sample>> per_trial;
  double abs_err = 0.0;
  int n = 0;
  for (const TrialData* t : trials) {
    per_trial.push_back(Samples(model, theta, *t, step_s));
    for (const Sample& s : per_trial.back()) abs_err += std::abs(s.sim - s.meas);
    n += static_cast<int>(per_trial.back().size());
  }
  AddGrouped(vehicle, per_trial, MaxForce(trials), std::string(model::VelocityUnit(b.dof)), &b);
  b.velocity_mae = n ? abs_err / n : 0.0;
  AddLag(per_trial, &b);
  if (campaign_clock) {
    AddDrift(trials, per_trial, &b);
  } else {
    b.drift_per_hour = b.campaign_span_h = b.drift_sigma_per_hour =
        std::numeric_limits<double>::quiet_NaN();
  }
  return b;
}

}  // namespace uuvplan::ident::diagnosis
