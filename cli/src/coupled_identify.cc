#include "uuvplan/cli/coupled_identify.h"

#include <iostream>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/ident/estimators/joint_ls.h"
#include "uuvplan/io/joint_ls_json.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::cli {

using text::Quantity;
using text::TextTable;

int RunCoupledIdentify(const model::Campaign& campaign, const std::string& campaign_path,
                       const std::string& json_path) {
  std::vector<const model::TrialLog*> logs;
  for (const model::TrialEntry& t : campaign.trials) {
    if (t.use == model::TrialUse::kFit) logs.push_back(&t.log);
  }
  const ident::JointLsResult r = ident::JointOneStepLeastSquares(
      model::CoupledHorizontalModel(campaign.vehicle), logs, ident::JointLsOptions{});
  std::ostream& out = ReportStream(json_path);
  out << "Identification of " << campaign_path << " (vehicle '" << campaign.vehicle.name << "', "
      << logs.size() << " combined-mode trial(s); coupled horizontal model, seed 003; one-step "
      << (r.instrumental ? "instrumental-variable" : "least-squares") << " estimate)\n\n";
  if (r.ok() || r.status == ident::JointLsStatus::kNonPhysical) {
    TextTable table({"DOF", "parameter", "value", "σ", "state"});
    for (std::size_t j = 0; j < r.names.size(); ++j) {
      const std::string& name = r.names[j];
      const auto dot = name.find('.');
      table.AddRow({name.substr(0, dot), name.substr(dot + 1),
                    Quantity(r.theta[static_cast<Eigen::Index>(j)], r.units[j], 4),
                    Quantity(r.Sigma(static_cast<int>(j)), r.units[j], 3),
                    r.IsDropped(static_cast<int>(j)) ? "dropped" : "estimated"});
    }
    table.Print(out);
    out << "\n  " << r.num_rows << " integral rows; coupling from the inertias: surge m_v·v·r, "
        << "sway −m_u·u·r, yaw (m_u − m_v)·u·v\n";
    for (const auto& d : r.dropped) {
      out << "  dropped " << r.names[d.index] << " = " << Quantity(d.value, r.units[d.index], 4)
          << " ± " << Quantity(d.sigma, r.units[d.index], 3)
          << ": negative and insignificant (seed 000 §IV-D, 51.02%); the other drag term of its "
             "DOF takes its part, so that term assumes the trials' speeds\n";
    }
  }
  for (const std::string& note : r.notes) out << "  note: " << note << "\n";
  if (!r.ok())
    out << "  FAILED (" << ident::kJointLsStatusNames.Name(r.status) << "): " << r.message << "\n";
  if (!json_path.empty()) WriteJson(json_path, io::JointLsJson(r, model::kCoupledModelName));
  return r.ok() ? kExitOk : kExitActionNeeded;
}

}  // namespace uuvplan::cli
