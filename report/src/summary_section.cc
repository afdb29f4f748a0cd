// The report's first section: one row per verdict, each pointing to its section.
#include "figure_parts.h"
#include "uuvplan/report/sections.h"

namespace uuvplan::report {

namespace {

void AddIdentification(const ident::IdentifyResult& r, Table* t) {
  for (const ident::DofIdentification& d : r.dofs) {
    std::string mae;
    if (!d.fit.trials.empty()) {
      mae = "; free-run velocity MAE " + Number(d.fit.velocity_mae_fit) + " (fit), " +
            Number(d.fit.velocity_mae_validate) + " (validate) " +
            std::string(model::VelocityUnit(d.dof));
    }
    t->rows.push_back({"identification of " + DofText(d.dof),
                       std::string(ident::IdentifyStatusName(d.status)) + " (" +
                           std::string(ident::FinalEstimatorName(d.estimator)) + ")" + mae,
                       "Estimates, Validation"});
  }
}

void AddDiagnosis(const ident::DiagnosisResult& r, Table* t) {
  std::string found;
  for (const ident::Finding& f : r.findings) {
    found += (found.empty() ? "" : "; ") + f.effect + " on " + DofText(f.dof) + " (held-out gain " +
             Number(100 * f.gain.relative) + " %)";
  }
  t->rows.push_back(
      {"diagnosis", found.empty() ? "no effect beyond the standard model" : found, "Diagnosis"});
  for (const auto& [dof, why] : r.not_diagnosed)
    t->rows.push_back({"diagnosis of " + DofText(dof), "not diagnosed: " + why, "Diagnosis"});
}

}  // namespace

Section SummarySection(const planner::Schedule* schedule, const std::string* verdict_sentence,
                       const ident::IdentifyResult* identification,
                       const ident::DiagnosisResult* diagnosis, const io::LoopHistory* loop) {
  Section s{"summary", "Summary", {}, {}, {}};
  Table t{"", {"question", "answer", "section"}, {}};
  if (schedule) {
    t.rows.push_back({"schedule",
                      std::to_string(schedule->trials.size()) + " trials, pool time " +
                          Number(schedule->pool_time / 60) + " min",
                      "Schedule"});
  }
  if (verdict_sentence) t.rows.push_back({"pool verdict", *verdict_sentence, "Schedule"});
  if (identification) AddIdentification(*identification, &t);
  if (diagnosis) AddDiagnosis(*diagnosis, &t);
  if (loop) {
    t.rows.push_back({"loop",
                      loop->status + " after " + std::to_string(loop->trials.size()) +
                          " trials, pool time " + Number(loop->pool_time / 60) + " min (target " +
                          Number(loop->target_percent) + " %)",
                      "Loop history"});
  }
  s.tables.push_back(std::move(t));
  return s;
}

}  // namespace uuvplan::report
