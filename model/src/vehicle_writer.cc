// Writes a vehicle file (contract §Vehicle) that ReadVehicle reads back to the same vehicle:
// the virtual pool stores the truth's vehicle beside the campaign it simulates.
#include <yaml-cpp/yaml.h>

#include "uuvplan/model/io.h"

namespace uuvplan::model {
namespace {

void EmitSensor(YAML::Emitter& out, const char* key, const std::optional<SensorSpec>& s) {
  if (!s) return;
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "rate"
      << YAML::Value << s->rate_hz << YAML::Key << "sigma" << YAML::Value << s->sigma
      << YAML::EndMap;
}

void EmitPair(YAML::Emitter& out, const std::array<double, 2>& p) {
  out << YAML::Flow << YAML::BeginSeq << p[0] << p[1] << YAML::EndSeq;
}

}  // namespace

void WriteVehicleYaml(const std::string& path, const Vehicle& v) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << v.name;
  out << YAML::Key << "mass" << YAML::Value << v.mass;
  out << YAML::Key << "size" << YAML::Value << YAML::Flow << YAML::BeginSeq << v.size[0]
      << v.size[1] << v.size[2] << YAML::EndSeq;
  if (!v.inertia.empty()) {
    out << YAML::Key << "inertia" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [dof, value] : v.inertia) {
      out << YAML::Key << std::string(DofName(dof)) << YAML::Value << value;
    }
    out << YAML::EndMap;
  }
  out << YAML::Key << "added_mass" << YAML::Value;
  EmitPair(out, v.added_mass);
  out << YAML::Key << "thrusters" << YAML::Value << YAML::BeginSeq;
  for (const auto& t : v.thrusters) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << t.name;
    out << YAML::Key << "thrust" << YAML::Value << YAML::BeginMap;
    if (t.model.kind == ThrustModel::Kind::kSquare) {
      out << YAML::Key << "model" << YAML::Value << "square" << YAML::Key << "c_pos"
          << YAML::Value << t.model.c_pos << YAML::Key << "c_neg" << YAML::Value << t.model.c_neg;
    } else {
      out << YAML::Key << "model" << YAML::Value << "poly2" << YAML::Key << "a" << YAML::Value
          << t.model.a << YAML::Key << "b" << YAML::Value << t.model.b;
    }
    if (t.model.deduction != 0.0) {
      out << YAML::Key << "deduction" << YAML::Value << t.model.deduction;
    }
    out << YAML::EndMap << YAML::Key << "command" << YAML::Value;
    EmitPair(out, {t.command_min, t.command_max});
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "min_thrust" << YAML::Value << v.min_thrust;
  out << YAML::Key << "mappings" << YAML::Value << YAML::BeginMap;
  for (const auto& m : v.mappings) {
    out << YAML::Key << m.name << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "dof" << YAML::Value << std::string(DofName(m.dof));
    out << YAML::Key << "shares" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [index, share] : m.shares) {
      out << YAML::Key << v.thrusters.at(index).name << YAML::Value << share;
    }
    out << YAML::EndMap;
    out << YAML::Key << "open_water" << YAML::Value << std::string(OpenWaterName(m.open_water));
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  if (!v.priors.empty()) {
    out << YAML::Key << "dofs" << YAML::Value << YAML::BeginMap;
    for (const auto& [dof, prior] : v.priors) {
      out << YAML::Key << std::string(DofName(dof)) << YAML::Value << YAML::BeginMap;
      if (prior.drag) {
        out << YAML::Key << "drag" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key
            << "k" << YAML::Value << prior.drag->k << YAML::Key << "kq" << YAML::Value
            << prior.drag->kq << YAML::Key << "rel_sigma" << YAML::Value << prior.drag->rel_sigma
            << YAML::EndMap;
      }
      if (prior.added_mass) {
        out << YAML::Key << "added_mass" << YAML::Value;
        EmitPair(out, *prior.added_mass);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  if (!v.sensors.empty()) {
    out << YAML::Key << "sensors" << YAML::Value << YAML::BeginMap;
    for (const auto& [dof, s] : v.sensors) {
      out << YAML::Key << std::string(DofName(dof)) << YAML::Value << YAML::BeginMap;
      EmitSensor(out, "position", s.position);
      EmitSensor(out, "velocity", s.velocity);
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  WriteFileAtomically(path, std::string("# written by uuvplan\n") + out.c_str() + "\n");
}

}  // namespace uuvplan::model
