#include "thruster_installation_yaml.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "uuvplan/io/number_text.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using model::Thruster;

namespace {

// A direction's norm may differ from 1 by this much and is then normalised: a unit vector
// written with 4 significant digits ([0.7071, 0.7071, 0]) is off by 1e-4; one off by more
// ([1, 1, 0]) is a mistake the reader refuses rather than guesses.
constexpr double kUnitTolerance = 1e-3;

// Within the vehicle's size of its centre on each axis: a box twice the vehicle's, which a
// thruster on an outrigger fits and a position in mm does not.
std::array<double, 3> ParsePosition(const Value& v, const std::array<double, 3>& size) {
  const std::string expectation =
      "a position [x, y, z] in m (body frame: x forward, y starboard, z down), each within the "
      "vehicle's size [" +
      model::Significant(size[0], 4) + ", " + model::Significant(size[1], 4) + ", " +
      model::Significant(size[2], 4) + "] of its centre";
  const std::array<double, 3> p = Triple(v, expectation);
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(p[i]) <= size[i])) v.Expected(expectation);
  }
  return p;
}

std::array<double, 3> ParseDirection(const Value& v) {
  const std::string expectation =
      "a unit vector [x, y, z] of positive thrust (body frame), norm within 1e-3 of 1";
  std::array<double, 3> d = Triple(v, expectation);
  const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(std::abs(norm - 1.0) <= kUnitTolerance)) {
    v.Fail("expected " + expectation + ", got norm " + model::Significant(norm, 6));
  }
  for (double& x : d) x /= norm;
  return d;
}

// thrust.dead_band: commands within it of neutral give no thrust; it must leave some command.
void ParseDeadBand(const MapValue& m, Thruster* t) {
  const MapValue thrust(m.Required("thrust"), "a thrust model");
  const Value band = thrust.Optional("dead_band");
  if (band.absent()) return;
  const auto [lo, hi] = t->SpanFromNeutral();
  const double reach = std::max(std::abs(lo), std::abs(hi));
  t->model.dead_band =
      NumberIf(band,
               "a dead band >= 0 in command units, below the command range's reach " +
                   model::Significant(reach, 4),
               [reach](double x) { return x >= 0 && x < reach; });
}

}  // namespace

void ParseThrusterInstallation(const MapValue& m, const std::array<double, 3>& size, Thruster* t) {
  const Value position = m.Optional("position"), direction = m.Optional("direction");
  if (position.absent() != direction.absent()) {
    m.self().Fail(std::string("expected both position and direction (or neither), got only ") +
                  (position.absent() ? "direction" : "position"));
  }
  if (!position.absent()) {
    t->geometry = model::ThrusterGeometry{ParsePosition(position, size), ParseDirection(direction)};
  }
  if (const Value r = m.Optional("reversible"); !r.absent()) {
    t->reversible = Choice(r, {"false", "true"}, "whether the thruster reverses in service") == 1;
  }
  ParseDeadBand(m, t);
}

void EmitThrusterInstallation(YAML::Emitter& out, const Thruster& t) {
  if (t.geometry) {
    for (const auto& [key, v] : {std::pair{"position", t.geometry->position},
                                 std::pair{"direction", t.geometry->direction}}) {
      out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << FileNumber(v[0])
          << FileNumber(v[1]) << FileNumber(v[2]) << YAML::EndSeq;
    }
  }
  if (t.reversible) out << YAML::Key << "reversible" << YAML::Value << true;
}

}  // namespace uuvplan::io
