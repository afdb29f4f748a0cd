#include "uuvplan/report/report.h"

#include "uuvplan/report/html.h"
#include "uuvplan/report/identification_figures.h"
#include "uuvplan/report/loop_figures.h"
#include "uuvplan/report/render.h"
#include "uuvplan/report/schedule_figures.h"
#include "uuvplan/report/sections.h"

namespace uuvplan::report {

namespace {

// Draws `figures` into `section` (PNG embedded) and into the report's files (PNG and SVG).
void AddFigures(const std::vector<Figure>& figures, Section* section, ReportFiles* out) {
  for (const Figure& f : figures) {
    const std::string png = Render(f, Format::kPng);
    out->files["figures/" + f.name + ".png"] = png;
    out->files["figures/" + f.name + ".svg"] = Render(f, Format::kSvg);
    section->figures.push_back({f.name, f.caption, png});
    ++out->figures;
  }
}

void AddIdentification(const ReportInputs& in, Document* doc, ReportFiles* out) {
  Section estimates = EstimatesSection(*in.identification);
  Section validation = ValidationSection(*in.identification);
  for (const ident::DofIdentification& d : in.identification->dofs) {
    if (d.fit.trials.empty()) continue;
    const std::string stem = "identification-" + std::string(model::DofName(d.dof));
    AddFigures({ParameterFigure(d, stem)}, &estimates, out);
    if (d.rls && d.rls->ok()) AddFigures({RlsConvergenceFigure(d, stem)}, &estimates, out);
    AddFigures({FreeRunFigure(d, stem), ResidualFigure(d, stem)}, &validation, out);
  }
  doc->sections.push_back(std::move(estimates));
  doc->sections.push_back(std::move(validation));
}

void AddDiagnosis(const ReportInputs& in, Document* doc, ReportFiles* out) {
  Section s = DiagnosisSection(*in.diagnosis);
  for (const BeforeAfter& ba : in.before_after) {
    AddFigures({ResidualsBeforeAfterFigure(ba), CandidateGainFigure(*in.diagnosis, ba.dof)}, &s,
               out);
  }
  doc->sections.push_back(std::move(s));
}

}  // namespace

ReportFiles BuildReport(const ReportInputs& in) {
  ReportFiles out;
  Document doc{in.title, in.source, {}};
  if (in.vehicle) doc.sections.push_back(VehicleSection(*in.vehicle, in.vehicle_source));
  if (in.pool) doc.sections.push_back(PoolSection(*in.pool, in.pool_source));
  if (in.schedule) {
    std::vector<std::string> verdict;
    if (in.verdict) {
      verdict = in.verdict->lines;
      verdict.push_back("(" + in.verdict->source + ".)");
    }
    Section s = ScheduleSection(*in.schedule, verdict);
    if (in.vehicle && in.pool) {
      AddFigures(ScheduleFigures(*in.vehicle, *in.pool, *in.schedule, in.planner, &out.notes), &s,
                 &out);
    }
    doc.sections.push_back(std::move(s));
  }
  if (in.identification) AddIdentification(in, &doc, &out);
  if (in.diagnosis) AddDiagnosis(in, &doc, &out);
  if (in.loop) {
    Section s = LoopSection(*in.loop);
    AddFigures({LoopFigure(*in.loop)}, &s, &out);
    doc.sections.push_back(std::move(s));
  }
  if (!out.notes.empty()) doc.sections.push_back({"notes", "Notes", out.notes, {}, {}});
  doc.sections.insert(
      doc.sections.begin(),
      SummarySection(
          in.schedule ? &*in.schedule : nullptr,
          in.verdict && !in.verdict->lines.empty() ? &in.verdict->lines.front() : nullptr,
          in.identification ? &*in.identification : nullptr,
          in.diagnosis ? &*in.diagnosis : nullptr, in.loop ? &*in.loop : nullptr));
  out.files["report.html"] = Html(doc);
  return out;
}

}  // namespace uuvplan::report
