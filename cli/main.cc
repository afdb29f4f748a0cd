// uuvplan <command> [options]: see docs/cli.md.
#include <malloc.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <exception>
#include <iostream>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/usage_errors.h"
#include "uuvplan/io/plausibility.h"
#include "uuvplan/model/input_error.h"

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

// glibc's heap, set for the two loads of the program (docs/performance.md, "Memory"):
// - blocks of 128 KiB and more (a long log's vectors) are mapped on their own and given back
//   to the system when freed. By default glibc raises this threshold to the size of the
//   largest such block freed (up to 32 MiB); the vectors that follow then come from the heap,
//   and the holes they leave stay resident: 3–4 MB more peak RSS on a 1,000,000-row log;
// - up to 1 MiB free at the heap's top is kept rather than returned at every free. Fixing
//   the first threshold also fixes this one at 128 KiB, and the planner's simulations, each
//   taking and freeing its buffers, then spent 9.7 s of system time in page faults besides
//   18.4 s of user time on BlueROV2's heave schedule (0.01 + 12.5 s with 1 MiB; 4 and 16 MiB
//   gave no more; 32 MiB cost 5.6 MB of peak RSS on the 1,000,000-row log, 1 MiB 0.3 MB).
void SetHeapThresholds() {
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace uuvplan::cli;
  SetHeapThresholds();
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
    return run ? run() : kExitBadInput;
  } catch (const uuvplan::model::InputError& e) {
    std::cerr << "uuvplan: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "uuvplan: internal error: " << e.what() << "\n";
    return 3;
  }
}
