// Errors in variables: a coupling term multiplies the logged velocities of other DOFs into the
// force, and their sensor noise (σ_a, the vehicle file's velocity sensors) scatters the
// estimates beyond the output-error covariance, which takes inputs as exact (on hidden-coupling
// draws the coupling coefficient fell outside 3 output-error σ in 25 of 195). To first order
// θ̂(a + ε) − θ̂(a) is linear in the noise ε, so refitting with the logs' other-DOF velocities
// perturbed by fresh draws of the same noise (seeded) spreads as the noise already in them:
//   Cov_eiv = (1/R)·Σ_r (θ̂_r − θ̂)(θ̂_r − θ̂)ᵀ,   Cov = Cov_oe + Cov_eiv.
#include <cmath>
#include <optional>
#include <random>

#include "diagnosis_internal.h"
#include "parallel.h"

namespace uuvplan::ident::diagnosis {

namespace {

using model::Dof;

// Velocity sensor σ of each other DOF a coupling term reads; false (and a note) when the
// vehicle file declares no such sensor.
bool LoggedVelocityNoise(const model::Vehicle& vehicle, const model::ModelStructure& s,
                         std::map<Dof, double>* noise, std::vector<DiagnosisNote>* notes) {
  for (const std::string& parameter : s.WithPrefix(model::param::kCouplingPrefix)) {
    for (char letter : model::Qualifier(parameter)) {
      for (Dof d : model::kAllDofs) {
        if (d == s.dof || model::VelocityLetter(d) != letter) continue;
        const auto it = vehicle.sensors.find(d);
        if (it == vehicle.sensors.end() || !it->second.velocity) {
          notes->push_back({DiagnosisNoteKind::kNoCouplingSensor,
                            s.dof,
                            {std::string(model::DofName(d))},
                            {},
                            {}});
          return false;
        }
        (*noise)[d] = it->second.velocity->sigma;
      }
    }
  }
  return true;
}

// The fit trials with their other-DOF velocities redrawn with replicate r's noise.
std::vector<std::unique_ptr<TrialData>> Perturbed(const model::Campaign& campaign,
                                                  const Trials& fit,
                                                  const std::map<Dof, double>& noise,
                                                  const TrialDataOptions& data, std::uint64_t seed,
                                                  int r) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(r) + 1);
  std::vector<std::unique_ptr<TrialData>> out;
  for (const TrialData* t : fit) {
    model::TrialEntry e = campaign.trials[t->index];
    for (const auto& [d, sigma] : noise) {
      std::normal_distribution<double> draw(0.0, sigma);
      for (double& v : e.log.velocity[Index(d)]) {
        if (std::isfinite(v)) v += draw(rng);
      }
    }
    out.push_back(std::make_unique<TrialData>(PrepareTrial(e, t->index, campaign.vehicle, data)));
  }
  return out;
}

void UpdateSigmas(StructureFit* f) {
  const auto& names = f->model->parameter_names();
  for (auto& e : f->oe.estimates) {
    const auto it = std::find(names.begin(), names.end(), e.name);
    if (it == names.end() || e.state != ParameterState::kEstimated) continue;
    const int i = static_cast<int>(it - names.begin());
    e.sigma = std::sqrt(f->oe.covariance(i, i));
  }
}

}  // namespace

void AddInputNoiseCovariance(const model::Campaign& campaign, const Trials& fit,
                             const TrialDataOptions& data, const OutputErrorOptions& oe,
                             int replicates, std::uint64_t seed, int threads, StructureFit* f,
                             std::vector<DiagnosisNote>* notes) {
  std::map<Dof, double> noise;
  if (!LoggedVelocityNoise(campaign.vehicle, f->structure, &noise, notes)) return;
  if (noise.empty() || replicates < 2) return;
  const int np = static_cast<int>(f->oe.theta.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(np, np);
  int used = 0;
  // The refits are independent (replicate r draws from its own stream): run in parallel, each
  // into its slot, and summed in order.
  std::vector<std::optional<Eigen::VectorXd>> refit(replicates);
  ParallelFor(replicates, threads, [&](std::size_t r) {
    const auto perturbed = Perturbed(campaign, fit, noise, data, seed, static_cast<int>(r));
    Trials trials;
    for (const auto& t : perturbed) trials.push_back(t.get());
    const StructureFit g =
        FitStructure(campaign.vehicle, f->structure, trials, f->values, f->dropped, oe, f->held);
    if (g.oe.ok() && g.oe.theta.size() == np) refit[r] = g.oe.theta;
  });
  for (const auto& theta : refit) {
    if (!theta) continue;
    const Eigen::VectorXd d = *theta - f->oe.theta;
    cov += d * d.transpose();
    ++used;
  }
  if (used < replicates / 2) {
    notes->push_back({DiagnosisNoteKind::kInputNoiseRefitsFailed, f->structure.dof, {}, {}, {}});
    return;
  }
  f->oe.covariance += cov / used;
  UpdateSigmas(f);
  notes->push_back({DiagnosisNoteKind::kInputNoiseIncluded,
                    f->structure.dof,
                    {},
                    {static_cast<double>(used)},
                    {}});
}

}  // namespace uuvplan::ident::diagnosis
