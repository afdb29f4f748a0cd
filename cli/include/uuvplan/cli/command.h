// The uuvplan command line: one file per command; each registers itself here so that main.cc
// never changes. Commands hold no numerics: a command binds its flags to the library's Options
// (defaults read from them), calls one library function, prints its result and writes it as
// JSON. Exit status (contract): 0 success, 1 a result the user must act on, 2 bad input.
// Environment variables are read here, in the tool, never in the libraries.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitActionNeeded = 1;
inline constexpr int kExitBadInput = 2;

/// A command adds its subcommand to `app` and stores in `run` what to do when it is chosen;
/// `run` returns the exit status. Input errors are thrown as model::InputError.
struct Command {
  std::string name;
  int order = 0;  ///< position in --help: the story's order (plan, run, identify, diagnose)
  std::function<void(CLI::App& app, std::function<int()>* run)> add;
};

std::vector<Command>& Registry();

/// --help's order: by `order` (each command's own), then by name.
bool HelpOrder(const Command& a, const Command& b);

struct CommandRegistration {
  explicit CommandRegistration(Command c) { Registry().push_back(std::move(c)); }
};

/// The command `name` (`description` in --help): when chosen, `bind` has added its flags to a
/// fresh `Flags` (each command's `<Command>Flags`, whose initial values are the defaults, the
/// library Options' among them) and `run` is called with them.
template <typename Flags>
Command MakeCommand(std::string name, int order, std::string description,
                    void (*bind)(CLI::App* sub, Flags* flags), int (*run)(const Flags& flags)) {
  return {name, order, [=](CLI::App& app, std::function<int()>* chosen) {
            auto flags = std::make_shared<Flags>();
            CLI::App* sub = app.add_subcommand(name, description);
            bind(sub, flags.get());
            sub->callback([=] { *chosen = [=] { return run(*flags); }; });
          }};
}

/// `--json F`: "<what> as JSON to this file ('-' = stdout)".
/// A finite number > 0 (`what`: "a percentage", "a duration in s"), in the option's message.
CLI::Validator PositiveNumber(const std::string& what);
/// --max-duration: a pool trial's length in s, in (0, kMaxTrialSeconds].
CLI::Validator TrialDuration();
/// An output file's check, at parse time so that nothing is computed for an output that cannot
/// be written and a command with two outputs writes both or neither: its directory exists and
/// is writable ('-' = stdout passes).
CLI::Validator OutputFile();
/// `check_now` false: the file may go into a directory the command creates (simulate --out).
CLI::Option* AddJsonOption(CLI::App* sub, std::string* path, const std::string& what,
                           bool check_now = true);

/// `--target PCT`: the loop's target percentile error 100·σ/|θ| (%), the precision the pool
/// verdict judges at (schedule, check-pool, next, loop; one default, planner::
/// kDefaultTargetPercent). Must be > 0 (exit 2 otherwise).
CLI::Option* AddTargetOption(CLI::App* sub, double* target_percent);

/// Where the readable report goes: stdout, or stderr when the JSON goes there (`--json -`).
std::ostream& ReportStream(const std::string& json_path);

/// A command's one-line Summary().Brief() on stderr, only when stderr is a terminal
/// (isatty(2)): stdout, --json output and captured stderr stay as they were.
void PrintBriefOnTerminal(const std::string& brief);

/// Progress lines on stderr ("uuvplan diagnose: 3.1 s: yaw: round 2, ..."), only when stderr is a
/// terminal and once the run has taken `after_s` (a short run stays quiet; captured output is
/// unchanged).
std::function<void(const std::string&)> TerminalProgress(const std::string& command,
                                                         double after_s = 2.0);

/// Writes `j` to `path` atomically, or to stdout when `path` is "-".
void WriteJson(const std::string& path, const nlohmann::json& j);

/// `path` without a trailing separator ("dir/" and "dir" are the same directory):
/// io::WriteCampaign builds its temporary sibling by appending to the name.
std::string DirectoryName(const std::string& path);

/// `--accept-units`: identify even when the campaign's logs fail the unit and sign checks.
void AddAcceptUnitsFlag(CLI::App* sub, bool* accept);

/// `--threads N` (default 0: one per core), stored into every option of `targets` (the
/// library Options' `threads`); `what` says what runs in parallel. Results never depend on it.
void AddThreadsOption(CLI::App* sub, const std::vector<int*>& targets, const std::string& what);

/// The campaign at `path` (io::ReadCampaign) after the unit and sign checks of
/// ident/prepare/input_sanity.h, run by every command that identifies from it (identify, diagnose,
/// next): a finding is a model::InputError naming the file, the column and the likely unit
/// (exit 2), or with `accept_units` a warning on stderr.
model::Campaign ReadCampaignForIdentification(const std::string& path, bool accept_units);

/// The DOFs named by repeated `--dof` flags; InputError naming the flag and the bad name.
std::vector<model::Dof> ParseDofFlags(const std::vector<std::string>& names);

/// Every DOF asked for must have a thrust mapping to drive it and a sensor to observe it;
/// InputError naming the vehicle file's key otherwise.
void CheckDofsPlannable(const std::vector<model::Dof>& dofs, const model::Vehicle& vehicle,
                        const std::string& vehicle_path);

}  // namespace uuvplan::cli
