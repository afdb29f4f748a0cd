#include "support/effect_design.h"

#include <cmath>
#include <utility>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/parameter.h"

namespace uuvplan::testing {

LagCase MakeFrameLagCase(model::Truth frame, model::Pool pool, double lag) {
  LagCase c{std::move(frame), {}, std::move(pool)};
  model::DofTruth& surge = c.truth.dofs.at(model::Dof::kSurge);
  surge.params[model::param::kLag] = lag;
  model::DofParameters written;
  written.params = surge.params;
  for (const auto& [name, value] : written.params) {
    if (name != model::param::kBiasStep) written.sigma[name] = 0.03 * std::abs(value) + 1e-3;
  }
  written.sigma[model::param::kLag] = 0.015;
  c.identified = c.truth.vehicle;
  c.identified.models[model::Dof::kSurge] = written;
  return c;
}

std::vector<LagEstimate> IdentifiedLags(const LagCase& c,
                                        const std::vector<model::TrialDesign>& designs,
                                        std::uint64_t first, int n) {
  std::vector<LagEstimate> out;
  for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(n); ++seed) {
    model::VirtualCampaignOptions vo;
    vo.seed = seed;
    model::Campaign campaign = model::BuildVirtualCampaign(c.truth, designs, vo);
    campaign.vehicle = c.identified;  // the file `identify` reads: its model has the lag
    ident::IdentifyOptions options;
    options.dofs = {model::Dof::kSurge};
    const ident::IdentifyResult r = ident::Identify(campaign, options);
    if (r.status == ident::IdentifyStatus::kFailed) continue;
    for (const ident::ParameterEstimate& p : r.dofs.at(0).params) {
      if (p.name == model::param::kLag) out.push_back({p.value, p.sigma});
    }
  }
  return out;
}

}  // namespace uuvplan::testing
