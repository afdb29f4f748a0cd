#include "uuvplan/ident/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "uuvplan/ident/chi_square.h"
#include "uuvplan/ident/trial_data.h"
#include "uuvplan/ident/validation.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::ident {

using model::Dof;
using model::Effect;
using model::ModelStructure;

model::ModelStructure NominalStructure(const model::Vehicle& vehicle, Dof dof,
                                       const std::vector<std::string>& mappings_used,
                                       bool ballast) {
  ModelStructure s = ModelStructure::Standard(vehicle, dof, mappings_used, ballast);
  s.free_eta.clear();  // contract: the standard model has all η = 1
  return s;
}

bool DiagnoseOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "DiagnoseOptions::" + m;
    return false;
  };
  if (!(significance > 0 && significance < 1)) {
    return fail("significance = " + std::to_string(significance) +
                ". Violated constraint: 0 < significance < 1");
  }
  if (!(min_z >= 0)) return fail("min_z must be >= 0");
  if (!(min_gain >= 0 && min_gain < 1)) return fail("min_gain must be in [0, 1)");
  if (input_noise_replicates < 0) return fail("input_noise_replicates must be >= 0");
  if (max_effects < 0) return fail("max_effects must be >= 0");
  std::string sub;
  if (!output_error.IsValid(&sub)) return fail("output_error: " + sub);
  if (!identify.IsValid(&sub)) return fail("identify: " + sub);
  return true;
}

namespace {

using Values = std::map<std::string, double>;

// A structure fitted by output error on the fit trials.
struct StructureFit {
  ModelStructure structure;
  std::shared_ptr<model::DofModel> model;
  OutputErrorResult oe;
  Values values;  // by parameter name
  std::set<std::string> dropped;
  int free_parameters = 0;  // model parameters + nuisance initial states
};

// Null values of an extension's parameters: "no effect".
double NullValue(const std::string& name) {
  return name.rfind(model::param::kEtaPrefix, 0) == 0 ? 1.0 : 0.0;
}

StructureFit FitStructure(const model::Vehicle& vehicle, const ModelStructure& structure,
                          const std::vector<const TrialData*>& trials, const Values& start,
                          const std::set<std::string>& dropped, const OutputErrorOptions& options) {
  StructureFit f;
  f.structure = structure;
  f.model = std::make_shared<model::DofModel>(vehicle, structure);
  f.dropped = dropped;
  const int np = f.model->num_parameters();
  Eigen::VectorXd theta0(np);
  std::vector<ParameterState> state(np, ParameterState::kEstimated);
  for (int i = 0; i < np; ++i) {
    const std::string& n = f.model->parameter_names()[i];
    const auto it = start.find(n);
    theta0[i] = it != start.end() ? it->second : NullValue(n);
    if (dropped.count(n)) {
      state[i] = ParameterState::kDropped;
      theta0[i] = 0.0;
    }
  }
  OutputErrorOptions o = options;
  o.prune_insignificant = false;  // structures are compared as given
  f.oe = OutputErrorFit(*f.model, trials, theta0, state, o);
  for (int i = 0; i < np; ++i) f.values[f.model->parameter_names()[i]] = f.oe.theta[i];
  for (const auto& s : f.oe.state) f.free_parameters += s == ParameterState::kEstimated;
  for (const auto& init : f.oe.initial) {
    f.free_parameters += init.chi0_estimated + init.xi0_estimated;
  }
  return f;
}

// A candidate extension of the current structure.
struct Candidate {
  Effect effect;
  std::string detail;
  ModelStructure structure;
  Values start;                    // starting values of the new parameters
  std::vector<std::string> added;  // names of the new parameters
};

// (mapping, direction) pairs of the nominal force present in the trials.
std::set<std::pair<std::string, model::Direction>> ThrustDirections(
    const model::Vehicle& vehicle, const std::vector<const TrialData*>& trials) {
  std::set<std::pair<std::string, model::Direction>> out;
  for (const TrialData* t : trials) {
    double fmax = 0.0;
    for (double f : t->force) fmax = std::max(fmax, std::abs(f));
    for (std::size_t i = 0; i < t->force.size(); ++i) {
      const int m = i < t->mapping.size() ? t->mapping[i] : -1;
      if (m < 0 || std::abs(t->force[i]) <= 1e-6 * fmax) continue;
      out.insert({vehicle.mappings[m].name,
                  t->force[i] > 0 ? model::Direction::kPos : model::Direction::kNeg});
    }
  }
  return out;
}

double TypicalSpeed(const std::vector<const TrialData*>& trials) {
  std::vector<double> s;
  for (const TrialData* t : trials) {
    for (double v : t->velocity_estimate.value) {
      if (std::isfinite(v)) s.push_back(std::abs(v));
    }
  }
  if (s.empty()) return 0.0;
  std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
  return s[s.size() / 2];
}

double MaxForce(const std::vector<const TrialData*>& trials) {
  double fmax = 0.0;
  for (const TrialData* t : trials) {
    for (double f : t->force) fmax = std::max(fmax, std::abs(f));
  }
  return fmax;
}

// Velocity letters measured in every trial (the own DOF's always).
std::vector<char> AvailableLetters(Dof dof, const std::vector<const TrialData*>& trials) {
  std::vector<char> letters = {model::VelocityLetter(dof)};
  for (Dof d : model::kAllDofs) {
    if (d == dof) continue;
    const bool all = std::all_of(trials.begin(), trials.end(),
                                 [&](const TrialData* t) { return t->aux && t->aux->Has(d); });
    if (all && !trials.empty()) letters.push_back(model::VelocityLetter(d));
  }
  return letters;
}

std::vector<Candidate> CandidatesFor(Effect effect, const model::Vehicle& vehicle,
                                     const StructureFit& base,
                                     const std::vector<const TrialData*>& trials,
                                     bool campaign_clock) {
  std::vector<Candidate> out;
  const ModelStructure& s = base.structure;
  const Values& v = base.values;
  const double m = v.count("m") ? v.at("m") : 1.0;
  const double speed = std::max(TypicalSpeed(trials), 1e-3);
  const double kl = (v.count("k") ? v.at("k") : 0.0) + 2 * (v.count("kq") ? v.at("kq") : 0.0) * speed;
  const double tc = kl > 0 ? m / kl : 1.0;
  auto make = [&](const std::string& detail) {
    Candidate c{effect, detail, s, {}, {}};
    return c;
  };
  switch (effect) {
    case Effect::kInstallationLoss: {
      Candidate c = make("");
      for (const auto& [mapping, dir] : ThrustDirections(vehicle, trials)) {
        const int mi = vehicle.MappingIndex(mapping);
        const std::string name = model::EtaName(mapping, dir);
        if (mi < 0 || vehicle.mappings[mi].IsOpenWater(dir)) continue;
        if (std::find(s.free_eta.begin(), s.free_eta.end(), name) != s.free_eta.end()) continue;
        c.structure.free_eta.push_back(name);
        c.start[name] = 1.0;
        c.added.push_back(name);
      }
      if (!c.added.empty()) out.push_back(c);
      break;
    }
    case Effect::kAsymmetricDrag: {
      if (s.asymmetric_drag) break;
      Candidate c = make("");
      c.structure.asymmetric_drag = true;
      if (s.linear_drag && !base.dropped.count("k")) {
        c.start["k_neg"] = v.at("k");
        c.added.push_back("k_neg");
      }
      if (s.quadratic_drag && !base.dropped.count("kq")) {
        c.start["kq_neg"] = v.at("kq");
        c.added.push_back("kq_neg");
      }
      // k_neg / kq_neg are compared with k / kq, not with 0: their null is the symmetric value.
      if (!c.added.empty()) out.push_back(c);
      break;
    }
    case Effect::kThrusterLag:
      if (!s.thruster_lag) {
        Candidate c = make("");
        c.structure.thruster_lag = true;
        c.start["lag"] = 0.1 * tc;
        c.added.push_back("lag");
        out.push_back(c);
      }
      break;
    case Effect::kDeadzone:
      if (!s.deadzone) {
        Candidate c = make("");
        c.structure.deadzone = true;
        c.start["deadzone"] = 0.02 * MaxForce(trials);
        c.added.push_back("deadzone");
        out.push_back(c);
      }
      break;
    case Effect::kAdvanceSpeedLoss:
      if (!s.advance_speed_loss) {
        Candidate c = make("");
        c.structure.advance_speed_loss = true;
        c.start["advance_loss"] = 0.0;
        c.added.push_back("advance_loss");
        out.push_back(c);
      }
      break;
    case Effect::kCoupling: {
      const std::vector<char> letters = AvailableLetters(s.dof, trials);
      const char own = model::VelocityLetter(s.dof);
      for (std::size_t i = 0; i < letters.size(); ++i) {
        for (std::size_t j = i; j < letters.size(); ++j) {
          if (letters[i] == own && letters[j] == own) continue;  // ξ² is quadratic drag
          const std::string pair{letters[i], letters[j]};
          if (std::find(s.coupling.begin(), s.coupling.end(), pair) != s.coupling.end()) continue;
          Candidate c = make(pair);
          c.structure.coupling.push_back(pair);
          const std::string name = std::string(model::param::kCouplingPrefix) + pair;
          c.start[name] = 0.0;
          c.added.push_back(name);
          out.push_back(c);
        }
      }
      break;
    }
    case Effect::kSensorDelay:
      if (!s.sensor_delay) {
        Candidate c = make("");
        c.structure.sensor_delay = true;
        c.start["sensor_delay"] = 0.05 * tc;
        c.added.push_back("sensor_delay");
        out.push_back(c);
      }
      break;
    case Effect::kParameterDrift:
      if (!s.parameter_drift) {
        // Drift needs trials spread over the campaign clock.
        double t0 = 1e300, t1 = -1e300;
        for (const TrialData* t : trials) {
          t0 = std::min(t0, t->start_time);
          t1 = std::max(t1, t->start_time + t->duration);
        }
        if (campaign_clock && trials.size() >= 2 && t1 - t0 > 0) {
          Candidate c = make("");
          c.structure.parameter_drift = true;
          c.start["drift"] = 0.0;
          c.added.push_back("drift");
          out.push_back(c);
        }
      }
      break;
    case Effect::kThrustMap:
      if (!s.thrust_map) {
        // The shape shows only across command levels: at a single |φ| it is a pure scale
        // (absorbed by m, k, kq, bias). Levels spanning less than a factor 1.5 are not tested.
        const double fmax = MaxForce(trials);
        double fmin = fmax;
        for (const TrialData* t : trials) {
          for (double f : t->force) {
            if (std::abs(f) > 0.01 * fmax) fmin = std::min(fmin, std::abs(f));
          }
        }
        if (fmax > 0 && fmin < fmax / 1.5) {
          Candidate c = make("");
          c.structure.thrust_map = true;
          c.structure.thrust_reference = fmax;  // η, m, k, kq keep their meaning at the largest command
          c.start[model::param::kThrustExponent] = 0.0;
          c.added.push_back(model::param::kThrustExponent);
          out.push_back(c);
        }
      }
      break;
  }
  return out;
}

// Null value of an added parameter given the base fit (asymmetric drag: the symmetric value).
double NullFor(const std::string& name, const Values& base) {
  if (name == "k_neg" && base.count("k")) return base.at("k");
  if (name == "kq_neg" && base.count("kq")) return base.at("kq");
  return NullValue(name);
}

CandidateTest Test(const Candidate& c, const StructureFit& base, const StructureFit& ext,
                   int round) {
  CandidateTest t;
  t.effect = c.effect;
  t.dof = c.structure.dof;
  t.detail = c.detail;
  t.round = round;
  t.added_parameters = static_cast<int>(c.added.size());
  if (!ext.oe.ok() || !base.oe.ok()) {
    t.detail += (t.detail.empty() ? "" : "; ") + std::string("fit failed: ") + ext.oe.message;
    return t;
  }
  const int n = ext.oe.num_residuals;
  const double s2 = 2.0 * ext.oe.cost / std::max(1, n - ext.free_parameters);
  t.statistic = std::max(0.0, 2.0 * (base.oe.cost - ext.oe.cost) / s2);
  t.p_value = ChiSquareSurvival(t.statistic, t.added_parameters);
  for (const std::string& name : c.added) {
    const int k = FindEstimate(ext.oe.estimates, name);
    if (k < 0) continue;
    const auto& e = ext.oe.estimates[k];
    if (e.sigma > 0) t.max_z = std::max(t.max_z, std::abs(e.value - NullFor(name, base.values)) / e.sigma);
  }
  return t;
}

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

std::string Percent(double r) {
  std::ostringstream s;
  s.precision(0);
  s << std::fixed << std::abs(100.0 * r) << "%";
  return s.str();
}

std::string Over(double r) { return r >= 0 ? "overpredicts" : "underpredicts"; }

// campaign_clock: every trial has a `start` on the campaign clock (else no drift over it).
ErrorBreakdown Breakdown(const model::Vehicle& vehicle, const model::DofModel& model,
                         const Eigen::VectorXd& theta, const std::vector<const TrialData*>& trials,
                         double step_s, bool campaign_clock) {
  ErrorBreakdown b;
  b.dof = model.dof();
  struct Acc {
    double sim = 0, meas = 0, abs_err = 0;
    int n = 0;
  };
  std::map<std::string, Acc> thrust, motion, speed, command;
  std::vector<double> all_speed;
  double fmax = MaxForce(trials);
  // Lag: correlation of measured and simulated velocity over shifts of ±2 s.
  std::vector<double> shifts;
  for (int k = -40; k <= 40; ++k) shifts.push_back(0.05 * k);
  std::vector<double> corr(shifts.size(), 0.0);
  std::vector<std::pair<double, double>> drift_points;  // (campaign time h, relative error)
  double abs_err = 0.0;
  int n_all = 0;
  struct Sample {
    double t, sim, meas, force;
    int mapping;
  };
  std::vector<std::vector<Sample>> per_trial;
  for (const TrialData* t : trials) {
    const std::vector<double> sim = FreeRunVelocity(model, theta, *t, step_s);
    std::vector<Sample> samples;
    const auto& ve = t->velocity_estimate;
    for (std::size_t i = 0; i < sim.size(); ++i) {
      if (!std::isfinite(ve.value[i]) || (i < ve.edge.size() && ve.edge[i])) continue;
      double f = 0;
      int mi = -1;
      t->input->Sample(ve.t[i], &f, &mi);
      samples.push_back({ve.t[i], sim[i], ve.value[i], f, mi});
      all_speed.push_back(std::abs(ve.value[i]));
    }
    per_trial.push_back(std::move(samples));
  }
  std::vector<double> sorted = all_speed;
  std::sort(sorted.begin(), sorted.end());
  const double median_speed = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  const std::string unit(model::VelocityUnit(model.dof()));
  for (std::size_t k = 0; k < trials.size(); ++k) {
    const TrialData* t = trials[k];
    Acc trial_acc;
    for (const Sample& s : per_trial[k]) {
      const double e = std::abs(s.sim - s.meas);
      auto add = [&](std::map<std::string, Acc>& m, const std::string& label) {
        Acc& a = m[label];
        a.sim += std::abs(s.sim);
        a.meas += std::abs(s.meas);
        a.abs_err += e;
        ++a.n;
      };
      if (s.mapping >= 0 && std::abs(s.force) > 1e-6 * fmax) {
        add(thrust, std::string("thrust ") + (s.force > 0 ? "positive" : "negative") + " in " +
                        vehicle.mappings[s.mapping].name);
      }
      add(motion, s.meas >= 0 ? "positive motion" : "negative motion");
      std::ostringstream sp;
      sp.precision(2);
      sp << std::fixed << median_speed << " " << unit;
      add(speed, (std::abs(s.meas) > median_speed ? "speed above " : "speed below ") + sp.str());
      add(command, std::abs(s.force) < 0.2 * fmax ? "small commands (|phi| < 20% of the largest)"
                                                   : "large commands");
      trial_acc.sim += std::abs(s.sim);
      trial_acc.meas += std::abs(s.meas);
      abs_err += e;
      ++n_all;
    }
    if (trial_acc.meas > 0) {
      drift_points.push_back({(t->start_time + 0.5 * t->duration) / 3600.0,
                              trial_acc.sim / trial_acc.meas - 1.0});
    }
    // Cross-correlation of simulated and measured velocity for each shift (measurement later).
    const auto& ps = per_trial[k];
    for (std::size_t j = 0; j < shifts.size(); ++j) {
      double sxy = 0, sxx = 0, syy = 0;
      std::size_t i2 = 0;
      for (std::size_t i = 0; i < ps.size(); ++i) {
        const double ts = ps[i].t - shifts[j];  // measurement at t vs simulation at t − shift
        while (i2 + 1 < ps.size() && ps[i2 + 1].t <= ts) ++i2;
        if (ts < ps.front().t || ts > ps.back().t || i2 + 1 >= ps.size()) continue;
        const double w = (ts - ps[i2].t) / (ps[i2 + 1].t - ps[i2].t);
        const double sim = ps[i2].sim + w * (ps[i2 + 1].sim - ps[i2].sim);
        sxy += sim * ps[i].meas;
        sxx += sim * sim;
        syy += ps[i].meas * ps[i].meas;
      }
      if (sxx > 0 && syy > 0) corr[j] += sxy / std::sqrt(sxx * syy);
    }
  }
  auto groups = [](const std::map<std::string, Acc>& m) {
    std::vector<ErrorGroup> out;
    for (const auto& [label, a] : m) {
      if (a.n == 0 || a.meas <= 0) continue;
      out.push_back({label, a.sim / a.meas - 1.0, a.abs_err / a.n, a.n});
    }
    return out;
  };
  b.by_thrust = groups(thrust);
  b.by_motion = groups(motion);
  b.by_speed = groups(speed);
  b.by_command = groups(command);
  b.velocity_mae = n_all ? abs_err / n_all : 0.0;
  b.lag_s = shifts[std::max_element(corr.begin(), corr.end()) - corr.begin()];
  if (!campaign_clock) {
    b.drift_per_hour = b.campaign_span_h = std::numeric_limits<double>::quiet_NaN();
  } else if (drift_points.size() >= 2) {
    double mt = 0, me = 0;
    for (auto [t, e] : drift_points) {
      mt += t;
      me += e;
    }
    mt /= drift_points.size();
    me /= drift_points.size();
    double sxy = 0, sxx = 0;
    for (auto [t, e] : drift_points) {
      sxy += (t - mt) * (e - me);
      sxx += (t - mt) * (t - mt);
    }
    b.drift_per_hour = sxx > 0 ? sxy / sxx : 0.0;
    const auto [first, last] = std::minmax_element(
        drift_points.begin(), drift_points.end(),
        [](const auto& a, const auto& c) { return a.first < c.first; });
    b.campaign_span_h = last->first - first->first;
  }
  return b;
}

const ErrorGroup* Largest(const std::vector<ErrorGroup>& g) {
  const ErrorGroup* best = nullptr;
  for (const auto& e : g) {
    if (!best || std::abs(e.relative) > std::abs(best->relative)) best = &e;
  }
  return best;
}

const ErrorGroup* Labeled(const std::vector<ErrorGroup>& g, const std::string& label) {
  for (const auto& e : g) {
    if (e.label == label) return &e;
  }
  return nullptr;
}

std::string What(const Finding& f, const ErrorBreakdown& b, const std::string& detail) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed;
  switch (f.effect) {
    case Effect::kInstallationLoss: {
      // The η that departs most from 1 names the mapping and direction.
      const ParameterEstimate* worst = nullptr;
      for (const auto& p : f.params) {
        if (!worst || std::abs(p.value - 1) > std::abs(worst->value - 1)) worst = &p;
      }
      if (worst) {
        const std::string name = worst->name.substr(4);  // "<mapping>.<pos|neg>"
        const std::string mapping = name.substr(0, name.rfind('.'));
        const bool neg = name.substr(name.rfind('.') + 1) == "neg";
        const std::string label =
            std::string("thrust ") + (neg ? "negative" : "positive") + " in " + mapping;
        // The fitted η says how much thrust is missing; the standard model's speed error there
        // can be much smaller, when its m, drag and bias absorb part of the loss (seed 000
        // Fig. 6: the heave weight), so it is quoted second.
        s << "thrust " << (neg ? "negative" : "positive") << " in mapping " << mapping
          << " delivers " << Percent(1 - worst->value) << (worst->value <= 1 ? " less" : " more")
          << " than the open-water model";
        if (const ErrorGroup* g = Labeled(b.by_thrust, label)) {
          s << " (with eta = 1 the standard model's simulation " << Over(g->relative)
            << " speed there by " << Percent(g->relative) << ")";
        }
        return s.str();
      }
      break;
    }
    case Effect::kAsymmetricDrag:
      if (const ErrorGroup* g = Largest(b.by_motion)) {
        s << "simulation " << Over(g->relative) << " speed by " << Percent(g->relative)
          << " in " << g->label << ": drag differs between the two directions";
        return s.str();
      }
      break;
    case Effect::kThrusterLag:
      s << "the response to every change of thrust comes late and smoothed";
      // The cross-correlation resolves whole samples only; a lag below that is not quoted.
      if (std::abs(b.lag_s) > 0) s << " (measured velocity lags the simulation by " << b.lag_s << " s)";
      return s.str();
    case Effect::kSensorDelay:
      s << "every measurement lags the simulated motion by a fixed time (" << b.lag_s
        << " s at the best cross-correlation)";
      return s.str();
    case Effect::kDeadzone:
      if (const ErrorGroup* g = Labeled(b.by_command, "small commands (|phi| < 20% of the largest)")) {
        s << "simulation " << Over(g->relative) << " speed by " << Percent(g->relative)
          << " for small commands: no thrust below a threshold";
        return s.str();
      }
      break;
    case Effect::kAdvanceSpeedLoss:
      if (const ErrorGroup* g = Largest(b.by_speed)) {
        s << "simulation " << Over(g->relative) << " speed by " << Percent(g->relative) << " at "
          << g->label << ": thrust falls with the speed of advance";
        return s.str();
      }
      break;
    case Effect::kCoupling:
      s << "errors follow the motion of other degrees of freedom (" << detail.substr(0, 1)
        << "·" << detail.substr(1, 1) << ")";
      return s.str();
    case Effect::kParameterDrift: {
      // drift·t_c·φ (force_terms_impl.h): the thrust's relative change per second of campaign.
      const double per_s = f.params.empty() ? 0.0 : f.params[0].value;
      std::ostringstream rate;
      rate.precision(2);
      rate << std::abs(100.0 * per_s * 3600.0);
      s << "the thrust " << (per_s >= 0 ? "grows" : "falls") << " by "
        << Percent(per_s * 3600.0 * b.campaign_span_h) << " from the first to the last trial ("
        << b.campaign_span_h << " h apart, " << rate.str() << "% per hour)";
      if (b.campaign_span_h > 24.0) {
        s << ". The trials are days apart: ballast, battery or thrust map may differ between "
             "sessions; if each session used its own command amplitude, a thrust map wrong in "
             "shape looks the same (compare one amplitude across sessions)";
      }
      return s.str();
    }
    case Effect::kThrustMap: {
      // u = u0·(|u0|/u_ref)^p: at a fifth of the largest command the force is 0.2^p of nominal.
      const double p = f.params.empty() ? 0.0 : f.params[0].value;
      const double fifth = std::pow(0.2, p) - 1.0;
      s << "the delivered force grows as |command|^" << 1.0 + p << ", not in proportion: at a "
        << "fifth of the largest command it is " << Percent(fifth) << (fifth >= 0 ? " above" : " below")
        << " what the thrust map says";
      if (const ErrorGroup* g = Labeled(b.by_command, "small commands (|phi| < 20% of the largest)")) {
        s << " (the standard simulation " << Over(g->relative) << " speed by " << Percent(g->relative)
          << " for small commands)";
      }
      s << ": the thrust map is wrong in shape";
      return s.str();
    }
  }
  return std::string(model::EffectName(f.effect));
}

// Velocity MAE of the free-run simulations of `trials` (pooled over samples).
double PooledMae(const model::DofModel& model, const Eigen::VectorXd& theta,
                 const std::vector<const TrialData*>& trials, double step_s) {
  ValidationOptions vo;
  vo.step_s = step_s;
  double sum = 0.0;
  int n = 0;
  for (const TrialData* t : trials) {
    const TrialFit fit = ValidateTrial(model, theta, *t, vo);
    sum += fit.velocity_mae * fit.velocity_samples;
    n += fit.velocity_samples;
  }
  return n ? sum / n : std::nan("");
}

// The gain of going from model `before` to `after` (issue #5 step 4): the free-run velocity
// MAE on the validate trials, or by 2-fold cross-validation across the fit trials (fit on one
// half, score on the other, both ways) when none is marked.
DiagnosisGain HeldOutGain(const model::Vehicle& vehicle, const StructureFit& before,
                          const StructureFit& after, const std::vector<const TrialData*>& fit,
                          const std::vector<const TrialData*>& validate,
                          const OutputErrorOptions& oe) {
  DiagnosisGain g;
  if (!validate.empty()) {
    g.on = "validate";
    g.before = PooledMae(*before.model, before.oe.theta, validate, oe.step_s);
    g.after = PooledMae(*after.model, after.oe.theta, validate, oe.step_s);
  } else {
    g.on = "cross-validation";
    std::vector<const TrialData*> folds[2];
    for (std::size_t k = 0; k < fit.size(); ++k) folds[k % 2].push_back(fit[k]);
    double sum_b = 0, sum_a = 0;
    int parts = 0;
    for (int k = 0; k < 2; ++k) {
      if (folds[k].empty() || folds[1 - k].empty()) continue;
      const StructureFit fb =
          FitStructure(vehicle, before.structure, folds[1 - k], before.values, before.dropped, oe);
      const StructureFit fa =
          FitStructure(vehicle, after.structure, folds[1 - k], after.values, after.dropped, oe);
      sum_b += PooledMae(*fb.model, fb.oe.theta, folds[k], oe.step_s);
      sum_a += PooledMae(*fa.model, fa.oe.theta, folds[k], oe.step_s);
      ++parts;
    }
    g.before = parts ? sum_b / parts : std::nan("");
    g.after = parts ? sum_a / parts : std::nan("");
  }
  g.relative = g.before > 0 ? (g.before - g.after) / g.before : 0.0;
  return g;
}

// Errors in variables: a coupling term multiplies the logged velocities of other DOFs into the
// force, and their sensor noise (σ_a, the vehicle file's velocity sensors) scatters the
// estimates beyond the output-error covariance, which takes inputs as exact (on hidden-coupling
// draws the coupling coefficient fell outside 3 output-error σ in 25 of 195). To first order
// θ̂(a + ε) − θ̂(a) is linear in the noise ε, so refitting with the logs' other-DOF velocities
// perturbed by fresh draws of the same noise (seeded) spreads as the noise already in them:
//   Cov_eiv = (1/R)·Σ_r (θ̂_r − θ̂)(θ̂_r − θ̂)ᵀ,   Cov = Cov_oe + Cov_eiv.
void AddInputNoiseCovariance(const model::Campaign& campaign, const std::vector<const TrialData*>& fit,
                             const TrialDataOptions& data, const OutputErrorOptions& oe,
                             int replicates, std::uint64_t seed, StructureFit* f,
                             std::vector<std::string>* notes) {
  const model::Vehicle& vehicle = campaign.vehicle;
  const Dof own = f->structure.dof;
  std::map<Dof, double> noise;  // other DOF -> velocity sensor σ
  for (const std::string& pair : f->structure.coupling) {
    for (char letter : pair) {
      for (Dof d : model::kAllDofs) {
        if (d == own || model::VelocityLetter(d) != letter) continue;
        const auto it = vehicle.sensors.find(d);
        if (it == vehicle.sensors.end() || !it->second.velocity) {
          notes->push_back(std::string(model::DofName(own)) + ": the vehicle file declares no " +
                           std::string(model::DofName(d)) +
                           " velocity sensor; the coupling's σ ignore the noise of its log");
          return;
        }
        noise[d] = it->second.velocity->sigma;
      }
    }
  }
  if (noise.empty() || replicates < 2) return;
  const int np = static_cast<int>(f->oe.theta.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(np, np);
  int used = 0;
  for (int r = 0; r < replicates; ++r) {
    std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(r) + 1);
    std::vector<std::unique_ptr<TrialData>> perturbed;
    std::vector<const TrialData*> trials;
    for (const TrialData* t : fit) {
      model::TrialEntry e = campaign.trials[t->index];
      for (const auto& [d, sigma] : noise) {
        std::normal_distribution<double> draw(0.0, sigma);
        for (double& v : e.log.velocity[Index(d)]) {
          if (std::isfinite(v)) v += draw(rng);
        }
      }
      perturbed.push_back(std::make_unique<TrialData>(PrepareTrial(e, t->index, vehicle, data)));
      trials.push_back(perturbed.back().get());
    }
    const StructureFit g = FitStructure(vehicle, f->structure, trials, f->values, f->dropped, oe);
    if (!g.oe.ok() || g.oe.theta.size() != np) continue;
    const Eigen::VectorXd d = g.oe.theta - f->oe.theta;
    cov += d * d.transpose();
    ++used;
  }
  if (used < replicates / 2) {
    notes->push_back(std::string(model::DofName(own)) +
                     ": refits with perturbed other-DOF velocities failed; the coupling's σ "
                     "ignore the noise of their logs");
    return;
  }
  cov /= used;
  f->oe.covariance += cov;
  const auto& names = f->model->parameter_names();
  for (auto& e : f->oe.estimates) {
    const auto it = std::find(names.begin(), names.end(), e.name);
    if (it == names.end() || e.state != ParameterState::kEstimated) continue;
    const int i = static_cast<int>(it - names.begin());
    e.sigma = std::sqrt(f->oe.covariance(i, i));
  }
  std::ostringstream s;
  s << model::DofName(own) << ": σ include the noise of the logged velocities the coupling uses ("
    << used << " refits with that noise redrawn)";
  notes->push_back(s.str());
}

}  // namespace

DiagnosisResult Diagnose(const model::Campaign& campaign, const DiagnoseOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("diagnose", error);
  DiagnosisResult result;
  const model::Vehicle& vehicle = campaign.vehicle;

  // Prepared trials, by DOF.
  std::vector<std::unique_ptr<TrialData>> prepared;
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    prepared.push_back(std::make_unique<TrialData>(
        PrepareTrial(campaign.trials[i], static_cast<int>(i), vehicle, options.identify.data)));
  }
  std::vector<Dof> dofs = options.dofs;
  if (dofs.empty()) {
    for (const auto& t : prepared) {
      if (t->use == model::TrialUse::kFit &&
          std::find(dofs.begin(), dofs.end(), t->dof) == dofs.end()) {
        dofs.push_back(t->dof);
      }
    }
  }

  // 1. The standard model of the contract, identified as `identify` would.
  IdentifyOptions nominal_options = options.identify;
  nominal_options.dofs = dofs;
  for (Dof dof : dofs) {
    std::vector<std::string> mappings;
    std::set<int> ballast;
    for (const auto& t : prepared) {
      if (t->dof != dof || t->use != model::TrialUse::kFit) continue;
      for (const auto& m : t->mappings_used) {
        if (std::find(mappings.begin(), mappings.end(), m) == mappings.end()) mappings.push_back(m);
      }
      ballast.insert(t->ballast_steps);
    }
    nominal_options.structures[dof] = NominalStructure(vehicle, dof, mappings, ballast.size() > 1);
  }
  result.nominal = Identify(campaign, nominal_options);
  const bool campaign_clock =
      std::all_of(campaign.trials.begin(), campaign.trials.end(),
                  [](const model::TrialEntry& e) { return e.has_start; });

  for (Dof dof : dofs) {
    const DofIdentification* nominal = result.nominal.Find(dof);
    if (!nominal || nominal->theta.size() == 0) {
      result.notes.push_back(std::string(model::DofName(dof)) +
                             ": the standard model could not be identified; nothing to diagnose");
      continue;
    }
    std::vector<const TrialData*> fit, validate;
    for (const auto& t : prepared) {
      if (t->dof != dof) continue;
      (t->use == model::TrialUse::kFit ? fit : validate).push_back(t.get());
    }
    // Structures are compared with every parameter free: a parameter that model selection
    // dropped from one stage (e.g. a small bias invisible to steady-state regression but not to
    // integrated positions) would otherwise bias the comparison.
    Values start;
    const std::set<std::string> dropped;
    for (std::size_t i = 0; i < nominal->parameter_names.size(); ++i) {
      start[nominal->parameter_names[i]] = nominal->theta[i];
    }
    const OutputErrorOptions& oe = options.output_error;
    StructureFit current = FitStructure(vehicle, nominal->structure, fit, start, dropped, oe);
    if (std::getenv("UUVPLAN_VERBOSE")) {
      std::fprintf(stderr, "base fit: status %s it %d cost %g N %d P %d msg %s\n",
                   std::string(OutputErrorStatusName(current.oe.status)).c_str(),
                   current.oe.iterations, current.oe.cost, current.oe.num_residuals,
                   current.free_parameters, current.oe.message.c_str());
      for (const auto& n : current.oe.notes) std::fprintf(stderr, "  note %s\n", n.c_str());
    }
    if (!current.oe.ok()) {
      result.notes.push_back(std::string(model::DofName(dof)) +
                             ": output-error fit of the standard model failed (" +
                             current.oe.message + "); nothing to diagnose");
      continue;
    }
    std::vector<const TrialData*> all = fit;
    all.insert(all.end(), validate.begin(), validate.end());
    const ErrorBreakdown breakdown =
        Breakdown(vehicle, *current.model, current.oe.theta, all, oe.step_s, campaign_clock);
    if (!campaign_clock && std::count(options.candidates.begin(), options.candidates.end(),
                                      Effect::kParameterDrift)) {
      result.notes.push_back(std::string(model::DofName(dof)) +
                             ": parameter_drift not tested: the campaign gives no `start` time "
                             "for every trial, so the campaign clock is unknown");
    }
    if (nominal->closed_loop_suspected) {
      result.warnings.push_back(
          std::string(model::DofName(dof)) +
          ": closed-loop data suspected (see the identification's warning): the logged force "
          "reacts to the motion through a controller, so an effect found here may describe the "
          "loop rather than the vehicle (a controller's delay looks like sensor_delay or "
          "thruster_lag, its gains like drag or a thrust-map shape); confirm with open-loop "
          "trials");
    }
    result.breakdowns.push_back(breakdown);

    // 2–3. Greedy forward selection of significant effects.
    std::vector<Finding> found;
    std::set<Effect> used;
    for (int round = 0; round < options.max_effects; ++round) {
      struct Significant {
        Candidate candidate;
        StructureFit fit;
        std::size_t test;  // index in result.tests
      };
      std::vector<Significant> significant;
      for (Effect effect : options.candidates) {
        if (used.count(effect)) continue;
        for (const Candidate& c : CandidatesFor(effect, vehicle, current, fit, campaign_clock)) {
          Values s = current.values;
          for (const auto& [n, v0] : c.start) s[n] = v0;
          StructureFit ext = FitStructure(vehicle, c.structure, fit, s, current.dropped, oe);
          CandidateTest t = Test(c, current, ext, round);
          t.significant = t.p_value < options.significance && t.max_z >= options.min_z;
          result.tests.push_back(t);
          if (t.significant) significant.push_back({c, std::move(ext), result.tests.size() - 1});
        }
      }
      // Strongest evidence first; the first that also predicts held-out data better is taken.
      std::stable_sort(significant.begin(), significant.end(), [&](const auto& a, const auto& b) {
        return result.tests[a.test].statistic > result.tests[b.test].statistic;
      });
      const Significant* chosen = nullptr;
      DiagnosisGain chosen_gain;
      for (const Significant& sig : significant) {
        const DiagnosisGain g = HeldOutGain(vehicle, current, sig.fit, fit, validate, oe);
        result.tests[sig.test].gain = g.relative;
        if (g.relative >= options.min_gain) {
          chosen = &sig;
          chosen_gain = g;
          result.tests[sig.test].accepted = true;
          break;
        }
      }
      if (!chosen) break;
      const Candidate& c = chosen->candidate;
      const CandidateTest& best_test = result.tests[chosen->test];
      Finding f;
      f.effect = c.effect;
      f.dof = dof;
      f.statistic = best_test.statistic;
      f.added_parameters = best_test.added_parameters;
      f.p_value = best_test.p_value;
      f.gain = chosen_gain;
      for (const std::string& name : c.added) {
        const int k = FindEstimate(chosen->fit.oe.estimates, name);
        if (k >= 0) f.params.push_back(chosen->fit.oe.estimates[k]);
      }
      f.what = What(f, breakdown, c.detail);
      used.insert(c.effect);
      current = chosen->fit;
      found.push_back(f);
    }

    if (!current.structure.coupling.empty()) {
      AddInputNoiseCovariance(campaign, fit, options.identify.data, oe,
                              options.input_noise_replicates, options.seed, &current,
                              &result.notes);
      // Every finding reports its parameters as the final extended model estimates them.
      for (Finding& f : found) {
        for (ParameterEstimate& p : f.params) {
          const int k = FindEstimate(current.oe.estimates, p.name);
          if (k >= 0) p = current.oe.estimates[k];
        }
      }
    }
    result.findings.insert(result.findings.end(), found.begin(), found.end());

    DofIdentification ext = *nominal;
    ext.structure = current.structure;
    ext.parameter_names = current.model->parameter_names();
    ext.theta = current.oe.theta;
    ext.covariance = current.oe.covariance;
    ext.params = current.oe.estimates;
    ext.estimator = FinalEstimator::kOutputError;
    result.extended.push_back(ext);
  }
  std::stable_sort(result.findings.begin(), result.findings.end(),
                   [](const Finding& a, const Finding& b) { return a.gain.relative > b.gain.relative; });
  return result;
}

}  // namespace uuvplan::ident
