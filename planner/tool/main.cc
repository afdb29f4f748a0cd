// uuvplan <command> [options]: see docs/cli.md.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <exception>
#include <iostream>

#include "command.h"
#include "usage_errors.h"
#include "uuvplan/model/input_error.h"

int main(int argc, char** argv) {
  using namespace uuvplan::tool;
  CLI::App app{
      "uuvplan: plan, run and analyse hydrodynamic identification trials of underwater "
      "vehicles (drag, added mass, thruster installation losses)",
      "uuvplan"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("uuvplan ") + UUVPLAN_VERSION,
                       "the version (CMake project()) and exit");
  auto& commands = Registry();
  std::sort(commands.begin(), commands.end(),
            [](const Command& a, const Command& b) { return a.order < b.order; });
  std::function<int()> run;
  for (auto& c : commands) c.add(app, &run);
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
