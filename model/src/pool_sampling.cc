#include "pool_sampling.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/util/checked_count.h"
#include "uuvplan/model/work_limits.h"

namespace uuvplan::model::internal {

std::vector<double> SampleTimes(double rate_hz, double duration) {
  const long n = CheckedFloor(duration * rate_hz, "virtual pool samples (duration × rate)",
                              limits::kMaxTrialRows, "a shorter trial or a lower sensor rate");
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(n) + 2);
  const double dt = 1.0 / rate_hz;
  for (long k = 0; k * dt <= duration + 1e-9; ++k) t.push_back(k * dt);
  return t;
}

double WrapAngle(double a) {
  double w = std::remainder(a, 2 * M_PI);  // (-pi, pi]
  if (w <= -M_PI) w += 2 * M_PI;
  return w;
}

std::vector<double> Corrupt(const Eigen::VectorXd& clean, const SensorSpec& spec,
                            const SensorDefects& defects, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, spec.sigma);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double outlier = defects.outlier_size > 0 ? defects.outlier_size : 20.0 * spec.sigma;
  const double rho = defects.noise_ar1;
  const double innovation = std::sqrt(1.0 - rho * rho);
  std::vector<double> y(clean.size());
  double e = 0.0;
  for (Eigen::Index i = 0; i < clean.size(); ++i) {
    e = i == 0 ? noise(rng) : rho * e + innovation * noise(rng);
    y[i] = clean[i] + e;
    if (u(rng) < defects.outlier_probability) y[i] += (u(rng) < 0.5 ? -1 : 1) * outlier;
    if (i > 0 && u(rng) < defects.dropout_probability) y[i] = std::nan("");
  }
  return y;
}

std::vector<double> MergeTimes(const std::vector<std::vector<double>>& grids) {
  std::vector<double> all;
  for (const auto& g : grids) all.insert(all.end(), g.begin(), g.end());
  std::sort(all.begin(), all.end());
  std::vector<double> rows;
  for (double t : all) {
    if (rows.empty() || t - rows.back() > 1e-9) rows.push_back(t);
  }
  return rows;
}

std::vector<double> OnRows(const std::vector<double>& rows, const std::vector<double>& t,
                           const std::vector<double>& v) {
  std::vector<double> col(rows.size(), std::nan(""));
  std::size_t r = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    while (rows[r] < t[i] - 1e-9) ++r;
    col[r] = v[i];
  }
  return col;
}

Commands HeldCommands(const Vehicle& v, const TrialDesign& design, double rate_hz) {
  const auto designed = MakeExcitation(v, design);
  Commands cmd;
  cmd.t = SampleTimes(rate_hz, design.duration);
  for (double b : designed->Breakpoints()) cmd.t.push_back(b);
  std::sort(cmd.t.begin(), cmd.t.end());
  cmd.t.erase(std::unique(cmd.t.begin(), cmd.t.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              cmd.t.end());
  cmd.force.resize(cmd.t.size());
  cmd.mapping.resize(cmd.t.size());
  for (std::size_t i = 0; i < cmd.t.size(); ++i) {
    cmd.force[i] = designed->Force(cmd.t[i]);
    cmd.mapping[i] = designed->Mapping(cmd.t[i]);
  }
  return cmd;
}

void LogMappingColumn(const Vehicle& v, const Commands& cmd, TrialLog* log) {
  const bool mapping_varies = std::any_of(cmd.mapping.begin(), cmd.mapping.end(),
                                          [&](int m) { return m != cmd.mapping.front(); });
  if (!mapping_varies) return;
  for (const auto& m : v.mappings) log->mapping_names.push_back(m.name);
  std::vector<double> as_double(cmd.mapping.begin(), cmd.mapping.end());
  const std::vector<double> col = OnRows(log->t, cmd.t, as_double);
  log->mapping.resize(col.size());
  for (std::size_t i = 0; i < col.size(); ++i) {
    log->mapping[i] = std::isnan(col[i]) ? -1 : static_cast<int>(col[i]);
  }
}

}  // namespace uuvplan::model::internal
