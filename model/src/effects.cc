#include "uuvplan/model/effects.h"

#include <algorithm>
#include <stdexcept>

#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

bool ProposalEvidence::Has(std::string_view parameter) const {
  return parameters &&
         std::find(parameters->begin(), parameters->end(), parameter) != parameters->end();
}

double ProposalEvidence::Value(std::string_view parameter, double fallback) const {
  if (!values) return fallback;
  const auto it = values->find(std::string(parameter));
  return it == values->end() ? fallback : it->second;
}

bool EffectEntry::Owns(std::string_view parameter) const {
  return std::any_of(parameters.begin(), parameters.end(),
                     [&](const ParameterFamily& f) { return f.Matches(parameter); });
}

const EffectEntry* EffectTable::Find(std::string_view name) const {
  for (const EffectEntry& e : entries_) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const EffectEntry* EffectTable::OwnerOf(std::string_view parameter) const {
  for (const EffectEntry& e : entries_) {
    if (e.Owns(parameter)) return &e;
  }
  return nullptr;
}

std::string EffectTable::NameList() const {
  std::vector<std::string> names;
  for (const EffectEntry& e : entries_) names.push_back(e.name);
  return Join(names);
}

std::vector<std::string> EffectTable::Diagnosable() const {
  std::vector<std::string> names;
  for (const EffectEntry& e : entries_) {
    if (e.diagnosable) names.push_back(e.name);
  }
  return names;
}

void EffectTable::Register(EffectEntry entry) {
  if (Find(entry.name)) throw std::invalid_argument("effect '" + entry.name + "' registered twice");
  if (entry.site == EffectSite::kForceTerm && !entry.make_term) {
    throw std::invalid_argument("effect '" + entry.name + "' acts by a force term but has none");
  }
  entries_.push_back(std::move(entry));
}

void EffectTable::Unregister(std::string_view name) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const EffectEntry& e) { return e.name == name; }),
                 entries_.end());
}

EffectTable& EffectTable::Mutable() {
  static EffectTable table = [] {
    EffectTable t;
    for (EffectEntry& e : internal::BuiltInEffects()) t.Register(std::move(e));
    return t;
  }();
  return table;
}

const EffectTable& Effects() { return EffectTable::Mutable(); }

ScopedEffect::ScopedEffect(EffectEntry entry) : name_(entry.name) {
  EffectTable::Mutable().Register(std::move(entry));
}

ScopedEffect::~ScopedEffect() { EffectTable::Mutable().Unregister(name_); }

}  // namespace uuvplan::model
