// Units in the tables people read (text/include/uuvplan/text/text_table.h): every table
// printed by schedule, check-pool, identify, next, loop and diagnose starts with a DOF column,
// is aligned (each column starts where its title does, after a gap), and every quantity column
// has its unit — in its title, "σ (m/s)", or in every cell, "0.84 kg", "4:05 min". Label
// columns (names, kinds, verdicts) are the only ones without. No number is printed with a
// positive exponent ("1.2e+03 s").
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/parameter.h"

namespace uuvplan::cli_test {
namespace {

const std::set<std::string> kLabelColumns = {
    "DOF",    "trial",  "kind",  "mapping", "parameter", "use",   "significance", "residuals",
    "effect", "detail", "round", "fits",    "verdict",   "state", "force_text"};

std::size_t Width(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

// The characters of `s` from code point `from` to `to` (to = npos: the end).
std::string Slice(const std::string& s, std::size_t from, std::size_t to) {
  std::string out;
  std::size_t i = 0;
  for (std::size_t b = 0; b < s.size(); ++b) {
    const unsigned char c = static_cast<unsigned char>(s[b]);
    if ((c & 0xC0) != 0x80 && b > 0) ++i;
    if (i >= from && i < to) out += s[b];
  }
  return out;
}

std::string Trim(const std::string& s) {
  const auto a = s.find_first_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// Every unit a cell may carry: the parameters' units on every DOF and the tables' own.
std::set<std::string> Units() {
  std::set<std::string> units = {"m",   "m/s", "rad",   "rad/s",     "s",     "min",   "N",
                                 "N·m", "kg",  "kg·m²", "(no unit)", "turns", "turns)"};
  for (const model::Dof dof : model::kAllDofs) {
    for (const char* p :
         {"m", "k", "kq", "bias", "bias_step", "k_neg", "kq_neg", "lag", "deadzone", "eta.a.pos"}) {
      units.insert(model::Unit(p, dof));
    }
  }
  return units;
}

bool HasUnit(const std::string& cell, const std::set<std::string>& units) {
  if (cell.find("°") != std::string::npos || cell.find("(no unit)") != std::string::npos) {
    return true;
  }
  std::istringstream words(cell);
  for (std::string w; words >> w;) {
    while (!w.empty() && (w.back() == ',' || w.back() == ';' || w.back() == ']')) w.pop_back();
    if (units.count(w)) return true;
  }
  return false;
}

struct Column {
  std::string title;
  std::size_t start = 0;
};

// Checks every table of `text` (a line whose first word is "DOF" and the lines under it with
// the same indent); returns how many it found.
int CheckTables(const std::string& command, const std::string& text) {
  const std::set<std::string> units = Units();
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  int tables = 0;
  for (std::size_t h = 0; h < lines.size(); ++h) {
    const std::string& header = lines[h];
    const std::size_t indent = header.find_first_not_of(' ');
    if (indent == std::string::npos || header.compare(indent, 4, "DOF ") != 0) continue;
    ++tables;
    std::vector<Column> columns;
    for (std::size_t i = 0; i < Width(header);) {
      const std::string rest = Slice(header, i, std::string::npos);
      if (rest[0] == ' ') {
        ++i;
        continue;
      }
      const std::size_t end = rest.find("  ");
      const std::string title = rest.substr(0, end);
      columns.push_back({title, i});
      i += Width(title);
    }
    std::size_t r = h + 1;
    // Rows: the lines under the title with its indent and a DOF in the first column.
    auto is_row = [&](const std::string& line) {
      std::istringstream words(line);
      std::string first;
      return line.find_first_not_of(' ') == indent && words >> first &&
             model::ParseDof(first).has_value();
    };
    for (; r < lines.size() && is_row(lines[r]); ++r) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const std::size_t to = c + 1 < columns.size() ? columns[c + 1].start : std::string::npos;
        const std::string cell = Trim(Slice(lines[r], columns[c].start, to));
        if (c > 0 && !cell.empty()) {
          EXPECT_EQ(Slice(lines[r], columns[c].start - 1, columns[c].start), " ")
              << command << ": column '" << columns[c].title << "' not aligned in\n"
              << lines[r];
        }
        const std::string& title = columns[c].title;
        if (kLabelColumns.count(title) || title.find('(') != std::string::npos) continue;
        if (cell.empty() || cell == "-") continue;
        EXPECT_TRUE(HasUnit(cell, units)) << command << ": column '" << title << "' cell '" << cell
                                          << "' has no unit (title nor cell)";
      }
    }
    EXPECT_GT(r, h + 1) << command << ": a table without rows:\n" << header;
  }
  EXPECT_EQ(text.find("e+0"), std::string::npos) << command << ": a number with an exponent";
  return tables;
}

// A short campaign of two DOFs: one steady run each way and a sine (seconds to identify).
const char* kPlanJson = R"({"trials": [
  {"id": "surge_fwd", "dof": "surge", "kind": "steady", "duration": 20, "mapping": "surge-front", "force": 35},
  {"id": "surge_back", "dof": "surge", "kind": "steady", "duration": 20, "mapping": "surge-rear", "force": -35},
  {"id": "surge_sine", "dof": "surge", "kind": "sine", "duration": 40, "mapping": "surge-front",
   "offset": 30, "amplitude": 20, "omega": 0.4},
  {"id": "yaw_sine", "dof": "yaw", "kind": "sine", "duration": 30, "mapping": "yaw-fr-rl",
   "offset": -5, "amplitude": 4, "omega": 0.2618}]})";

TEST(TableUnits, EveryTableOfEveryCommandHasItsUnits) {
  const TempDir scratch;
  const std::string romeo = kRomeoCase + "vehicle.yaml --pool " + kRomeoCase + "pool.yaml";
  const std::string plan = scratch.Write("plan.json", kPlanJson);
  const std::string campaign = scratch / "campaign";
  ASSERT_EQ(RunTool("simulate --truth " + kRomeoCase + "truth.yaml --plan " + plan + " --out " +
                        campaign + " --seed 5",
                    scratch)
                .status,
            0);
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"schedule", "schedule " + romeo},
      {"check-pool", "check-pool " + romeo + " --plan " + plan},
      {"identify", "identify " + campaign},
      {"next", "next " + campaign + " --pool " + kRomeoCase + "pool.yaml --dof surge"},
      {"loop", "loop --truth " + kRomeoCase + "truth.yaml --pool " + kRomeoCase +
                   "pool.yaml --dof yaw --budget 2 --seed 3"},
      {"diagnose", "diagnose " + campaign + " --dof surge"}};
  for (const auto& [command, args] : runs) {
    const ToolRun run = RunTool(args, scratch);
    EXPECT_LE(run.status, 6) << command << ": " << run.err;
    EXPECT_NE(run.status, 2) << command << ": " << run.err;
    EXPECT_GE(CheckTables(command, run.out), 1) << command << " printed no table:\n" << run.out;
  }
}

}  // namespace
}  // namespace uuvplan::cli_test
