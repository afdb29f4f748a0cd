// Usage errors (usage_errors.h).
#include "uuvplan/cli/usage_errors.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace uuvplan::cli {
namespace {

// "-5", "-0.3", "-1e3": a negative number given as an option's value, not an option.
bool IsNegativeNumber(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' &&
         (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
}

std::string Suggestion(const std::string& word, const std::vector<std::string>& names) {
  const auto best = ClosestName(word, names);
  return best ? " (did you mean '" + *best + "'?)" : "";
}

// Length of the longest common subsequence: the tie-breaker between names equally far away
// ("foo" is two edits from both "log" and "loop"; "loop" keeps its "oo").
int CommonSubsequence(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1, 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = 0;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = a[i - 1] == b[j - 1] ? diagonal + 1 : std::max(row[j], row[j - 1]);
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> CommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

// Every long and short name of the options of `app` ("--json", "-h").
std::vector<std::string> OptionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// The first option of argv[first..] that `app` does not know, with its message.
// The command's own options and, after its name, uuvplan's (`--accept-implausible`: the app
// falls through to them).
std::optional<std::string> UnknownOption(const CLI::App& app, const std::string& where, int first,
                                         int argc, const char* const* argv,
                                         const CLI::App* parent = nullptr) {
  std::vector<std::string> known = OptionNames(app);
  if (parent) {
    const std::vector<std::string> inherited = OptionNames(*parent);
    known.insert(known.end(), inherited.begin(), inherited.end());
  }
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;  // the rest are positional arguments
    if (arg.size() < 2 || arg[0] != '-' || IsNegativeNumber(arg)) continue;
    const std::string name = arg.substr(0, arg.find('='));
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    return "uuvplan: unknown option '" + name + "'" + where + Suggestion(name, known) +
           "\nRun with --help for more information.";
  }
  return std::nullopt;
}

}  // namespace

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::optional<std::string> ClosestName(const std::string& word,
                                       const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  int best_distance = std::max(2, static_cast<int>(word.size()) / 3) + 1, best_common = 0;
  for (const std::string& c : candidates) {
    // A known name the word begins ("--vers" for "--version") is one edit away.
    const bool prefix = word.size() >= 3 && c.compare(0, word.size(), word) == 0;
    const int d = prefix ? 1 : EditDistance(word, c);
    const int common = CommonSubsequence(word, c);
    if (d < best_distance || (d == best_distance && best && common > best_common)) {
      best = c, best_distance = d, best_common = common;
    }
  }
  return best;
}

std::optional<std::string> UnknownNameMessage(const CLI::App& app, int argc,
                                              const char* const* argv) {
  if (argc < 2) return std::nullopt;  // CLI11 says a command is required
  const std::string first = argv[1];
  if (first.size() > 1 && first[0] == '-') return UnknownOption(app, "", 1, 2, argv);
  const std::vector<std::string> commands = CommandNames(app);
  if (std::find(commands.begin(), commands.end(), first) == commands.end()) {
    return "uuvplan: unknown command '" + first + "'" + Suggestion(first, commands) +
           "\nRun 'uuvplan --help' for the list of commands.";
  }
  return UnknownOption(*app.get_subcommand(first), " for '" + first + "'", 2, argc, argv, &app);
}

std::string ParseErrorMessage(const CLI::ParseError& e) {
  return "uuvplan: " + std::string(e.what()) + "\nRun with --help for more information.";
}

}  // namespace uuvplan::cli
