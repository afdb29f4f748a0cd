// What every command shares (command.h): the registry, the `--json` flag and its output, `--dof`.
#include "uuvplan/cli/command.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>

#include "uuvplan/ident/prepare/input_sanity.h"
#include "uuvplan/io/io.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::cli {

std::vector<Command>& Registry() {
  static std::vector<Command> commands;
  return commands;
}

bool HelpOrder(const Command& a, const Command& b) {
  return a.order != b.order ? a.order < b.order : a.name < b.name;
}

namespace {

// Whether `text` is a whole finite number in (0, most].
bool NumberInRange(const std::string& text, double most) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && end == text.c_str() + text.size();
  return number && std::isfinite(x) && x > 0 && x <= most;
}

}  // namespace

CLI::Validator PositiveNumber(const std::string& what) {
  return CLI::Validator(
      [what](std::string& text) -> std::string {
        return NumberInRange(text, std::numeric_limits<double>::infinity())
                   ? ""
                   : "expected " + what + " > 0, got '" + text + "'";
      },
      "NUMBER > 0");
}

// A pool is booked by the hour; the papers' trials last 0.5–4 min. A longer "trial" is a unit
// slip (ms for s) and would only meet the simulation's work limit further on.
constexpr double kMaxTrialSeconds = 3600.0;

CLI::Validator TrialDuration() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return NumberInRange(text, kMaxTrialSeconds)
                   ? ""
                   : "expected a trial's duration in (0, 3600] s (a pool is booked by the hour), "
                     "got '" +
                         text + "'";
      },
      "SECONDS in (0, 3600]");
}

CLI::Validator OutputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        if (path == "-") return "";
        const std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
        if (!std::filesystem::is_directory(dir)) {
          return "expected a file in an existing directory: " + dir.string() + " does not exist";
        }
        if (access(dir.c_str(), W_OK) != 0)
          return "the directory " + dir.string() + " is not writable";
        if (std::filesystem::is_directory(path))
          return "expected a file, " + path + " is a directory";
        if (std::filesystem::exists(path) && access(path.c_str(), W_OK) != 0) {
          return path + " exists and is not writable";
        }
        return "";
      },
      "FILE");
}

CLI::Option* AddJsonOption(CLI::App* sub, std::string* path, const std::string& what,
                           bool check_now) {
  CLI::Option* option =
      sub->add_option("--json", *path, what + " as JSON to this file ('-' = stdout)");
  return check_now ? option->check(OutputFile()) : option;
}

CLI::Option* AddTargetOption(CLI::App* sub, double* target_percent) {
  return sub
      ->add_option("--target", *target_percent,
                   "percentile error 100·σ/|θ| (%) every parameter of interest must reach; the "
                   "pool verdict judges whether the loop can reach it in this pool")
      ->capture_default_str()
      ->check(PositiveNumber("a percentage"));
}

void PrintBriefOnTerminal(const std::string& brief) {
  if (isatty(STDERR_FILENO)) std::cerr << brief << "\n";
}

std::function<void(const std::string&)> TerminalProgress(const std::string& command,
                                                         double after_s) {
  if (!isatty(STDERR_FILENO)) return [](const std::string&) {};
  const auto start = std::chrono::steady_clock::now();
  return [start, after_s, command](const std::string& line) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (s >= after_s) {
      std::cerr << "uuvplan " << command << ": " << model::DurationText(s) << ": " << line << "\n";
    }
  };
}

std::ostream& ReportStream(const std::string& json_path) {
  return json_path == "-" ? std::cerr : std::cout;
}

void WriteJson(const std::string& path, const nlohmann::json& j) {
  const std::string text = j.dump(2) + "\n";
  if (path == "-") {
    std::cout << text;
  } else {
    io::WriteFileAtomically(path, text);
  }
}

std::string DirectoryName(const std::string& path) {
  std::filesystem::path p = std::filesystem::path(path).lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p.string();
}

void CheckDofsPlannable(const std::vector<model::Dof>& dofs, const model::Vehicle& vehicle,
                        const std::string& vehicle_path) {
  for (const model::Dof dof : dofs) {
    const std::string name(model::DofName(dof));
    if (vehicle.MappingsOf(dof).empty()) {
      throw model::InputError(vehicle_path + ": mappings",
                              "--dof " + name + ": no thrust mapping acts on " + name);
    }
    auto s = vehicle.sensors.find(dof);
    if (s == vehicle.sensors.end() || (!s->second.position && !s->second.velocity)) {
      throw model::InputError(vehicle_path + ": sensors." + name,
                              "--dof " + name + ": no position or velocity sensor on " + name);
    }
  }
}

std::vector<model::Dof> ParseDofFlags(const std::vector<std::string>& names) {
  std::vector<model::Dof> dofs;
  for (const std::string& name : names) {
    const auto dof = model::ParseDof(name);
    if (!dof) {
      throw model::InputError("--dof " + name, "expected surge, sway, heave, roll, pitch or yaw");
    }
    dofs.push_back(*dof);
  }
  return dofs;
}

void AddThreadsOption(CLI::App* sub, const std::vector<int*>& targets, const std::string& what) {
  sub->add_option_function<int>(
         "--threads",
         [targets](int n) {
           for (int* t : targets) *t = n;
         },
         "threads for " + what + " (default 0: one per core; the results do not depend on it)")
      ->check(CLI::NonNegativeNumber);
}

void AddAcceptUnitsFlag(CLI::App* sub, bool* accept) {
  sub->add_flag("--accept-units", *accept,
                "identify even when a log's units, signs or sensors look wrong (a rate 57.3× "
                "the derivative of its angle, a position column that holds a velocity, a force "
                "opposite to the motion, a sensor stuck at one value); the findings are then "
                "printed as warnings");
}

model::Campaign ReadCampaignForIdentification(const std::string& path, bool accept_units) {
  model::Campaign campaign = io::ReadCampaign(path);
  const std::vector<ident::InputProblem> problems = ident::CheckInputSanity(&campaign);
  if (problems.empty()) return campaign;
  std::string text;
  for (const ident::InputProblem& p : problems) text += "\n  " + p.Text();
  if (accept_units) {
    std::cerr << "warning: units, signs or sensors look wrong (accepted by --accept-units):" << text
              << "\n";
    return campaign;
  }
  throw model::InputError(problems.front().file,
                          "units, signs or sensors look wrong, identification not started:" + text +
                              "\n(fix the columns; if they are right, pass --accept-units)");
}

}  // namespace uuvplan::cli
