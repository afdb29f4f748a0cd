// The commands files and the run sheet (command_files.h).
#include "uuvplan/io/command_files.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "uuvplan/io/new_directory.h"
#include "uuvplan/io/number_text.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {
namespace {

// A distance along the trial's DOF for people: m, or degrees (and turns) for a rotation.
std::string Along(model::Dof dof, double x) {
  return model::IsRotational(dof) ? model::AngleText(x) : model::Significant(x, 3) + " m";
}

// A start coordinate or abort line, marked by hand to the centimetre (command_sheet.h): "1.60 m".
std::string Centimetres(double metres) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << (std::abs(metres) < 0.005 ? 0.0 : metres) << " m";
  return s.str();
}

// An abort line: metres to the centimetre, or degrees for a rotation; signed.
std::string AbortText(model::Dof dof, double x) {
  return (x >= 0 ? "+" : "") + (model::IsRotational(dof) ? model::AngleText(x) : Centimetres(x));
}

std::string Signed(model::Dof dof, double x) { return (x >= 0 ? "+" : "") + Along(dof, x); }

std::string StartText(const planner::TrialCommands& t) {
  return "x " + Centimetres(t.start[0]) + ", y " + Centimetres(t.start[1]) + ", z " +
         Centimetres(t.start[2]);
}

std::string HeadingText(const planner::TrialCommands& t) {
  std::string text = "0°";
  if (model::IsRotational(t.dof)) text += ", tether twisted " + Signed(t.dof, t.start_twist);
  return text;
}

std::string RunSheetRow(int order, const planner::TrialCommands& t) {
  std::ostringstream row;
  row << "| " << order << " | " << t.id << " | " << model::DofName(t.dof) << " | "
      << model::TrialKindName(t.kind) << " | " << model::Join(t.mappings) << " | " << StartText(t)
      << " | " << HeadingText(t) << " | " << model::DurationText(t.duration) << " | "
      << Along(t.dof, t.travel[0]) << " to " << Along(t.dof, t.travel[1]) << " | "
      << AbortText(t.dof, t.abort[0]) << " / " << AbortText(t.dof, t.abort[1]) << " | " << t.id
      << ".csv |\n";
  return row.str();
}

}  // namespace

std::string CommandsCsv(const planner::CommandSheet& sheet, const planner::TrialCommands& t) {
  std::string out = "t_s";
  for (const std::string& name : sheet.thrusters) out += "," + name;
  out += model::IsRotational(t.dof) ? ",expected_position_rad\n" : ",expected_position_m\n";
  for (std::size_t i = 0; i < t.t.size(); ++i) {
    AppendGeneral(t.t[i], 10, &out);
    for (int j = 0; j < t.command.cols(); ++j) {
      out += ',';
      AppendGeneral(t.command(static_cast<int>(i), j), 8, &out);
    }
    out += ',';
    AppendGeneral(t.expected_position[i], 8, &out);
    out += '\n';
  }
  return out;
}

std::string RunSheetMarkdown(const planner::CommandSheet& sheet, const model::Vehicle& vehicle,
                             const model::Pool& pool) {
  std::ostringstream md;
  double total = 0.0;
  for (const auto& t : sheet.trials) total += t.duration;
  md << "# Run sheet: " << vehicle.name << " in pool " << pool.name << "\n\n"
     << sheet.trials.size() << " trials, " << model::DurationText(total)
     << " of thrusters running. Pool " << model::Significant(pool.length, 3) << " m long, "
     << model::Significant(pool.width, 3) << " m wide, " << model::Significant(pool.depth, 3)
     << " m deep, " << model::Significant(pool.margin, 3) << " m kept clear of every wall.\n\n"
     << "- Start: x along the pool's length from the wall behind the vehicle, y across its width "
        "from the left wall, z depth below the surface; heading 0° = bow along the length, "
        "toward the far wall. A rotation starts with the tether twisted as stated (+ = the "
        "trial's positive direction), so that its twist stays centred on the untwisted tether.\n"
     << "- Each trial starts from rest. Its commands file (" << model::Join(sheet.thrusters)
     << " in each thruster's command units, rows every "
     << model::Significant(1.0 / sheet.rate_hz, 3)
     << " s and at every change, each held until the next row) ends with every thruster stopped.\n"
     << "- Expected travel: from the start, over every vehicle of the box planned over (the a "
        "priori box, or the box about the estimates where the vehicle is identified).\n"
     << "- Abort: stop the thrusters when the vehicle reaches either distance from the start (a "
        "margin line; for a rotation the tether's twist limit). Starts and abort lines are to "
        "the centimetre, each within 5 mm of the exact line.\n\n"
     << "| # | trial | DOF | kind | mapping | start | heading | duration | expected travel | "
        "abort at | commands |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  int order = 1;
  for (const auto& t : sheet.trials) md << RunSheetRow(order++, t);
  return md.str();
}

void WriteCommandFiles(const std::string& dir, const planner::CommandSheet& sheet,
                       const model::Vehicle& vehicle, const model::Pool& pool) {
  std::map<std::string, std::string> files;
  for (const auto& t : sheet.trials) files[t.id + ".csv"] = CommandsCsv(sheet, t);
  files["run_sheet.md"] = RunSheetMarkdown(sheet, vehicle, pool);
  WriteNewDirectory(dir, files, "--commands", "the command files");
}

void WriteScheduleCommands(const std::string& dir, const model::Vehicle& vehicle,
                           const model::Pool& pool, const planner::Schedule& schedule,
                           const planner::ScheduleOptions& options) {
  planner::CommandSheetOptions sheet;
  sheet.schedule = options;
  WriteCommandFiles(dir, planner::MakeCommandSheet(vehicle, pool, schedule, sheet), vehicle, pool);
}

}  // namespace uuvplan::io
