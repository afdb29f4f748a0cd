// What every command shares (command.h): the registry, the `--json` flag and its output, `--dof`.
#include "command.h"

#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"

namespace uuvplan::tool {

std::vector<Command>& Registry() {
  static std::vector<Command> commands;
  return commands;
}

CLI::Option* AddJsonOption(CLI::App* sub, std::string* path, const std::string& what) {
  return sub->add_option("--json", *path, what + " as JSON to this file ('-' = stdout)");
}

void PrintBriefOnTerminal(const std::string& brief) {
  if (isatty(STDERR_FILENO)) std::cerr << brief << "\n";
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

}  // namespace uuvplan::tool
