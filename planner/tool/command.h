// The uuvplan command line: one file per command; each registers itself here so that main.cc
// never changes. Commands hold no numerics: they read input, call the libraries, print and
// write JSON. Exit status (contract): 0 success, 1 a result the user must act on, 2 bad input.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace uuvplan::tool {

inline constexpr int kExitOk = 0;
inline constexpr int kExitActionNeeded = 1;
inline constexpr int kExitBadInput = 2;

/// A command adds its subcommand to `app` and stores in `run` what to do when it is chosen;
/// `run` returns the exit status. Input errors are thrown as model::InputError.
struct Command {
  std::string name;
  int order = 0;  ///< position in --help
  std::function<void(CLI::App& app, std::function<int()>* run)> add;
};

std::vector<Command>& Registry();

struct CommandRegistration {
  explicit CommandRegistration(Command c) { Registry().push_back(std::move(c)); }
};

}  // namespace uuvplan::tool
