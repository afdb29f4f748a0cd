#include "uuvplan/cli/coupled_schedule.h"

#include <cmath>
#include <iostream>

#include "uuvplan/cli/command.h"
#include "uuvplan/io/combined_design_json.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/coupled_design.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::cli {
namespace {

using text::Quantity;
using text::TextTable;

void PrintInputs(const planner::CombinedDesign& d, std::ostream& out) {
  TextTable table({"DOF", "mapping", "offset", "amplitude", "ω", "period"});
  for (const model::TrialDesign& in : d.trial.inputs) {
    const std::string unit(model::ForceUnit(in.dof));
    table.AddRow({std::string(model::DofName(in.dof)), in.mapping, Quantity(in.offset, unit, 4),
                  Quantity(in.amplitude, unit, 4), Quantity(in.omega, "rad/s", 3),
                  Quantity(2 * M_PI / in.omega, "s", 3)});
  }
  table.Print(out);
}

void PrintCramerRao(const planner::CombinedDesign& d, std::ostream& out) {
  TextTable table({"parameter", "worst σ over the box", "σ / value"});
  for (std::size_t c = 0; c < d.parameters.size(); ++c) {
    const double rel = d.worst_relative_sigma[c];
    table.AddRow({d.parameters[c], Quantity(d.worst_sigma[c], d.units[c], 3),
                  std::isfinite(rel) ? model::Significant(100 * rel, 3) + " %" : "-"});
  }
  table.Print(out);
}

}  // namespace

int RunCoupledSchedule(const model::Vehicle& vehicle, const model::Pool& pool,
                       const planner::CombinedDesignOptions& options,
                       const std::string& json_path) {
  const model::MultiDofModel coupled = model::CoupledHorizontalModel(vehicle);
  const planner::CombinedDesign d = planner::PlanCombinedDesign(coupled, vehicle, pool, options);
  const int surge = coupled.DofIndex(model::Dof::kSurge),
            sway = coupled.DofIndex(model::Dof::kSway);
  const auto &x = d.envelope.travel[surge], &y = d.envelope.travel[sway];
  std::ostream& out = ReportStream(json_path);
  out << "Combined " << model::DofList(options.dofs) << " sine trial for " << vehicle.name
      << " in pool " << pool.name << " (coupled horizontal model, seed 003; "
      << model::Significant(options.duration_s, 4)
      << " s, robust over the a priori box): " << (d.fits ? "fits" : "DOES NOT FIT") << "\n\n";
  PrintInputs(d, out);
  out << "\n  start: " << model::Significant(d.start[surge], 3)
      << " m from the wall behind the vehicle, " << model::Significant(d.start[sway], 3)
      << " m from the wall on its negative-sway side, heading "
      << "along the pool's length\n  track over the box: " << model::Significant(x[1] - x[0], 3)
      << " m × " << model::Significant(y[1] - y[0], 3) << " m of the free "
      << model::Significant(pool.FreeTravel(model::Dof::kSurge), 3) << " m × "
      << model::Significant(pool.FreeTravel(model::Dof::kSway), 3) << " m; heading "
      << model::Significant(d.envelope.turns, 3) << " turns (tether "
      << model::Significant(pool.max_turns, 3) << "); thrusters "
      << model::Significant(d.envelope.thrust_margin, 3)
      << " N above min_thrust at their weakest (negative: one comes too near zero or reverses), at "
         "most "
      << model::Significant(100 * d.envelope.thrust_load, 3) << "% of their limit\n\nCramér–Rao σ ("
      << planner::kCoupledSigmaAssumption << "):\n";
  PrintCramerRao(d, out);
  for (const std::string& note : d.notes) out << "  note: " << note << "\n";
  if (d.envelope.turns > 1.0) {
    out << "  note: the offsets keep every thruster one way while the swings change sign, so the "
           "vehicle spins; under a spin of one sign the yaw drag terms and bias are nearly "
           "collinear — take the drags from steady runs (`schedule --model dof`) and this trial "
           "for the inertias that carry the coupling\n";
  }
  for (const std::string& r : d.reasons) out << "  DOES NOT FIT: " << r << "\n";
  if (!json_path.empty()) {
    const io::CombinedModelText text{model::kCoupledModelName, planner::kCoupledSigmaAssumption};
    WriteJson(json_path, io::CombinedDesignJson(d, coupled, vehicle, pool, text));
  }
  return d.fits ? kExitOk : kExitActionNeeded;
}

}  // namespace uuvplan::cli
