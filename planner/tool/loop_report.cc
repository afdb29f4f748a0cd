// Printing and JSON shared by `next` and `loop` (loop_report.h).
#include "loop_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "trial_text.h"
#include "uuvplan/ident/monte_carlo.h"
#include "uuvplan/io/io.h"

namespace uuvplan::tool {
namespace {

using nlohmann::json;

json Num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string Percent(double p) {
  if (!std::isfinite(p)) return "—";
  std::ostringstream s;
  s << std::fixed << std::setprecision(p < 10 ? 2 : 1) << p << "%";
  return s.str();
}

}  // namespace

std::string TrialLine(const model::TrialDesign& d) {
  std::ostringstream s;
  s << std::left << std::setw(9) << model::TrialKindName(d.kind) << std::setw(22) << d.mapping
    << std::right << std::fixed << std::setprecision(1) << std::setw(6) << d.duration << " s  "
    << ForceText(d, kLoopForceStyle);
  if (d.ballast_steps != 0) s << ", ballast " << d.ballast_steps;
  return s.str();
}

void PrintProgress(const std::vector<planner::DofProgress>& progress, double target,
                   std::ostream& out, const model::Truth* truth) {
  for (const auto& p : progress) {
    out << "  " << model::DofName(p.dof) << " (" << p.trials << " trial"
        << (p.trials == 1 ? "" : "s") << "): "
        << (p.converged ? "every parameter of interest below " + Percent(target)
                        : "worst " + p.worst + " at " + Percent(p.worst_percent) + " (target " +
                              Percent(target) + ")")
        << "\n";
    for (const auto& q : p.interest) {
      std::ostringstream line;
      line << "    " << std::left << std::setw(30) << q.name << std::right;
      if (q.estimated) {
        line << std::setw(11) << std::setprecision(5) << q.value << " ± " << std::left
             << std::setw(10) << std::setprecision(3) << q.sigma << std::right << std::setw(8)
             << Percent(q.percent) << (q.percent <= target ? "  ok" : "    ");
      } else {
        line << std::setw(34) << "not estimated yet"
             << "    ";
      }
      if (truth != nullptr) {
        const double v = ident::TrueParameter(*truth, p.dof, q.name);
        line << "   true " << std::setprecision(5) << v;
        if (q.estimated && v != 0) {
          line << std::fixed << std::setprecision(2) << "  error " << std::showpos
               << 100.0 * (q.value - v) / std::abs(v) << "%" << std::noshowpos << " ("
               << std::setprecision(1) << (q.value - v) / q.sigma << "σ)" << std::defaultfloat;
        }
      }
      out << line.str() << "\n";
    }
  }
}

json ProgressJson(const std::vector<planner::DofProgress>& progress) {
  json j = json::object();
  for (const auto& p : progress) {
    json interest = json::object();
    for (const auto& q : p.interest) {
      interest[q.name] =
          q.estimated
              ? json{{"value", Num(q.value)}, {"sigma", Num(q.sigma)}, {"percent", Num(q.percent)}}
              : json(nullptr);
    }
    j[std::string(model::DofName(p.dof))] = {
        {"converged", p.converged}, {"worst", p.worst},   {"worst_percent", Num(p.worst_percent)},
        {"trials", p.trials},       {"usable", p.usable}, {"status", p.status},
        {"interest", interest}};
  }
  return j;
}

json PredictedJson(model::Dof dof, const planner::PredictedPrecision& p) {
  json sigma = json::object();
  for (const auto& [name, s] : p.sigma) sigma[name] = Num(s);
  return {{std::string(model::DofName(dof)),
           {{"sigma", sigma}, {"criterion", p.criterion}, {"value", Num(p.criterion_value)}}}};
}

}  // namespace uuvplan::tool
