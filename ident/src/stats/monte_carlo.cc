#include "uuvplan/ident/stats/monte_carlo.h"

#include <cmath>
#include <map>
#include <tuple>

#include "diagnosis/parallel.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/seed.h"

namespace uuvplan::ident {
namespace {

struct Acc {
  int n = 0, covered = 0, within3 = 0;
  double sum = 0, sum2 = 0, sum_sigma = 0;
  double truth = 0, crb = 0;
};

}  // namespace

model::Campaign VirtualCampaign(const model::Truth& truth,
                                const std::vector<model::TrialDesign>& designs, std::uint64_t seed,
                                const std::vector<model::TrialUse>& uses, double pause_s,
                                double command_rate_hz) {
  model::VirtualCampaignOptions o;
  o.seed = seed;
  o.uses = uses;
  o.pause_s = pause_s;
  o.command_rate_hz = command_rate_hz;
  return model::BuildVirtualCampaign(truth, designs, o);
}

double TrueParameter(const model::Truth& truth, model::Dof dof, const std::string& name) {
  const auto it = truth.dofs.find(dof);
  if (it != truth.dofs.end()) {
    if (auto p = it->second.params.find(name); p != it->second.params.end()) return p->second;
    if (name == model::param::kLinearDragNeg)
      return TrueParameter(truth, dof, model::param::kLinearDrag);
    if (name == model::param::kQuadraticDragNeg)
      return TrueParameter(truth, dof, model::param::kQuadraticDrag);
  }
  return name.rfind(model::param::kEtaPrefix, 0) == 0 ? 1.0 : 0.0;
}

bool MonteCarloOptions::IsValid(std::string* error) const {
  if (repetitions < 1 || !(z > 0)) {
    if (error) *error = "MonteCarloOptions: repetitions >= 1 and z > 0";
    return false;
  }
  return identify.IsValid(error);
}

const CoverageCell* MonteCarloReport::Find(const std::string& estimator, model::Dof dof,
                                           const std::string& name) const {
  for (const auto& c : cells) {
    if (c.estimator == estimator && c.dof == dof && c.name == name) return &c;
  }
  return nullptr;
}

namespace {

using CellKey = std::tuple<std::string, int, std::string>;  // estimator, DOF index, parameter

// Coverage counts of every (estimator, DOF, parameter), in the order first seen.
class CoverageTally {
 public:
  CoverageTally(const model::Truth& truth, double z) : truth_(truth), z_(z) {}

  void Add(const std::string& estimator, model::Dof dof, const ParameterEstimate& e) {
    if (e.state != ParameterState::kEstimated || !(e.sigma > 0) || !std::isfinite(e.value)) return;
    const CellKey key = std::make_tuple(estimator, model::Index(dof), e.name);
    auto [it, inserted] = acc_.try_emplace(key);
    if (inserted) order_.push_back(key);
    Acc& a = it->second;
    a.truth = TrueParameter(truth_, dof, e.name);
    const double err = std::abs(e.value - a.truth);
    ++a.n;
    if (err <= z_ * e.sigma) ++a.covered;
    if (err <= 3.0 * e.sigma) ++a.within3;
    a.sum += e.value;
    a.sum2 += e.value * e.value;
    a.sum_sigma += e.sigma;
  }

  // Every estimator's estimates of one DOF; false if the DOF failed.
  // Every DOF with an estimate is tallied, a `failed` one too (e.g. kq < 0 by more than 3σ
  // when the truth is on the bound): leaving those out would keep the good repetitions only
  // and overstate the coverage. A DOF without any estimate is a failure.
  bool AddDof(const DofIdentification& d) {
    if (d.estimator == FinalEstimator::kNone) return false;
    if (d.steady && d.steady->ok()) {
      for (const auto& e : d.steady->estimates) Add("steady_state", d.dof, e);
    }
    if (d.inertia && d.inertia->ok()) Add("integral_inertia", d.dof, d.inertia->estimate);
    if (d.one_step && d.one_step->ok()) {
      for (const auto& e : d.one_step->estimates) Add("one_step_ls", d.dof, e);
    }
    if (d.output_error && d.output_error->ok()) {
      for (const auto& e : d.output_error->estimates) Add("output_error", d.dof, e);
    }
    for (const auto& e : d.params) Add("final", d.dof, e);
    return true;
  }

  std::vector<CoverageCell> Cells(const std::map<std::pair<int, std::string>, double>& crb) const {
    std::vector<CoverageCell> cells;
    for (const auto& key : order_) {
      const Acc& a = acc_.at(key);
      CoverageCell c;
      c.estimator = std::get<0>(key);
      c.dof = static_cast<model::Dof>(std::get<1>(key));
      c.name = std::get<2>(key);
      c.truth = a.truth;
      c.n = a.n;
      c.covered = a.covered;
      c.within3 = a.within3;
      c.mean = a.sum / a.n;
      c.sd = a.n > 1 ? std::sqrt(std::max(0.0, (a.sum2 - a.sum * a.sum / a.n) / (a.n - 1))) : 0.0;
      c.mean_sigma = a.sum_sigma / a.n;
      if (c.estimator == "output_error" || c.estimator == "final") {
        if (auto it = crb.find({std::get<1>(key), c.name}); it != crb.end())
          c.crb_sigma = it->second;
      }
      cells.push_back(c);
    }
    return cells;
  }

 private:
  const model::Truth& truth_;
  double z_;
  std::map<CellKey, Acc> acc_;
  std::vector<CellKey> order_;
};

// Cramér–Rao bound at the truth for the output-error parameters (same sample times and
// nuisance parameters as the fit): √CRB by (DOF index, parameter).
std::map<std::pair<int, std::string>, double> CramerRaoSigmas(const model::Truth& truth,
                                                              const model::Campaign& campaign,
                                                              const IdentifyResult& res,
                                                              const MonteCarloOptions& o) {
  std::map<std::pair<int, std::string>, double> crb;
  std::vector<TrialData> trials;
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    trials.push_back(
        PrepareTrial(campaign.trials[i], static_cast<int>(i), campaign.vehicle, o.identify.data));
  }
  for (const DofIdentification& d : res.dofs) {
    if (!d.output_error || !d.output_error->ok()) continue;
    const model::DofModel model(campaign.vehicle, d.structure);
    std::vector<const TrialData*> fit;
    for (const auto& t : trials) {
      if (t.dof == d.dof && t.use == model::TrialUse::kFit) fit.push_back(&t);
    }
    Eigen::VectorXd theta(model.num_parameters());
    for (int j = 0; j < model.num_parameters(); ++j) {
      theta[j] = TrueParameter(truth, d.dof, model.parameter_names()[j]);
    }
    // Truth: every trial starts at rest; the position offset is a nuisance.
    std::vector<TrialInitialState> init;
    for (const auto& s : d.output_error->initial) {
      TrialInitialState t = s;
      t.xi0 = 0.0;
      init.push_back(t);
    }
    const Eigen::MatrixXd C =
        CramerRaoBound(model, fit, theta, d.output_error->state, init, o.identify.output_error);
    for (int j = 0; j < model.num_parameters(); ++j) {
      if (C(j, j) > 0) crb[{model::Index(d.dof), model.parameter_names()[j]}] = std::sqrt(C(j, j));
    }
  }
  return crb;
}

}  // namespace

MonteCarloReport RunMonteCarlo(const model::Truth& truth,
                               const std::vector<model::TrialDesign>& designs,
                               const MonteCarloOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw model::InputError("Monte Carlo options", error);
  MonteCarloReport report;
  report.repetitions = o.repetitions;
  model::VirtualCampaignOptions virtual_pool;
  virtual_pool.uses = o.uses;
  virtual_pool.pause_s = o.pause_s;
  auto pool_of = [&](int rep) {
    model::VirtualCampaignOptions v = virtual_pool;
    v.seed = model::SplitMix64(o.seed + 0x1000 * static_cast<std::uint64_t>(rep));
    return v;
  };
  // Repetitions in parallel, each into its own slot; tallied in order below.
  struct Slot {
    IdentifyResult result;
    std::string error;  ///< what Identify or the virtual pool threw
  };
  std::vector<Slot> slots(o.repetitions);
  IdentifyOptions identify = o.identify;
  if (o.threads != 1) identify.threads = 1;  // the repetitions share the cores
  diagnosis::ParallelFor(slots.size(), o.threads, [&](std::size_t rep) {
    try {
      slots[rep].result =
          Identify(model::BuildVirtualCampaign(truth, designs, pool_of(int(rep))), identify);
    } catch (const std::exception& ex) {
      slots[rep].error = ex.what();
    }
  });
  CoverageTally tally(truth, o.z);
  std::map<std::pair<int, std::string>, double> crb;
  bool crb_done = false;
  for (int rep = 0; rep < o.repetitions; ++rep) {
    const Slot& s = slots[rep];
    if (!s.error.empty()) {
      ++report.failures;
      if (report.notes.size() < 5)
        report.notes.push_back("repetition " + std::to_string(rep) + ": " + s.error);
      continue;
    }
    for (const DofIdentification& d : s.result.dofs) {
      if (!tally.AddDof(d)) ++report.failures;
    }
    if (o.cramer_rao && !crb_done) {
      crb_done = true;  // the first good repetition's campaign, rebuilt from its seed
      crb = CramerRaoSigmas(truth, model::BuildVirtualCampaign(truth, designs, pool_of(rep)),
                            s.result, o);
    }
  }
  report.cells = tally.Cells(crb);
  return report;
}

}  // namespace uuvplan::ident
