// The pool verdict as JSON (pool_verdict_json.h).
#include "uuvplan/io/pool_verdict_json.h"

#include <cmath>
#include <string>

#include "uuvplan/text/verdict_text.h"

namespace uuvplan::io {
namespace {

// A free travel along a DOF: {"free", "unit"} and, for a translation, "wall_to_wall"; for a
// rotation "turns". +inf (no pool lifts the limit) is null.
nlohmann::json TravelJson(const model::Pool& pool, model::Dof dof, double free) {
  if (!std::isfinite(free)) return nullptr;
  nlohmann::json j = {{"free", free}, {"unit", std::string(model::PositionUnit(dof))}};
  if (model::IsRotational(dof)) {
    j["turns"] = pool.ExtentFor(dof, free);
  } else {
    j["wall_to_wall"] = pool.WallToWallFor(free);
  }
  return j;
}

// The box points a DOF not hosted over the whole box was planned at: SI values and whether
// the pool hosts that vehicle.
nlohmann::json PointsJson(const planner::DofVerdict& d) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : d.points) {
    out.push_back({{"m", p.point.m},
                   {"k", p.point.k},
                   {"kq", p.point.kq},
                   {"label", text::BoxPointLabel(p.point, d.dof)},
                   {"hosted", p.hosted}});
  }
  return out;
}

}  // namespace

nlohmann::json PoolVerdictJson(const planner::PoolVerdict& v, const model::Pool& pool) {
  nlohmann::json dofs = nlohmann::json::object();
  for (const auto& d : v.dofs) {
    dofs[std::string(model::DofName(d.dof))] = {
        {"hosted", d.hosted},
        {"limit", std::string(planner::PoolLimitName(d.limit))},
        {"reason", text::DofReason(v, d, pool)},
        {"extent", TravelJson(pool, d.dof, d.extent)},
        {"need", TravelJson(pool, d.dof, d.need)},
        {"need_verified", d.need_verified},
        {"need_refuted",
         d.need_verified ? TravelJson(pool, d.dof, d.need_refuted) : nlohmann::json()},
        {"undetermined", d.determinacy.undetermined},
        {"hostability", std::string(planner::HostabilityName(d.hostability))},
        {"points", PointsJson(d)},
        {"points_start_known", d.points_start_known}};
  }
  const planner::RequiredPool& r = v.required;
  const double m2 = 2 * pool.margin;
  nlohmann::json required = {{"length", r.length},
                             {"width", r.width},
                             {"depth", r.depth},
                             {"unit", "m"},
                             {"measure", "wall to wall"},
                             {"free",
                              {{"length", r.length - m2},
                               {"width", r.width - m2},
                               {"depth", r.depth - m2},
                               {"unit", "m"}}},
                             {"turns", r.turns},
                             {"turns_unit", "turns"},
                             {"exists", r.exists}};
  return {{"hosted", v.hosted},
          {"hostability", std::string(planner::HostabilityName(v.hostability))},
          {"identified_box", v.identified_box},
          {"derived_box", v.derived_box},
          {"sentence", text::VerdictSentence(v, pool)},
          {"lines", text::VerdictLines(v, pool)},
          {"dofs", dofs},
          {"required", required}};
}

}  // namespace uuvplan::io
