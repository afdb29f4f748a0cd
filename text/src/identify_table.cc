// The `identify` result as a readable table (docs/cli.md), shared by the commands that print
// identification results (identify, next, loop, diagnose).
#include "uuvplan/text/identify_table.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"
#include "uuvplan/text/trial_notes_text.h"

namespace uuvplan::text {
namespace {

// The parameters of a DOF: value, σ (each with its unit), percentile error and significance.
void PrintParameters(const ident::DofIdentification& d, std::ostream& out) {
  TextTable table({"DOF", "parameter", "value", "σ", "error (%)", "significance"});
  for (const auto& e : d.params) {
    std::string sig;
    double value = e.value, sigma = e.sigma;
    switch (e.state) {
      case ident::ParameterState::kEstimated:
        sig = e.significant ? "significant" : "NOT significant (> 51.02%)";
        break;
      case ident::ParameterState::kDropped:
        sig = "dropped (insignificant, set to 0)";
        value = e.value_before_drop;
        sigma = e.sigma_before_drop;
        break;
      case ident::ParameterState::kFixed:
        sig = "fixed (not estimated)";
        break;
    }
    if (std::find(d.unreliable.begin(), d.unreliable.end(), e.name) != d.unreliable.end()) {
      sig += "; NOT RELIABLE (see warnings)";
    }
    const double pe =
        e.state == ident::ParameterState::kFixed ? std::nan("") : e.percentile_error();
    const std::string unit = model::Unit(e.name, d.dof);
    table.AddRow({std::string(model::DofName(d.dof)), e.name, Quantity(value, unit, 4),
                  Quantity(sigma, unit, 3), Cell(pe, 3), sig});
  }
  table.Print(out);
}

// The fit figures of a DOF, overall and per trial with its residual analysis.
void PrintFit(const ident::DofIdentification& d, std::ostream& out) {
  const auto& f = d.fit;
  // Angles for people in degrees (docs/cli.md); rates stay in rad/s, as the papers report them.
  const bool rotation = model::IsRotational(d.dof);
  const double p_scale = rotation ? 180.0 / M_PI : 1.0;
  const std::string v_unit(model::VelocityUnit(d.dof)), p_unit(rotation ? "°" : "m");
  out << "  fit: velocity MAE (seed 002 eq. 37) fit " << Cell(f.velocity_mae_fit) << ", validate "
      << Cell(f.velocity_mae_validate) << " " << v_unit << " (zero-velocity model "
      << Cell(f.zero_velocity_mae_fit) << ", " << Cell(f.zero_velocity_mae_validate) << " "
      << v_unit << "); position RMS fit " << Cell(p_scale * f.position_rms_fit) << ", validate "
      << Cell(p_scale * f.position_rms_validate) << " " << p_unit << "\n";
  TextTable table({"DOF", "trial", "use", "vel. MAE (" + v_unit + ")", "pos. RMS (" + p_unit + ")",
                   "residuals"});
  for (const auto& t : f.trials) {
    const bool position = t.residual_signal == "position";
    const std::string unit = position ? p_unit : v_unit;
    std::ostringstream res;
    res << t.residual_signal << " mean " << Cell((position ? p_scale : 1.0) * t.residuals.mean, 3)
        << " " << unit << ", " << (t.residuals.white ? "white" : "NOT white") << " ("
        << t.residuals.lags_outside << "/"
        << (t.residuals.autocorrelation.empty() ? 0 : t.residuals.autocorrelation.size() - 1)
        << " lags outside ±" << Cell(t.residuals.bound95, 2) << ")"
        << (t.velocity_reference == "estimated" ? " [velocity estimated from positions]" : "");
    table.AddRow({std::string(model::DofName(d.dof)), t.name,
                  std::string(model::TrialUseName(t.use)), Cell(t.velocity_mae),
                  Cell(p_scale * t.position_rms), res.str()});
  }
  table.Print(out);
}

// The papers' one-step integral LS beside the reported estimate, when that is another's.
void PrintOneStep(const ident::DofIdentification& d, std::ostream& out) {
  if (!d.one_step || !d.one_step->ok()) return;
  if (d.estimator != ident::FinalEstimator::kOneStep) {
    out << "  one-step LS (seed 002 eqs. 20-36, seed 004 eqs. 8-14"
        << (d.one_step->instrumental ? "; instrumental variables" : "") << "):";
    const char* sep = " ";
    for (const auto& e : d.one_step->estimates) {
      out << sep << e.name << " = " << Cell(e.value, 4) << " ± " << Cell(e.sigma, 3)
          << UnitSuffix(model::Unit(e.name, d.dof));
      sep = ", ";
    }
    out << "\n";
  }
  if (d.one_step->standard) {
    const auto& c = d.one_step->seed;
    out << "  one-step LS coefficients (seed 002 eq. 4): alpha " << Cell(c.alpha) << ", beta "
        << Cell(c.beta) << ", gamma " << Cell(c.gamma) << ", delta " << Cell(c.delta) << "\n";
  }
}

// Ref 004 Fig. 11 as a table: the estimated parameters ± σ after the updates at about 10%,
// 25%, 50%, 75% and 100% of the rows (the whole trace is in the JSON).
void PrintRlsConvergence(const ident::DofIdentification& d, std::ostream& out) {
  if (!d.rls || !d.rls->ok()) return;
  const ident::RlsDofResult& r = *d.rls;
  const int steps = static_cast<int>(r.theta.rows());
  std::vector<int> columns;
  std::vector<std::string> titles = {"DOF", "t (s)"};
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    if (r.state[j] != ident::ParameterState::kEstimated) continue;
    columns.push_back(static_cast<int>(j));
    titles.push_back(r.names[j] + " (" + model::Unit(r.names[j], d.dof) + ")");
  }
  out << "  RLS convergence (seed 004 eq. 15, forgetting λ = " << Cell(r.lambda, 6) << ", memory ≈ "
      << (r.lambda < 1 ? Cell(1.0 / (1.0 - r.lambda), 3) : std::string("all")) << " rows), θ ± σ "
      << "after about 10%, 25%, 50%, 75% and all of the " << steps << " rows:\n";
  TextTable table(titles);
  int last = -1;
  for (const double fraction : {0.1, 0.25, 0.5, 0.75, 1.0}) {
    const int k = std::max(0, static_cast<int>(std::ceil(fraction * steps)) - 1);
    if (k == last) continue;
    last = k;
    std::vector<std::string> row = {std::string(model::DofName(d.dof)), Cell(r.psi.t[k], 4)};
    for (int j : columns) row.push_back(Cell(r.theta(k, j), 4) + " ± " + Cell(r.sigma(k, j), 2));
    table.AddRow(row);
  }
  table.Print(out, "    ");
}

void PrintDof(const ident::DofIdentification& d, std::ostream& out) {
  const std::string dof(model::DofName(d.dof));
  out << dof << " (" << ident::IdentifyStatusName(d.status) << ", estimator "
      << ident::FinalEstimatorName(d.estimator) << "; " << d.fit_trials.size() << " fit, "
      << d.validate_trials.size() << " validate trial(s))\n";
  if (d.status == ident::IdentifyStatus::kFailed) out << "  FAILED: " << d.message << "\n";
  PrintParameters(d, out);
  PrintFit(d, out);
  PrintOneStep(d, out);
  PrintRlsConvergence(d, out);
  for (const auto& o : d.outside_prior) {
    out << "  OUTSIDE THE A PRIORI RANGE: " << OutsidePriorText(d.dof, o) << "\n";
  }
  for (const auto& w : d.warnings) out << "  WARNING: " << w << "\n";
  for (const auto& n : d.notes) out << "  note: " << n << "\n";
  out << "\n";
}

// What the data preparation excluded (outliers and gaps per trial), and the trials that moved
// the vehicle in other DOFs too.
void PrintExclusions(const ident::IdentifyResult& r, std::ostream& out) {
  for (const auto& t : r.trials) {
    const std::size_t excluded = t.position_outliers.size() + t.velocity_outliers.size();
    if (excluded == 0 && t.gaps.empty()) continue;
    out << "data: " << t.file << ": " << excluded << " outlier(s) excluded";
    if (excluded > 0) {
      out << " at t =";
      int shown = 0;
      for (const auto* list : {&t.position_outliers, &t.velocity_outliers}) {
        for (const auto& o : *list) {
          if (shown++ < 6) out << " " << Cell(o.t + t.time_offset);
        }
      }
      if (shown > 6) out << " …";
      out << " s";
    }
    out << "; " << t.gaps.size() << " gap(s)\n";
  }
  for (const auto& t : r.trials) {
    const std::string motion = OtherMotionText(t.notes);
    if (!motion.empty()) out << "data: " << t.file << ": " << motion << "\n";
  }
}

// What moves an inertia estimate above or below the truth (ref 000 eq. 5: m·dν/dt = τ − drag,
// so a force logged η⁻¹ times too large gives m/η).
std::string InertiaCauses(model::Dof dof, bool above) {
  if (above) {
    return "the logged force larger than the force that moved the vehicle (an installation loss, "
           "a thrust map too strong or a thruster lag: `uuvplan diagnose` tests these), water "
           "entrained by an open frame or a payload beyond the added_mass range, or motion in "
           "other DOFs during the trials";
  }
  return std::string(
             "the logged force smaller than the force that moved the vehicle (a thrust "
             "map too weak, commands in other units), or the vehicle file's ") +
         (model::IsRotational(dof) ? "inertia too large (one computed from an assumed mass "
                                     "distribution errs by tens of percent)"
                                   : "mass too large");
}

}  // namespace

std::string OutsidePriorText(model::Dof dof, const ident::OutsidePrior& o) {
  const std::string unit = model::Unit(o.parameter, dof);
  const double beyond = o.SigmasBeyond();
  return o.parameter + " = " + ValueSigma(o.value, o.sigma, unit, 4) + " lies " +
         (o.above() ? "above" : "below") + " the vehicle file's a priori range [" +
         model::Significant(o.lo, 4) + ", " + model::Significant(o.hi, 4) + "] " + unit + " (" +
         (model::IsRotational(dof) ? "inertia" : "mass") + " × (1 + added_mass))" +
         (std::isfinite(beyond) ? ", " + model::Significant(beyond, 3) + "σ beyond it" : "") +
         "; likely causes: " + InertiaCauses(dof, o.above());
}

void PrintIdentifyTable(const ident::IdentifyResult& r, std::ostream& out) {
  for (const auto& d : r.dofs) PrintDof(d, out);
  PrintExclusions(r, out);
  out << r.message << " — status " << ident::IdentifyStatusName(r.status) << "\n";
}

}  // namespace uuvplan::text
