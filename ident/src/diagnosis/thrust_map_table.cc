// The static thrust map a thrust_map finding implies, as the vehicle file states thrust: per
// thruster command (diagnosis.h CorrectedThrustMap). The finding's exponent p acts on the DOF
// force φ; in the vehicle file the map is a function of the command V, φ = Thrust(V)/share
// (ref 000 Table I), so a square thrust table with p = −½ delivers a force linear in V.
#include <algorithm>
#include <cmath>

#include "diagnosis_internal.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::diagnosis {

namespace {

struct Shape {
  double p = 0.0, reference = 1.0, deadzone = 0.0;
};

// Delivered DOF force of the extended model for nominal DOF force φ (dof_model_kernel.h
// Actuate: the dead zone, then the shape).
double Delivered(double phi, const Shape& s) {
  const double u0 = std::copysign(std::max(std::abs(phi) - s.deadzone, 0.0), phi);
  return u0 == 0.0 ? 0.0 : u0 * std::pow(std::abs(u0) / s.reference, s.p);
}

// The command from neutral of `thruster` that gives thruster force f (bisection: Thrust is
// monotonic).
double CommandFor(const model::Thruster& thruster, double f) {
  const auto [low, high] = thruster.SpanFromNeutral();
  double lo = f >= 0 ? 0.0 : low, hi = f >= 0 ? high : 0.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (thruster.model.Thrust(mid) < f ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// |V| range of the reference thruster's commands over the trials' samples of mapping `m`.
void CommandRange(const model::Vehicle& v, int m, int thruster, double share, const Trials& trials,
                  double* smallest, double* largest) {
  *smallest = 1e300;
  *largest = 0.0;
  const double fmax = MaxForce(trials);
  for (const TrialData* t : trials) {
    for (std::size_t i = 0; i < t->force.size(); ++i) {
      if (i >= t->mapping.size() || t->mapping[i] != m || std::abs(t->force[i]) < 0.01 * fmax) {
        continue;
      }
      const double c = std::abs(CommandFor(v.thrusters[thruster], share * t->force[i]));
      *smallest = std::min(*smallest, c);
      *largest = std::max(*largest, c);
    }
  }
}

// f = sign(V)·(a·V² + b·|V|), a, b ≥ 0, least squares over the rows.
void FitPoly2(CorrectedThrustMap* map) {
  double s4 = 0, s3 = 0, s2 = 0, s2f = 0, s1f = 0;
  for (const auto& r : map->rows) {
    const double v = std::abs(r.command), f = std::abs(r.delivered);
    s4 += v * v * v * v, s3 += v * v * v, s2 += v * v, s2f += v * v * f, s1f += v * f;
  }
  const double det = s4 * s2 - s3 * s3;
  double a = det > 0 ? (s2f * s2 - s1f * s3) / det : 0.0;
  double b = det > 0 ? (s4 * s1f - s3 * s2f) / det : 0.0;
  if (a < 0) a = 0, b = s2 > 0 ? s1f / s2 : 0.0;
  if (b < 0) b = 0, a = s4 > 0 ? s2f / s4 : 0.0;
  map->poly2_a = a;
  map->poly2_b = b;
}

// n of f_d ∝ |V|^n between the smallest and largest command, for exponent p.
double CommandExponent(const model::Thruster& thruster, double share, double v0, double v1,
                       const Shape& s) {
  const double f0 = std::abs(Delivered(thruster.model.Thrust(v0) / share, s));
  const double f1 = std::abs(Delivered(thruster.model.Thrust(v1) / share, s));
  return f0 > 0 && f1 > 0 ? std::log(f1 / f0) / std::log(v1 / v0) : std::nan("");
}

std::string ShapeName(double n, double range) {
  // Named when that power law stays within 20% of the fitted one over the commands used.
  if (std::pow(range, std::abs(n - 1.0)) <= 1.2) return "linear in the command";
  if (std::pow(range, std::abs(n - 2.0)) <= 1.2) return "square in the command";
  return "a power of the command, |command|^" + model::Significant(n, 3);
}

}  // namespace

std::vector<CorrectedThrustMap> CorrectedThrustMaps(const model::Vehicle& vehicle,
                                                    const StructureFit& f, const Trials& trials) {
  std::vector<CorrectedThrustMap> maps;
  const int k = FindEstimate(f.oe.estimates, model::param::kThrustExponent);
  const auto ref = f.structure.settings.find(model::param::kThrustReference);
  if (k < 0 || ref == f.structure.settings.end()) return maps;
  const Shape s{
      f.oe.estimates[k].value, ref->second,
      f.values.count(model::param::kDeadzone) ? f.values.at(model::param::kDeadzone) : 0.0};
  const double sigma_p = f.oe.estimates[k].sigma;
  std::set<int> mappings;
  for (const TrialData* t : trials) {
    for (int m : t->mapping) {
      if (m >= 0) mappings.insert(m);
    }
  }
  for (int m : mappings) {
    const model::ThrustMapping& mapping = vehicle.mappings[m];
    const auto ref_share = *std::max_element(
        mapping.shares.begin(), mapping.shares.end(),
        [](const auto& a, const auto& b) { return std::abs(a.second) < std::abs(b.second); });
    const model::Thruster& thruster = vehicle.thrusters[ref_share.first];
    const double share = ref_share.second;
    CorrectedThrustMap map{mapping.name, thruster.name, {}, 0, 0, 0, 0, 0, 0, {}, ""};
    CommandRange(vehicle, m, ref_share.first, share, trials, &map.smallest_command,
                 &map.largest_command);
    if (!(map.largest_command > map.smallest_command && map.smallest_command > 0)) continue;
    for (double sign : {-1.0, 1.0}) {
      for (int i = 0; i <= 6; ++i) {
        const double v =
            sign * (map.smallest_command + i / 6.0 * (map.largest_command - map.smallest_command));
        const double phi = thruster.model.Thrust(v) / share;
        const double fd = share * Delivered(phi, s);
        map.rows.push_back({v, thruster.model.Thrust(v), fd,
                            std::abs(fd * std::log(std::abs(phi) / s.reference)) * sigma_p});
      }
    }
    std::sort(map.rows.begin(), map.rows.end(),
              [](const auto& a, const auto& b) { return a.command < b.command; });
    map.command_exponent =
        CommandExponent(thruster, share, map.smallest_command, map.largest_command, s);
    Shape up = s;
    up.p += sigma_p;
    map.command_exponent_sigma =
        std::abs(CommandExponent(thruster, share, map.smallest_command, map.largest_command, up) -
                 map.command_exponent);
    map.shape = ShapeName(map.command_exponent, map.largest_command / map.smallest_command);
    FitPoly2(&map);
    maps.push_back(std::move(map));
  }
  return maps;
}

}  // namespace uuvplan::ident::diagnosis
