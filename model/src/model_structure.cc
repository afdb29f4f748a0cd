#include "uuvplan/model/model_structure.h"

#include <algorithm>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

bool ModelStructure::Has(std::string_view parameter) const {
  return std::find(parameters.begin(), parameters.end(), parameter) != parameters.end();
}

std::vector<std::string> ModelStructure::WithPrefix(std::string_view prefix) const {
  std::vector<std::string> out;
  for (const std::string& p : parameters) {
    if (StartsWith(p, prefix)) out.push_back(p);
  }
  return out;
}

std::vector<std::string> ModelStructure::OfEffect(std::string_view effect) const {
  const EffectEntry* entry = Effects().Find(effect);
  return entry ? Of(*entry) : std::vector<std::string>{};
}

std::vector<std::string> ModelStructure::Of(const EffectEntry& effect) const {
  std::vector<std::string> out;
  for (const std::string& p : parameters) {
    if (effect.Owns(p)) out.push_back(p);
  }
  return out;
}

void ModelStructure::Add(const std::string& parameter) {
  if (!Has(parameter)) parameters.push_back(parameter);
}

void ModelStructure::Remove(std::string_view parameter) {
  parameters.erase(std::remove(parameters.begin(), parameters.end(), parameter), parameters.end());
}

double ModelStructure::Setting(const std::string& key, double fallback) const {
  const auto it = settings.find(key);
  return it == settings.end() ? fallback : it->second;
}

ModelStructure ModelStructure::Standard(const Vehicle& vehicle, Dof dof,
                                        const std::vector<std::string>& mappings_used,
                                        bool ballast) {
  ModelStructure s;
  s.dof = dof;
  if (ballast) s.Add(std::string(param::kBiasStep));
  for (const auto& name : mappings_used) {
    const int i = vehicle.MappingIndex(name);
    if (i < 0) continue;
    const ThrustMapping& m = vehicle.mappings[i];
    for (Direction d : {Direction::kPos, Direction::kNeg}) {
      if (!m.IsOpenWater(d)) s.Add(EtaName(m.name, d));
    }
  }
  return s;
}

ModelStructure WithWrittenEffects(ModelStructure base, const DofParameters& written,
                                  std::vector<std::string>* added) {
  for (const auto& [name, value] : written.params) {
    if (name == param::kMass || name == param::kBiasStep || base.Has(name)) continue;
    if (StartsWith(name, param::kEtaPrefix)) continue;
    base.Add(name);
    if (added) added->push_back(name);
  }
  for (const auto& [key, value] : written.settings) base.settings.emplace(key, value);
  return base;
}

}  // namespace uuvplan::model
