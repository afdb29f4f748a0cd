// Internal to the truth reader: the truth file's parameters shared by its standard-model
// parameters (truth_yaml.cc) and its effect settings (truth_effects.cc).
#pragma once

#include <string>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// Sets a true parameter; fails at `where` if it is given twice.
void SetParam(model::DofTruth* truth, const std::string& name, double value, const Value& where);

/// A qualified family's map, {<qualifier>: value} (eta: {<mapping>.<pos|neg>: v}).
void ParseQualified(const model::ParameterFamily& family, const Value& v, model::Dof dof,
                    const model::Vehicle& vehicle, model::DofTruth* truth);

/// The settings of one effect (dofs.<dof>.effects.<effect>), as the effect table declares them.
void ParseEffectSettings(const model::EffectEntry& effect, const Value& v, model::Dof dof,
                         const model::Vehicle& vehicle, model::DofTruth* truth);

}  // namespace uuvplan::io
