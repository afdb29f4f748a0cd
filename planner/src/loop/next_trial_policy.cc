// The next-trial policy of the design–identify loop (next_trial_policy.h, design_loop.h).
#include "loop/next_trial_policy.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

#include "loop/loop_trust.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/parallel.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner::internal {
namespace {

using model::Dof;
using Direction = std::pair<std::string, int>;  // (mapping, sign ±1)

constexpr const char* kAPrioriSource = "a priori schedule";
constexpr const char* kKnownModelSource = "design about the vehicle file's model";

int Sign(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// The trial's id as a campaign names it: the file stem ("trials/surge-sine.csv" → "surge-sine").
std::string EntryId(const model::TrialEntry& e) {
  return std::filesystem::path(e.file).stem().string();
}

// Estimates of a DOF as DesignNextTrial wants them (box centre, and prior information from the
// covariance, rows in `names` order): the values the data decided — estimated, or dropped to 0
// as insignificant. An estimate is left out (the design keeps the a priori value, without prior
// information on it) when it is an a priori fallback (held, not reliable: never information),
// insignificant (percentile error above `max_percent`: its ±2σ box would span zero) or
// non-physical (NonPhysical; m above twice the upper a priori inertia bound or below
// LeastInertia): a diverged fit must not steer the design, e.g. to a time constant of
// milliseconds (which the planner refuses, DofPlanningProblem).
void DesignInputs(const model::Vehicle& vehicle, const ident::DofIdentification& id,
                  double max_percent, ParameterValues* estimates, std::vector<std::string>* names,
                  Eigen::MatrixXd* covariance, std::vector<std::string>* notes) {
  const double m_max = 2.0 * vehicle.InertiaBounds(id.dof)[1];
  const double m_min = LeastInertia(vehicle, id.dof);
  std::vector<int> idx;
  for (std::size_t j = 0; j < id.params.size(); ++j) {
    const ident::ParameterEstimate& p = id.params[j];
    if (p.state == ident::ParameterState::kDropped) (*estimates)[p.name] = p.value;
    if (p.state != ident::ParameterState::kEstimated) continue;
    if (!(std::isfinite(p.sigma) && p.sigma > 0 && std::isfinite(p.value))) continue;
    const double percent = p.value != 0.0 ? 100.0 * p.sigma / std::abs(p.value)
                                          : std::numeric_limits<double>::infinity();
    const bool nuisance = p.name == model::param::kBias || p.name == model::param::kBiasStep;
    if (Held(id, p.name)) {
      notes->push_back(p.name + " = " + model::Significant(p.value, 3) +
                       " is not reliable (an a priori fallback): the design keeps its a priori "
                       "value");
      continue;
    }
    std::string wrong = NonPhysical(vehicle, id.dof, p.name, p.value);
    if (wrong.empty() && p.name == model::param::kMass && p.value > m_max) {
      wrong = "m = " + model::Significant(p.value, 3) +
              " is implausible (above twice the a priori bound)";
    }
    if (wrong.empty() && p.name == model::param::kMass && p.value < m_min) {
      wrong = "m = " + model::Significant(p.value, 3) + " is implausible (below " +
              model::Significant(m_min, 3) + " " + model::Unit(p.name, id.dof) +
              ", the least physical inertia: the dry mass, or half the vehicle file's rigid "
              "inertia for a rotation)";
    }
    if (!wrong.empty()) {
      notes->push_back(wrong + ": the design keeps its a priori value");
      continue;
    }
    if (!nuisance && !(percent < max_percent)) {
      notes->push_back(p.name + " = " + model::Significant(p.value, 3) + " ± " +
                       model::Significant(p.sigma, 3) +
                       " is insignificant: the design keeps its a priori value");
      continue;
    }
    (*estimates)[p.name] = p.value;
    names->push_back(p.name);
    idx.push_back(static_cast<int>(j));
  }
  const bool full = id.covariance.rows() == static_cast<int>(id.params.size()) &&
                    id.covariance.cols() == static_cast<int>(id.params.size());
  if (full) {
    *covariance = ident::SubMatrix(id.covariance, idx);
    return;
  }
  const int n = static_cast<int>(idx.size());
  *covariance = Eigen::MatrixXd::Zero(n, n);
  for (int a = 0; a < n; ++a) {
    const double sigma = id.params[idx[a]].sigma;
    (*covariance)(a, a) = sigma * sigma;
  }
}
// The (mapping, direction) pairs a logged trial pushed in: the sign of its force_<dof> column
// on every row, with the row's mapping (the `mapping` column, else the trial's).
std::set<Direction> PushedDirections(const model::TrialEntry& e) {
  std::set<Direction> out;
  const auto& f = e.log.force[model::Index(e.dof)];
  for (std::size_t i = 0; i < f.size(); ++i) {
    const int s = Sign(f[i]);
    if (std::isnan(f[i]) || s == 0) continue;
    std::string m = e.mapping;
    if (i < e.log.mapping.size() && e.log.mapping[i] >= 0 &&
        e.log.mapping[i] < static_cast<int>(e.log.mapping_names.size())) {
      m = e.log.mapping_names[e.log.mapping[i]];
    }
    out.insert({m, s});
  }
  return out;
}

// The open-water directions of a DOF's mappings that its thrusters can hold: the reference of
// the installation coefficients (ref 000 §II-A: η must be known for at least one mapping).
std::vector<Direction> OpenWaterDirections(const model::Vehicle& v, Dof dof) {
  std::vector<Direction> out;
  for (int i : v.MappingsOf(dof)) {
    const model::ThrustMapping& m = v.mappings[i];
    if (m.IsOpenWater(model::Direction::kPos) && DirectionForceRange(v, i, +1).feasible) {
      out.push_back({m.name, +1});
    }
    if (m.IsOpenWater(model::Direction::kNeg) && DirectionForceRange(v, i, -1).feasible) {
      out.push_back({m.name, -1});
    }
  }
  return out;
}

std::string DirectionName(const Direction& d) {
  return d.first + (d.second > 0 ? " pushing positive" : " pushing negative");
}
// The next trial of one DOF, or a reason why there is none. In this order:
//   1. No trial of the DOF has pushed in an open-water direction yet: one that does — without
//      that reference the installation coefficients cannot be told from the inertia and the drag
//      (ref 000 §II-A, eq. 3 is homogeneous in θ), and the estimates of m and k absorb η.
//   2. An installation coefficient of interest is not estimated yet: a trial pushing in its
//      mapping and direction. The D criterion of DesignNextTrial does not ask for it by itself:
//      it scores the parameters a trial reaches, and refining m with another open-water sine can
//      score higher than opening a new direction.
//   For 1 and 2 the a priori schedule's first trial that does it is taken (ref 000 order),
//   else DesignNextTrial with its sine restricted to that mapping and direction.
//   3. Estimates not usable yet (m or the drag of interest insignificant): the a priori
//      schedule, in order (ref 000 §III: steady runs, then the sine).
//   4. DesignNextTrial on all the DOF's parameters (box = estimates ± 2σ, prior = C⁻¹).
// A DOF whose model the vehicle file gives with σ (identified, or a payload on an identified
// base) takes DesignNextTrial's trial about that model before its estimates are usable, when the
// trial's predicted σ make them usable; else it follows the order above.
class DofTrialPolicy {
 public:
  DofTrialPolicy(Planner& planner, const model::Campaign& campaign, const DofProgress& progress,
                 Decision* decision)
      : planner_(planner),
        campaign_(campaign),
        progress_(progress),
        dof_(progress.dof),
        name_(model::DofName(progress.dof)),
        d_(decision) {}

  bool Plan(const ident::DofIdentification* id, std::string* why) {
    ReadHistory();
    ChooseWanted();
    ReadEstimates(id);
    if (KnownModel() && !progress_.usable && SequentialFirst()) return true;
    for (const Direction& w : want_) {
      if (const PlannedTrial* t = PendingPushing(w)) {
        return TakeAPriori(*t, DirectionName(w) + ": " + want_why_);
      }
    }
    if (!progress_.usable && !pending_.empty() && want_.empty()) {
      return TakeAPriori(*pending_.front(),
                         progress_.trials == 0 ? "no trial yet" : NotUsableYet());
    }
    if (schedule_->status == PlanStatus::kInfeasible && progress_.trials == 0) {
      *why = name_ + ": " + schedule_->message;
      return false;
    }
    const NextTrialOptions next = SequentialOptions();
    if (DesignForWanted(next, why)) return true;
    if (!progress_.usable && !pending_.empty()) {
      return TakeAPriori(*pending_.front(), NotUsableYet());
    }
    const NextTrialResult nt = Design(next, "sequential design", why);
    if (nt.status == DesignStatus::kOk) return Accept(nt);
    if (!pending_.empty()) return TakeAPriori(*pending_.front(), "the sequential design failed");
    return false;
  }

  // The planned trial's predicted σ at the current estimates (the centre of the design's box;
  // the design's own prediction is the worst over the box, pessimistic by design: on ROMEO
  // surge in a 5 m pool it predicted σ(kq) down 29% where the trial achieved 78%).
  PredictedPrecision AtEstimates() const { return PrecisionAt({d_->trial}, true); }

  // The predicted σ after `trials` at the current estimates (the box's centre), with the
  // information of the estimates so far as prior (`with_estimates`) or none.
  PredictedPrecision PrecisionAt(const std::vector<PlannedTrial>& trials,
                                 bool with_estimates) const {
    std::vector<std::string> notes;
    const auto probe = DofPlanningProblem::APriori(planner_.vehicle, planner_.pool, dof_,
                                                   planner_.options.schedule.planner, &notes);
    ParameterBox centre;
    centre.nominal = probe->box().nominal;
    for (const auto& [name, value] : estimates_) {
      if (centre.nominal.count(name)) centre.nominal[name] = value;
    }
    const DofPlanningProblem ctx(planner_.vehicle, planner_.pool, dof_, std::move(centre),
                                 planner_.options.schedule.planner);
    // The identification fixes what it dropped as insignificant (ref 000 §IV-D model
    // selection): so does the prediction, by a prior 1000× tighter than its σ before the drop
    // (k dropped leaves kq alone to explain the drag; left free, k and kq are confounded and
    // the predicted gain on kq was 10× too small).
    std::vector<std::string> names = names_;
    for (const auto& [name, sigma] : dropped_) {
      if (ctx.Index(name) >= 0) names.push_back(name);
    }
    Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(names.size(), names.size());
    covariance.topLeftCorner(names_.size(), names_.size()) = covariance_;
    for (std::size_t i = names_.size(), j = 0; i < names.size(); ++j) {
      if (ctx.Index(dropped_[j].first) < 0) continue;
      covariance(i, i) = std::pow(1e-3 * dropped_[j].second, 2);
      ++i;
    }
    PriorInformation prior;
    if (!names.empty()) prior = PriorInformation::FromCovariance(names, covariance);
    const PriorInformation* p = with_estimates && !names.empty() ? &prior : nullptr;
    return PredictPrecision(ctx, TrialsInformation(ctx, trials, p));
  }

  // Trials like this one to bring a parameter of value `value` to the target. One not determined
  // yet (σ_now = ∞) that this trial determines — a first estimate, or one below the usable
  // percentile error — counts as one trial: the next is planned from that estimate, so the rate
  // of identical trials does not apply. Otherwise that rate (TrialsToTarget, whose limit for
  // σ_now = ∞ is (σ_after/σ_target)²).
  void SetTrialsToTarget(double value, CandidateGain* g) const {
    const auto& o = planner_.options;
    g->first_estimate =
        std::isinf(g->sigma_now) && std::isfinite(g->sigma_after) &&
        (!std::isfinite(value) || g->sigma_after < o.usable_percent / 100 * std::abs(value));
    g->trials_to_target = g->first_estimate
                              ? 1.0
                              : TrialsToTarget(g->sigma_now, g->sigma_after,
                                               o.target_percent / 100 * std::abs(value));
  }

  // The planned trial's predicted gain (CandidateGain): the parameter of interest above the
  // target it brings nearest to the target, at the current estimates.
  CandidateGain Gain() {
    d_->at_estimates = AtEstimates();
    CandidateGain best;
    best.dof = dof_;
    best.trial = d_->trial.design.id;
    best.trials_to_target = std::numeric_limits<double>::infinity();
    for (const auto& q : progress_.interest) {
      if (q.percent <= planner_.options.target_percent) continue;
      CandidateGain g;
      g.dof = dof_;
      g.trial = best.trial;
      g.parameter = q.name;
      const auto after = d_->at_estimates.sigma.find(q.name);
      g.sigma_after = after != d_->at_estimates.sigma.end()
                          ? after->second
                          : std::numeric_limits<double>::infinity();  // the trial does not reach it
      const auto known = std::find(names_.begin(), names_.end(), q.name);
      const int i = static_cast<int>(known - names_.begin());
      g.sigma_now = known != names_.end() ? std::sqrt(covariance_(i, i))
                                          : std::numeric_limits<double>::infinity();
      SetTrialsToTarget(q.value, &g);
      g.gain = std::isinf(g.sigma_now) ? (std::isfinite(g.sigma_after) ? 1.0 : 0.0)
                                       : 1.0 - g.sigma_after / g.sigma_now;
      if (!(g.trials_to_target >= best.trials_to_target)) best = g;
    }
    // The a priori schedule's trials are designed as a set (ref 000: steady runs at several
    // levels, then the sine): one alone may inform nothing, and each runs once. So are the
    // first trials about a model the vehicle file gives (SequentialFirst: taken only when
    // they make the estimates usable).
    // A trial with no parameter above the target to bring down (every one below it but not
    // confirmed, or nothing estimated yet) is not judged by a gain it cannot have.
    best.negligible = d_->source != kAPrioriSource && d_->source != kKnownModelSource &&
                      !best.parameter.empty() &&
                      !(best.trials_to_target <= planner_.options.max_trials_to_target);
    return best;
  }

 private:
  // The DOF's trials run so far (by id), the directions its fit trials pushed in, and the a
  // priori schedule's trials not run yet, in ref 000 order.
  void ReadHistory() {
    std::set<std::string> run;
    for (const auto& e : campaign_.trials) {
      if (e.dof != dof_) continue;
      run.insert(EntryId(e));
      if (e.use == model::TrialUse::kFit) {
        for (const auto& p : PushedDirections(e)) pushed_.insert(p);
      }
    }
    schedule_ = &planner_.APriori(dof_);
    for (const auto& t : schedule_->schedule.trials) {
      if (t.design.dof == dof_ && !run.count(t.design.id)) pending_.push_back(&t);
    }
  }

  // Steps 1 and 2: the directions a trial should push in, and why.
  void ChooseWanted() {
    const auto open_water = OpenWaterDirections(planner_.vehicle, dof_);
    reference_ = std::any_of(open_water.begin(), open_water.end(),
                             [&](const auto& p) { return pushed_.count(p) > 0; });
    if (!reference_ && !open_water.empty()) {
      want_ = open_water;
      want_why_ = "no open-water run yet: the reference of the installation coefficients";
      return;
    }
    for (const auto& q : progress_.interest) {
      if (!q.estimated && model::StartsWith(q.name, model::param::kEtaPrefix)) {
        want_.push_back(EtaDirection(q.name));
      }
    }
    want_why_ = "its installation coefficient is not estimated yet";
  }

  void ReadEstimates(const ident::DofIdentification* id) {
    if (id == nullptr || id->status == ident::IdentifyStatus::kFailed) return;
    std::vector<std::string> input_notes;
    DesignInputs(planner_.vehicle, *id, planner_.options.usable_percent, &estimates_, &names_,
                 &covariance_, &input_notes);
    for (const auto& n : input_notes) d_->notes.push_back(name_ + ": " + n);
    for (const auto& p : id->params) {
      if (p.state == ident::ParameterState::kDropped && std::isfinite(p.sigma_before_drop) &&
          p.sigma_before_drop > 0) {
        dropped_.push_back({p.name, p.sigma_before_drop});
      }
    }
  }

  // The vehicle file gives the DOF's model with σ (identified, or a payload on an identified
  // base): its box (parameter_box.h PlanningBox) is narrow enough to design in before any
  // estimate is usable.
  bool KnownModel() const {
    const auto model = planner_.vehicle.models.find(dof_);
    return model != planner_.vehicle.models.end() && model->second.identified();
  }

  // The sequential design about the vehicle file's model (steps 1, 2 and 4): designed with the
  // file's σ as prior information where the data have no usable estimate yet (its box the
  // file's ± estimate_sigmas σ), taken when the information of the DOF's trials so far and this
  // one alone, at the model's values, makes m and the drag usable (the identification uses no
  // prior); else the a priori schedule, whose steady runs at several levels tell k from kq
  // where one trial cannot (e.g. in a narrow pool).
  bool SequentialFirst() {
    const Decision before = *d_;
    const auto data_names = names_;
    const Eigen::MatrixXd data_covariance = covariance_;
    AddFilePrior();
    NextTrialOptions next = SequentialOptions();
    next.box_sigmas = planner_.options.schedule.planner.box.estimate_sigmas;
    std::string why;
    bool designed = DesignForWanted(next, &why);
    if (!designed) {
      const NextTrialResult nt = Design(next, "design about the vehicle file's model", &why);
      designed = nt.status == DesignStatus::kOk && Accept(nt);
    }
    names_ = data_names;
    covariance_ = data_covariance;
    if (!designed) return Restore(before, why);
    d_->source = kKnownModelSource;
    std::vector<PlannedTrial> trials = planner_.run[dof_];
    trials.push_back(d_->trial);
    if (MakesUsable(PrecisionAt(trials, false))) return true;
    return Restore(before,
                   "the design about the vehicle file's model would leave m or the "
                   "drag unusable after it");
  }

  // The file's σ, as a diagonal covariance, of the parameters the data have no usable estimate
  // of (names_ and covariance_ extended; estimates_ keeps the data's values where it has them).
  void AddFilePrior() {
    const model::DofParameters& model = planner_.vehicle.models.at(dof_);
    std::vector<std::pair<std::string, double>> added;
    for (const auto& [name, sigma] : model.sigma) {
      const bool known = std::find(names_.begin(), names_.end(), name) != names_.end();
      if (!known && sigma > 0 && model.params.count(name)) added.push_back({name, sigma});
    }
    const auto n = static_cast<Eigen::Index>(names_.size());
    const auto total = n + static_cast<Eigen::Index>(added.size());
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(total, total);
    c.topLeftCorner(n, n) = covariance_;
    for (std::size_t i = 0; i < added.size(); ++i) {
      names_.push_back(added[i].first);
      estimates_.emplace(added[i].first, model.params.at(added[i].first));
      c(n + static_cast<Eigen::Index>(i), n + static_cast<Eigen::Index>(i)) =
          added[i].second * added[i].second;
    }
    covariance_ = c;
  }

  // m and the drag (kq, or k where the file's kq is 0) predicted within the usable percentile
  // error of the file's values.
  bool MakesUsable(const PredictedPrecision& predicted) const {
    const model::DofParameters& model = planner_.vehicle.models.at(dof_);
    const auto within = [&](const std::string& name) {
      const auto value = model.params.find(name);
      const auto sigma = predicted.sigma.find(name);
      return value != model.params.end() && sigma != predicted.sigma.end() &&
             sigma->second < planner_.options.usable_percent / 100 * std::abs(value->second);
    };
    const auto kq = model.params.find(model::param::kQuadraticDrag);
    const bool quadratic = kq != model.params.end() && kq->second != 0.0;
    return within(model::param::kMass) &&
           within(quadratic ? model::param::kQuadraticDrag : model::param::kLinearDrag);
  }

  bool Restore(const Decision& before, const std::string& why) {
    *d_ = before;
    d_->notes.push_back(name_ + ": " + why + ": the a priori schedule");
    return false;
  }

  const PlannedTrial* PendingPushing(const Direction& w) const {
    for (const PlannedTrial* t : pending_) {
      if (t->design.Pushes(w.first, w.second)) return t;
    }
    return nullptr;
  }

  std::string NotUsableYet() const {
    return "estimates not usable yet: " + progress_.worst + " at " +
           model::Significant(progress_.worst_percent, 3) + "%";
  }

  bool TakeAPriori(const PlannedTrial& t, const std::string& why_this) {
    d_->dof = dof_;
    d_->source = kAPrioriSource;
    d_->trial = t;
    // Predicted precision after this trial: its information over the a priori box plus the
    // prior information of the estimates so far (what DesignNextTrial reports for its trials).
    std::vector<std::string> ctx_notes;
    const std::unique_ptr<DofPlanningProblem> ctx = DofPlanningProblem::APriori(
        planner_.vehicle, planner_.pool, dof_, planner_.options.schedule.planner, &ctx_notes);
    PriorInformation prior;
    if (!names_.empty()) prior = PriorInformation::FromCovariance(names_, covariance_);
    d_->predicted =
        PredictPrecision(*ctx, TrialsInformation(*ctx, {t}, names_.empty() ? nullptr : &prior));
    d_->notes.push_back(name_ + ": a priori trial '" + t.design.id + "' (" + why_this + ")");
    return true;
  }

  // DesignNextTrial's options for this DOF, with a fresh id: the DOF and the trial's number in
  // the campaign, unique among its files.
  NextTrialOptions SequentialOptions() const {
    NextTrialOptions no = planner_.options.next;
    no.schedule = planner_.options.schedule;
    no.schedule.dofs = {dof_};
    no.schedule.prior.clear();
    std::set<std::string> ids;
    for (const auto& e : campaign_.trials) ids.insert(EntryId(e));
    int k = static_cast<int>(campaign_.trials.size()) + 1;
    do {
      std::ostringstream os;
      os << name_ << "-next-" << (k < 10 ? "0" : "") << k;
      no.id = os.str();
      ++k;
    } while (ids.count(no.id));
    return no;
  }

  // Without any usable estimate the covariance is empty: no prior information, the a priori
  // box (PriorInformation::FromCovariance).
  NextTrialResult Design(const NextTrialOptions& o, const std::string& what, std::string* why) {
    const NextTrialResult nt =
        DesignNextTrial(planner_.vehicle, planner_.pool, dof_, estimates_, names_, covariance_, o);
    for (const auto& n : nt.notes) d_->notes.push_back(name_ + ": " + n);
    if (nt.status != DesignStatus::kOk) {
      d_->notes.push_back(name_ + ": " + what + ": " + std::string(DesignStatusName(nt.status)) +
                          ": " + nt.message);
      *why = name_ + ": " + nt.message;
    }
    return nt;
  }

  // Steps 1 and 2 by DesignNextTrial, its sine restricted to each wanted direction in turn.
  bool DesignForWanted(const NextTrialOptions& next, std::string* why) {
    for (const Direction& w : want_) {
      NextTrialOptions o = next;
      o.schedule.sine.mappings = {w.first};
      o.schedule.sine.sign = w.second;
      // An open-water direction needs no prior; another is no longer confounded with m once the
      // reference trials have informed m (the prior information of the design).
      o.schedule.sine.open_water_only = !reference_;
      const std::string what = "sequential design for " + DirectionName(w);
      const NextTrialResult nt = Design(o, what, why);
      if (nt.status == DesignStatus::kOk && nt.trial.design.Pushes(w.first, w.second)) {
        d_->notes.push_back(name_ + ": " + what + " (" + want_why_ + ")");
        return Accept(nt);
      }
      if (nt.status == DesignStatus::kOk) {
        d_->notes.push_back(name_ + ": " + what + " gave a trial that does not push that way");
      }
    }
    return false;
  }

  bool Accept(const NextTrialResult& nt) {
    d_->dof = dof_;
    d_->source = "sequential design";
    d_->trial = nt.trial;
    d_->predicted = nt.predicted;
    return true;
  }

  Planner& planner_;
  const model::Campaign& campaign_;
  const DofProgress& progress_;
  const Dof dof_;
  const std::string name_;
  Decision* d_;
  const ScheduleResult* schedule_ = nullptr;
  std::set<Direction> pushed_;
  std::vector<const PlannedTrial*> pending_;
  std::vector<Direction> want_;
  std::string want_why_;
  bool reference_ = false;
  ParameterValues estimates_;
  std::vector<std::pair<std::string, double>> dropped_;  ///< name, σ before the drop
  std::vector<std::string> names_;
  Eigen::MatrixXd covariance_ = Eigen::MatrixXd(0, 0);
};

// A DOF's trials stop: the DOF with its stop's kind and reason, in the message's words.
void AddStop(Dof dof, NextStatus kind, const std::string& reason, Decision* d) {
  d->stops.push_back({dof, kind, reason});
}

// The decision when no DOF that needs a trial gets one: infeasible before refused before stuck
// (the pool verdict first; then what no trial can fix; then what this pool cannot).
void NoTrial(Decision* d) {
  d->status = NextStatus::kStuck;
  for (const auto& s : d->stops) {
    if (s.kind == NextStatus::kInfeasible) d->status = NextStatus::kInfeasible;
    if (s.kind == NextStatus::kRefused && d->status != NextStatus::kInfeasible) {
      d->status = NextStatus::kRefused;
    }
  }
  std::ostringstream m;
  m << (d->status == NextStatus::kInfeasible ? "no trial can be planned for the DOFs still "
                                               "above the target:"
        : d->status == NextStatus::kRefused  ? "no convergence claimed:"
                                             : "stuck: no trial this pool allows adds enough "
                                               "information:");
  for (const auto& s : d->stops) m << " " << s.reason << ";";
  d->message = m.str();
}

std::string ConvergedMessage(const DesignLoopOptions& options) {
  return "every parameter of interest is below " + model::Significant(options.target_percent, 3) +
         "% percentile error, physical, not an a priori fallback, validated and consistent "
         "with the estimate before its newest trial: no further trial needed";
}

}  // namespace

bool Plannable(const model::Vehicle& v, Dof dof) {
  const auto s = v.sensors.find(dof);
  const bool sensed = s != v.sensors.end() && (s->second.position || s->second.velocity);
  return sensed && !v.MappingsOf(dof).empty();
}

void RequirePlannable(const model::Vehicle& v, Dof dof, const std::string& where) {
  const std::string name(model::DofName(dof));
  if (v.MappingsOf(dof).empty()) {
    throw model::InputError(where, "vehicle '" + v.name + "' has no thrust mapping on " + name +
                                       ": the loop cannot excite it (add a mapping, or drop " +
                                       "--dof " + name + ")");
  }
  const auto s = v.sensors.find(dof);
  if (s == v.sensors.end() || (!s->second.position && !s->second.velocity)) {
    throw model::InputError(where, "vehicle '" + v.name + "' has no " + name + " sensor (sensors." +
                                       name + "): nothing to identify it from");
  }
}

std::pair<std::string, int> EtaDirection(const std::string& name) {
  const std::string rest = name.substr(std::string(model::param::kEtaPrefix).size());
  const std::size_t dot = rest.rfind('.');
  return {rest.substr(0, dot), rest.substr(dot + 1) == "pos" ? +1 : -1};
}

const ScheduleResult& Planner::APriori(Dof dof) {
  auto it = schedules.find(dof);
  if (it != schedules.end()) return it->second;
  Prepare({dof});
  return schedules.at(dof);
}

void Planner::Prepare(const std::vector<Dof>& dofs) {
  std::vector<Dof> missing;
  for (Dof dof : dofs) {
    if (!schedules.count(dof)) missing.push_back(dof);
  }
  std::vector<ScheduleResult> planned(missing.size());
  model::ParallelFor(missing.size(), Threads(), [&](std::size_t i) {
    ScheduleOptions so = options.ScheduleAtTarget();
    so.dofs = {missing[i]};
    so.prior.clear();
    planned[i] = PlanSchedule(vehicle, pool, so);
  });
  for (std::size_t i = 0; i < missing.size(); ++i) {
    schedules.emplace(missing[i], std::move(planned[i]));
  }
}

std::vector<Dof> DofsOrTruths(const model::Truth& truth, const std::vector<Dof>& asked) {
  if (!asked.empty()) return asked;
  std::vector<Dof> dofs;
  for (Dof dof : model::kAllDofs) {
    if (truth.dofs.count(dof)) dofs.push_back(dof);
  }
  return dofs;
}

int FitTrials(const model::Campaign& campaign, Dof dof) {
  int trials = 0;
  for (const auto& e : campaign.trials) {
    if (e.dof == dof && e.use == model::TrialUse::kFit) ++trials;
  }
  return trials;
}

void AddModelDoubts(const LoopMemory& memory, DofProgress* p) {
  const auto doubts = memory.model_doubts.find(p->dof);
  if (doubts == memory.model_doubts.end() || doubts->second.empty()) return;
  p->doubts.insert(p->doubts.end(), doubts->second.begin(), doubts->second.end());
  p->trusted = false;
  p->converged = false;
}

model::Campaign DofCampaign(const model::Campaign& campaign, const model::Vehicle& vehicle,
                            Dof dof) {
  model::Campaign sub;
  sub.path = campaign.path;
  sub.vehicle_file = campaign.vehicle_file;
  sub.vehicle = vehicle;
  sub.pool_file = campaign.pool_file;
  sub.pool = campaign.pool;
  for (const auto& e : campaign.trials) {
    if (e.dof == dof) sub.trials.push_back(e);
  }
  return sub;
}

bool PlanCandidate(Planner& planner, const model::Campaign& campaign, const DofProgress& progress,
                   const ident::DofIdentification* id, Decision* d, CandidateGain* gain,
                   std::string* why) {
  DofTrialPolicy policy(planner, campaign, progress, d);
  if (!policy.Plan(id, why)) return false;
  *gain = policy.Gain();
  return true;
}

namespace {

// One DOF's candidate trial, planned on its own (PlanCandidate into an empty Decision): the
// candidates of several DOFs can be planned at once and taken in Decide's order after.
struct PolicyCandidate {
  bool planned = false;
  Decision part;  ///< what the policy decided (trial, predictions, notes)
  CandidateGain gain;
  std::string why;  ///< why there is none, when not planned
};

// `d` with the candidate's trial and notes, as PlanCandidate on `d` itself leaves it.
Decision WithCandidate(const Decision& d, const PolicyCandidate& c) {
  Decision tried = d;
  for (const auto& n : c.part.notes) tried.notes.push_back(n);
  tried.dof = c.part.dof;
  tried.source = c.part.source;
  tried.trial = c.part.trial;
  tried.predicted = c.part.predicted;
  tried.at_estimates = c.part.at_estimates;
  return tried;
}

// Plans the candidates open[from..] of the next Threads() DOFs at once (their a priori
// schedules first): one batch of the candidates Decide may need. Returns the batch's end.
std::size_t PlanBatch(Planner& planner, const model::Campaign& campaign,
                      const ident::IdentifyResult& estimates,
                      const std::vector<const DofProgress*>& open, std::size_t from,
                      std::vector<PolicyCandidate>* out) {
  const std::size_t to = std::min(open.size(), from + model::Workers(planner.Threads()));
  std::vector<Dof> dofs;
  for (std::size_t i = from; i < to; ++i) dofs.push_back(open[i]->dof);
  planner.Prepare(dofs);
  model::ParallelFor(to - from, planner.Threads(), [&](std::size_t k) {
    PolicyCandidate& c = (*out)[from + k];
    const DofProgress& p = *open[from + k];
    c.planned =
        PlanCandidate(planner, campaign, p, estimates.Find(p.dof), &c.part, &c.gain, &c.why);
  });
  return to;
}

// Each DOF's progress towards the target, judged against the loop's memory of it.
std::vector<DofProgress> ProgressOfEach(const Planner& planner, const model::Campaign& campaign,
                                        const std::vector<Dof>& dofs,
                                        const ident::IdentifyResult& estimates,
                                        const LoopMemory& memory) {
  std::vector<DofProgress> progress;
  for (Dof dof : dofs) {
    const auto prev = memory.previous.find(dof);
    progress.push_back(EvaluateProgress(planner.vehicle, dof, estimates.Find(dof),
                                        FitTrials(campaign, dof), planner.options,
                                        prev == memory.previous.end() ? nullptr : &prev->second));
    AddModelDoubts(memory, &progress.back());
  }
  return progress;
}

// The DOFs not converged, furthest above the target first; ties keep the order of `progress`.
std::vector<const DofProgress*> FurthestFirst(const std::vector<DofProgress>& progress) {
  std::vector<const DofProgress*> order;
  for (const auto& p : progress) {
    if (!p.converged) order.push_back(&p);
  }
  std::stable_sort(order.begin(), order.end(), [](const DofProgress* a, const DofProgress* b) {
    return a->worst_percent > b->worst_percent;
  });
  return order;
}

// A DOF without a candidate trial stops: infeasible (the pool verdict's answer: no trial for a
// DOF that has none yet), or stuck when its trials ran in this pool and no further trial fits
// (at its estimates ± 2σ): held by a limit of this pool, with what stops the next trial.
void StopUnplanned(const DofProgress& p, const PolicyCandidate& c, Decision* d) {
  const std::string name(model::DofName(p.dof));
  if (p.trials > 0) {
    AddStop(p.dof, NextStatus::kStuck,
            c.why + " (after " + std::to_string(p.trials) + " trial(s) of " + name +
                " in this pool; a larger pool or a wider thrust range lifts it)",
            d);
  } else {
    AddStop(p.dof, NextStatus::kInfeasible, c.why, d);
  }
}

// Why the trial `tried` is next: its DOF is the furthest from the target.
std::string NextTrialMessage(const DofProgress& p, const Decision& tried) {
  std::ostringstream m;
  m << model::DofName(p.dof) << " is furthest from the target (" << p.worst
    << (std::isfinite(p.worst_percent) ? " at " + model::Significant(p.worst_percent, 3) + "%"
                                       : std::string(" not estimated yet"))
    << (p.precise && !p.doubts.empty() ? ", not trusted yet: " + p.doubts.front() : "")
    << "): " << tried.source << " trial '" << tried.trial.design.id << "'";
  return m.str();
}

}  // namespace

Decision Decide(Planner& planner, const model::Campaign& campaign, const std::vector<Dof>& dofs,
                const ident::IdentifyResult& estimates, const LoopMemory& memory) {
  Decision d;
  d.progress = ProgressOfEach(planner, campaign, dofs, estimates, memory);
  const std::vector<const DofProgress*> order = FurthestFirst(d.progress);
  if (order.empty()) {
    d.status = NextStatus::kConverged;
    d.message = ConvergedMessage(planner.options);
    return d;
  }
  // The DOFs that get a candidate (not stopped, not refused), planned in batches of Threads().
  std::vector<const DofProgress*> open;
  for (const DofProgress* p : order) {
    if (!memory.stopped.count(p->dof) && p->refusal.empty()) open.push_back(p);
  }
  std::vector<PolicyCandidate> candidates(open.size());
  std::size_t next = 0;  // the next entry of `open`; those before it are planned
  for (const DofProgress* p : order) {
    const std::string name(model::DofName(p->dof));
    if (const auto s = memory.stopped.find(p->dof); s != memory.stopped.end()) {
      AddStop(p->dof, s->second.kind, name + ": " + s->second.reason, &d);
      continue;
    }
    if (!p->refusal.empty()) {
      AddStop(p->dof, NextStatus::kRefused, name + ": " + p->refusal, &d);
      continue;
    }
    const std::size_t i = std::find(open.begin(), open.end(), p) - open.begin();
    if (i >= next) next = PlanBatch(planner, campaign, estimates, open, i, &candidates);
    const PolicyCandidate& c = candidates[i];
    Decision tried = WithCandidate(d, c);
    if (!c.planned) {
      d.notes = tried.notes;
      StopUnplanned(*p, c, &d);
      continue;
    }
    const CandidateGain& gain = c.gain;
    tried.candidates.push_back(gain);
    if (gain.negligible && !p->precise) {
      d.notes = tried.notes;
      d.candidates = tried.candidates;
      AddStop(p->dof, NextStatus::kStuck,
              StuckReason(planner, campaign, *p, estimates.Find(p->dof), tried.trial, gain), &d);
      continue;
    }
    // Before `d` is replaced: `p` points into d.progress.
    std::string message = NextTrialMessage(*p, tried);
    d = std::move(tried);
    d.status = NextStatus::kTrial;
    d.message = std::move(message);
    return d;
  }
  NoTrial(&d);
  return d;
}

}  // namespace uuvplan::planner::internal
