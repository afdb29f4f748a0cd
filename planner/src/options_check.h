// The checks behind every planner Options::IsValid, with Ceres' message form
// "SolverOptions::max_local_evaluations = 0. Violated constraint: >= 1". The first violated
// constraint is reported; later ones are not looked at.
#pragma once

#include <string>
#include <string_view>

namespace uuvplan::planner::internal {

class OptionsCheck {
 public:
  /// `owner` names the struct ("PlannerOptions"); `error` (may be null) receives the message.
  OptionsCheck(std::string_view owner, std::string* error) : owner_(owner), error_(error) {}

  /// Records `field` = `value` as violating `constraint` unless `holds`.
  OptionsCheck& Require(bool holds, std::string_view field, const std::string& value,
                        std::string_view constraint) {
    if (!holds && ok_) {
      ok_ = false;
      if (error_) {
        *error_ = std::string(owner_) + "::" + std::string(field) + " = " + value +
                  ". Violated constraint: " + std::string(constraint);
      }
    }
    return *this;
  }
  OptionsCheck& Require(bool holds, std::string_view field, int value,
                        std::string_view constraint) {
    return Require(holds, field, std::to_string(value), constraint);
  }
  OptionsCheck& Require(bool holds, std::string_view field, double value,
                        std::string_view constraint) {
    return Require(holds, field, std::to_string(value), constraint);
  }

  bool ok() const { return ok_; }

 private:
  std::string_view owner_;
  std::string* error_;
  bool ok_ = true;
};

}  // namespace uuvplan::planner::internal
