// The Monte Carlo coverage table (monte_carlo_table.h).
#include "uuvplan/text/monte_carlo_table.h"

#include <cstdio>
#include <sstream>

namespace uuvplan::text {

std::string MonteCarloTable(const ident::MonteCarloReport& report) {
  std::ostringstream os;
  os.precision(4);
  os << "estimator              dof    param                 truth        mean         sd"
        "   mean σ  sd/σ   cover  ≤3σ   crb σ    sd/crb   n\n";
  for (const auto& c : report.cells) {
    char line[512];
    std::snprintf(
        line, sizeof line,
        "%-22s %-6s %-20s %11.5g %11.5g %10.4g %8.4g %5.2f  %5.1f%% %4.0f%% %8.4g %6.2f %4d\n",
        c.estimator.c_str(), std::string(model::DofName(c.dof)).c_str(), c.name.c_str(), c.truth,
        c.mean, c.sd, c.mean_sigma, c.mean_sigma > 0 ? c.sd / c.mean_sigma : 0.0,
        100.0 * c.coverage(), c.n > 0 ? 100.0 * c.within3 / c.n : 0.0, c.crb_sigma,
        c.crb_sigma > 0 ? c.sd / c.crb_sigma : 0.0, c.n);
    os << line;
  }
  os << "repetitions " << report.repetitions << ", failures " << report.failures << "\n";
  return os.str();
}

}  // namespace uuvplan::text
