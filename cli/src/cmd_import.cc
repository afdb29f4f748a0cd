// `uuvplan import SOURCE --map MAP --out DIR [--vehicle V] [--json F]`: turns a lab's
// recordings (ROS 1 bags, MCAP files; one file or a directory of them) into a campaign by the
// map file (docs/import.md): DIR/campaign.yaml, DIR/vehicle.yaml, DIR/trials/<id>.csv, written
// whole or not at all. Exit 0 when written, 2 on bad input.
#include <filesystem>

#include "uuvplan/cli/command.h"
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/import.h"
#include "uuvplan/io/import_json.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::cli {
namespace {

struct ImportFlags {
  std::string source;
  std::string map;
  std::string out;
  std::string vehicle;
  std::string json;
};

void PrintTrials(const io::ImportedCampaign& imported, std::ostream& out) {
  text::TextTable table(
      {"DOF", "trial", "use", "rows", "span (s)", "rate (Hz)", "start (s)", "recording"});
  for (std::size_t i = 0; i < imported.trials.size(); ++i) {
    const model::TrialEntry& e = imported.campaign.trials[i];
    const io::ImportedTrial& t = imported.trials[i];
    table.AddRow({std::string(model::DofName(e.dof)), std::filesystem::path(e.file).stem().string(),
                  std::string(model::TrialUseName(e.use)), std::to_string(e.log.size()),
                  model::Decimals(t.span_s, 1), model::Decimals(t.rate_hz, 0),
                  model::Decimals(e.start, 1),
                  std::filesystem::path(t.recording).filename().string()});
  }
  table.Print(out);
}

int RunImport(const ImportFlags& o) {
  io::CheckNewCampaignDirectory(o.out);
  const io::ImportedCampaign imported = io::ImportRecordings(o.source, o.map, o.vehicle);
  io::WriteCampaign(o.out, imported.campaign, imported.campaign.vehicle, imported.comments);
  const std::string campaign_path = (std::filesystem::path(o.out) / "campaign.yaml").string();
  std::ostream& out = ReportStream(o.json);
  out << "Imported " << imported.trials.size() << " trial(s) from " << o.source << " by the map "
      << o.map << "\n(vehicle " << imported.campaign.vehicle_file << ")\n\n";
  PrintTrials(imported, out);
  out << "\nCampaign: " << campaign_path << "  (next: uuvplan identify " << campaign_path << ")\n";
  if (!o.json.empty()) WriteJson(o.json, io::ImportJson(imported, campaign_path));
  return kExitOk;
}

void BindImport(CLI::App* sub, ImportFlags* o) {
  sub->add_option("source", o->source, "a ROS 1 bag or MCAP file, or a directory of them")
      ->required();
  sub->add_option("--map", o->map, "the import map (docs/import.md): topics, fields, units")
      ->required();
  sub->add_option("--out", o->out, "campaign directory to create (must be new or empty)")
      ->required();
  sub->add_option("--vehicle", o->vehicle, "the vehicle file (default: the map's 'vehicle')");
  AddJsonOption(sub, &o->json, "the trials written", false);
}

const CommandRegistration kImportRegistration(MakeCommand<ImportFlags>(
    "import", 35,
    "Turn recordings (ROS 1 bags, MCAP) into a campaign by a map file: commands held, forces "
    "from a thrust table, measured signals in uuvplan's units and axes.",
    BindImport, RunImport));

}  // namespace
}  // namespace uuvplan::cli
