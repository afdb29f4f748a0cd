#include "uuvplan/io/joint_ls_json.h"

namespace uuvplan::io {

nlohmann::json JointLsJson(const ident::JointLsResult& r, const std::string& model_name) {
  nlohmann::json j;
  j["model"] = model_name;
  j["method"] = "one-step";
  j["status"] = std::string(ident::kJointLsStatusNames.Name(r.status));
  j["message"] = r.message;
  j["instrumental"] = r.instrumental;
  j["rows"] = r.num_rows;
  j["condition_number"] = r.condition_number;
  j["notes"] = r.notes;
  if (r.theta.size() != static_cast<Eigen::Index>(r.names.size())) return j;
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json cov = nlohmann::json::array();
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    params[r.names[k]] = {{"value", r.theta[i]},
                          {"sigma", r.Sigma(static_cast<int>(k))},
                          {"unit", r.units[k]},
                          {"state", r.IsDropped(static_cast<int>(k)) ? "dropped" : "estimated"}};
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < r.covariance.cols(); ++c) row.push_back(r.covariance(i, c));
    cov.push_back(row);
  }
  nlohmann::json dropped = nlohmann::json::array();
  for (const auto& d : r.dropped) {
    dropped.push_back({{"name", r.names[d.index]},
                       {"value_before_drop", d.value},
                       {"sigma_before_drop", d.sigma}});
  }
  j["dropped"] = dropped;
  j["params"] = params;
  j["covariance"] = cov;
  return j;
}

}  // namespace uuvplan::io
