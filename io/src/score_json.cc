#include "uuvplan/io/score_json.h"

#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/text/score_notes_text.h"

namespace uuvplan::io {

using nlohmann::json;

json ScoreJson(const ident::ScoreResult& r, const std::string& vehicle,
               const std::string& campaign) {
  json trials = json::array(), dofs = json::object();
  for (const ident::TrialScore& s : r.trials) {
    const ident::TrialFit& t = s.fit;
    trials.push_back({{"file", t.name},
                      {"dof", std::string(model::DofName(s.dof))},
                      {"use", std::string(model::TrialUseName(t.use))},
                      {"velocity_mae", JsonNumber(t.velocity_mae)},
                      {"velocity_samples", t.velocity_samples},
                      {"position_rms", JsonNumber(t.position_rms)},
                      {"position_samples", t.position_samples}});
  }
  for (const ident::DofScore& d : r.dofs) {
    dofs[std::string(model::DofName(d.dof))] = {
        {"velocity_mae_fit", JsonNumber(d.velocity_mae_fit)},
        {"velocity_mae_validate", JsonNumber(d.velocity_mae_validate)},
        {"velocity_mae_all", JsonNumber(d.velocity_mae_all)},
        {"samples_fit", d.samples_fit},
        {"samples_validate", d.samples_validate},
        {"problem", d.problem}};
  }
  return {{"vehicle", vehicle},
          {"campaign", campaign},
          {"trials", trials},
          {"dofs", dofs},
          {"notes", text::NoteTexts(r.notes)}};
}

}  // namespace uuvplan::io
