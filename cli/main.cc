// uuvplan <command> [options]: see docs/cli.md.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <exception>
#include <iostream>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/usage_errors.h"
#include "uuvplan/io/plausibility.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/heap.h"

namespace {

// CLI11 reads "-1" for an unsigned option as 2^64 − 1, and a number past 2^64 − 1 (or in hex)
// as 2^64 − 1: every unsigned option (--seed, --budget) takes only decimal digits that make a
// number from 0 to 2^64 − 1 (exit 2 otherwise), so that two different seeds never give the
// same draws.
void RefuseCountsOutOfRange(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands({})) {
    for (CLI::Option* option : sub->get_options()) {
      if (option->get_type_name() != "UINT") continue;
      option->check(CLI::Validator(
          [](std::string& text) {
            std::uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, value);
            const bool digits = !text.empty() && std::isdigit(static_cast<unsigned char>(text[0]));
            return digits && ec == std::errc() && ptr == end
                       ? std::string()
                       : "expected a whole number from 0 to 18446744073709551615, got " + text;
          },
          "UINT >= 0"));
    }
  }
}

// Whether everything printed reached the standard output: a write error there (a full disk,
// `> /dev/full`) is an error, not a success with the results lost.
bool StandardOutputWritten() {
  errno = 0;
  if (std::cout.flush()) return true;
  std::cerr << "uuvplan: error: the standard output cannot be written"
            << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()) << "\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace uuvplan::cli;
  uuvplan::model::SetHeapThresholds();
  CLI::App app{
      "uuvplan: plan, run and analyse hydrodynamic identification trials of underwater "
      "vehicles (drag, added mass, thruster installation losses)",
      "uuvplan"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("uuvplan ") + UUVPLAN_VERSION,
                       "the version (CMake project()) and exit");
  auto& commands = Registry();
  std::sort(commands.begin(), commands.end(), HelpOrder);
  app.fallthrough();  // a flag of uuvplan itself may follow the command's name
  std::function<int()> run;
  for (auto& c : commands) c.add(app, &run);
  bool accept_implausible = false;
  app.add_flag("--accept-implausible", accept_implausible,
               "read values outside the plausible ranges of a pool trial (docs/formats.md, "
               "\"Plausibility\") as given, with a warning, instead of refusing the file");
  RefuseCountsOutOfRange(app);
  if (const auto unknown = UnknownNameMessage(app, argc, argv)) {
    std::cerr << *unknown << "\n";
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << ParseErrorMessage(e) << "\n";
    return kExitBadInput;
  }
  if (accept_implausible) {
    uuvplan::io::AcceptImplausible(
        [](const std::string& warning) { std::cerr << "warning: " << warning << "\n"; });
  }
  try {
    const int status = run ? run() : kExitBadInput;
    return StandardOutputWritten() ? status : kExitBadInput;
  } catch (const uuvplan::model::InputError& e) {
    std::cerr << "uuvplan: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "uuvplan: internal error: " << e.what() << "\n";
    return 3;
  }
}
