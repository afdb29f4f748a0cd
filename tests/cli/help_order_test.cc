// The commands in --help in a deliberate order (command.h): each command's own place, no two
// at the same one, so the order never depends on which file registered first.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"

namespace uuvplan::cli {
namespace {

TEST(HelpOrder, EveryCommandHasItsOwnPlace) {
  std::set<int> orders;
  for (const Command& c : Registry()) {
    EXPECT_TRUE(orders.insert(c.order).second) << c.name << " shares its place " << c.order;
  }
}

TEST(HelpOrder, TheStorysOrder) {
  std::vector<Command> commands = Registry();
  std::sort(commands.begin(), commands.end(), HelpOrder);
  std::vector<std::string> names;
  for (const Command& c : commands) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"schedule", "check-pool", "simulate", "import",
                                             "identify", "log", "next", "loop", "demo", "diagnose",
                                             "score", "report"}));
}

}  // namespace
}  // namespace uuvplan::cli
