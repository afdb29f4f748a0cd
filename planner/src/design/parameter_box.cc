// The a priori box of a DOF's parameters (see parameter_box.h).
#include "uuvplan/planner/design/parameter_box.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/prior.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {

bool IsEta(const std::string& name) { return model::StartsWith(name, model::param::kEtaPrefix); }

// A parameter the estimates do not cover: the box's η centre, else the model's nominal value
// (model/prior.h: an effect's null value).
double NominalWithoutValue(const std::string& name, const BoxOptions& options) {
  return IsEta(name) ? options.eta_nominal : model::NullValue(name);
}

// The drag axis (k and kq scaled together by [drag_lo, drag_hi]) and, when the box has free
// installation coefficients, their axis over the options' eta range.
void AddDragAndEtaAxes(double drag_lo, double drag_hi, const std::vector<std::string>& etas,
                       const BoxOptions& options, ParameterBox* box) {
  box->axes.push_back(
      {"drag", {model::param::kLinearDrag, model::param::kQuadraticDrag}, drag_lo, drag_hi, true});
  if (!etas.empty()) {
    box->axes.push_back({"eta", etas, options.eta_range[0] / options.eta_nominal,
                         options.eta_range[1] / options.eta_nominal, false});
  }
}

void AddPoints(const ParameterBox& box, const std::vector<int>& axes,
               const std::vector<std::vector<double>>& values, std::vector<double>* factors,
               std::size_t a, std::vector<ParameterValues>* out) {
  if (a == axes.size()) {
    out->push_back(box.At(*factors));
    return;
  }
  for (double f : values[a]) {
    (*factors)[axes[a]] = f;
    AddPoints(box, axes, values, factors, a + 1, out);
  }
}

}  // namespace

ParameterValues ParameterBox::At(const std::vector<double>& factors) const {
  ParameterValues p = nominal;
  for (std::size_t a = 0; a < axes.size() && a < factors.size(); ++a) {
    for (const auto& name : axes[a].params) {
      if (auto it = p.find(name); it != p.end()) it->second = nominal.at(name) * factors[a];
    }
  }
  return p;
}

double ParameterBox::Nominal(const std::string& name, double fallback) const {
  auto it = nominal.find(name);
  return it == nominal.end() ? fallback : it->second;
}

std::vector<ParameterValues> ParameterBox::Sample(int n, std::uint64_t seed) const {
  std::mt19937_64 rng(model::SplitMix64(seed));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ParameterValues> out;
  std::vector<double> factors(axes.size());
  for (int k = 0; k < n; ++k) {
    for (std::size_t a = 0; a < axes.size(); ++a) {
      factors[a] = axes[a].lo + unit(rng) * (axes[a].hi - axes[a].lo);
    }
    out.push_back(At(factors));
  }
  return out;
}

std::vector<ParameterValues> ParameterBox::DesignPoints() const {
  std::vector<ParameterValues> out = {nominal};
  std::vector<int> idx;
  std::vector<std::vector<double>> values;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (!axes[a].in_design || axes[a].lo == axes[a].hi) continue;
    idx.push_back(static_cast<int>(a));
    values.push_back({axes[a].lo, axes[a].hi});
  }
  if (idx.empty()) return out;
  std::vector<double> factors(axes.size(), 1.0);
  AddPoints(*this, idx, values, &factors, 0, &out);
  return out;
}

std::vector<ParameterValues> ParameterBox::CheckPoints(int per_axis) const {
  per_axis = std::max(2, per_axis);
  std::vector<int> idx;
  std::vector<std::vector<double>> values;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (axes[a].lo == axes[a].hi) continue;
    idx.push_back(static_cast<int>(a));
    std::vector<double> v;
    for (int i = 0; i < per_axis; ++i) {
      v.push_back(axes[a].lo + (axes[a].hi - axes[a].lo) * i / (per_axis - 1));
    }
    values.push_back(v);
  }
  std::vector<ParameterValues> out;
  std::vector<double> factors(axes.size(), 1.0);
  AddPoints(*this, idx, values, &factors, 0, &out);
  return out;
}

// Centred on the model's nominal values (model/prior.h), except η: the box is centred on
// options.eta_nominal, a planning assumption (installation losses are expected, ref 000
// Table III), not a prior.
ParameterBox APrioriBox(const model::Vehicle& vehicle, model::Dof dof,
                        const std::vector<std::string>& names, const BoxOptions& options,
                        std::vector<std::string>* notes) {
  ParameterBox box;
  const auto mb = vehicle.InertiaBounds(dof);
  const model::APrioriDrag drag = model::DragOf(vehicle, dof, options.fallback_drag_rel_sigma);
  const double rel = drag.drag.rel_sigma;
  if (!drag.from_vehicle_file() && notes) {
    notes->push_back(model::DragAssumption(dof, drag) +
                     ". Give the drag of a previous fit to plan better.");
  }
  box.nominal = model::NominalValues(vehicle, dof, names, options.fallback_drag_rel_sigma);
  std::vector<std::string> etas;
  for (const auto& n : names) {
    if (!IsEta(n)) continue;
    box.nominal[n] = options.eta_nominal;
    etas.push_back(n);
  }
  const double m_mid = 0.5 * (mb[0] + mb[1]);
  box.axes.push_back({"m", {model::param::kMass}, mb[0] / m_mid, mb[1] / m_mid, true});
  const double half = options.drag_sigmas * rel;
  AddDragAndEtaAxes(std::max(0.05, 1.0 - half), 1.0 + half, etas, options, &box);
  return box;
}

ParameterBox JointAPrioriBox(const model::Vehicle& vehicle, const model::MultiDofModel& model,
                             const BoxOptions& options, std::vector<std::string>* notes) {
  ParameterBox joint;
  for (int i = 0; i < model.num_dofs(); ++i) {
    const std::string prefix = std::string(model::DofName(model.dof(i))) + ".";
    std::vector<std::string> names;
    for (int j = 0; j < model.num_parameters(); ++j) {
      const auto [dof, local] = model.LocalName(j);
      if (dof == model.dof(i)) names.push_back(local);
    }
    const ParameterBox box = APrioriBox(vehicle, model.dof(i), names, options, notes);
    for (const auto& [name, value] : box.nominal) joint.nominal[prefix + name] = value;
    for (BoxAxis axis : box.axes) {
      axis.in_design = axis.name == "m";
      axis.name = prefix + axis.name;
      for (std::string& p : axis.params) p = prefix + p;
      joint.axes.push_back(axis);
    }
  }
  return joint;
}

ParameterBox EstimateBox(const ParameterValues& estimates, const ParameterValues& sigmas,
                         const std::vector<std::string>& names, double n_sigma,
                         const BoxOptions& options) {
  ParameterBox box;
  std::vector<std::string> etas;
  for (const auto& n : names) {
    auto it = estimates.find(n);
    box.nominal[n] = it != estimates.end() ? it->second : NominalWithoutValue(n, options);
    if (IsEta(n) && it == estimates.end()) etas.push_back(n);
  }
  auto rel = [&](const std::string& n) {
    auto v = estimates.find(n);
    auto s = sigmas.find(n);
    if (v == estimates.end() || s == sigmas.end() || v->second == 0.0) return 0.0;
    return std::min(0.9, n_sigma * s->second / std::abs(v->second));
  };
  const double rm = rel(model::param::kMass);
  box.axes.push_back({"m", {model::param::kMass}, 1.0 - rm, 1.0 + rm, true});
  const double rd = std::max(rel(model::param::kLinearDrag), rel(model::param::kQuadraticDrag));
  AddDragAndEtaAxes(1.0 - rd, 1.0 + rd, etas, options, &box);
  return box;
}

ParameterBox BoxAboutEstimates(const ParameterBox& apriori, const std::vector<std::string>& names,
                               const ParameterValues& estimates, const ParameterValues& sigmas,
                               double n_sigma, const BoxOptions& options) {
  ParameterValues centre = apriori.nominal;
  for (const auto& [name, value] : estimates) {
    if (centre.count(name)) centre[name] = value;
  }
  ParameterBox box = EstimateBox(centre, sigmas, names, n_sigma, options);
  for (BoxAxis& axis : box.axes) {
    bool estimated = false;
    for (const auto& p : axis.params) {
      estimated = estimated || (estimates.count(p) && sigmas.count(p));
    }
    if (estimated) continue;
    for (const BoxAxis& a : apriori.axes) {
      if (a.name != axis.name) continue;
      // The a priori factors, about the a priori centre.
      const std::string& ref = axis.params.front();
      const double scale = box.Nominal(ref) != 0.0 ? apriori.Nominal(ref) / box.Nominal(ref) : 1.0;
      axis.lo = a.lo * scale;
      axis.hi = a.hi * scale;
    }
  }
  return box;
}

namespace {

// "m = 0.575 ± 0.073 kg·m², k = 4.29 ± 0.1 N·m·s/rad": the estimates a box is centred on (a
// parameter held, σ 0, as "η = 1 (held)").
std::string EstimatesText(model::Dof dof, const model::DofParameters& model,
                          const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) {
    const auto value = model.params.find(name);
    const auto sigma = model.sigma.find(name);
    if (value == model.params.end() || sigma == model.sigma.end()) continue;
    std::string unit = model::Unit(name, dof);
    if (unit == "1") unit.clear();  // a ratio (η)
    text += (text.empty() ? "" : ", ") + name + " = " + model::Significant(value->second, 4);
    if (sigma->second > 0) {
      text += " ± " + model::Significant(sigma->second, 2) + (unit.empty() ? "" : " " + unit);
    } else {
      text += (unit.empty() ? "" : " " + unit) + " (held)";
    }
  }
  return text;
}

// No axis of `box` wider than the same axis of `apriori` (as factors of their own centres):
// an estimate narrows what was known a priori, never widens it (an insignificant k at
// ± 300% would otherwise make the drag box wider than the vehicle file's ± rel_sigma).
void NoWiderThan(const ParameterBox& apriori, ParameterBox* box) {
  for (BoxAxis& axis : box->axes) {
    for (const BoxAxis& a : apriori.axes) {
      if (a.name != axis.name || axis.hi - axis.lo <= a.hi - a.lo) continue;
      const double centre = 0.5 * (axis.lo + axis.hi), half = 0.5 * (a.hi - a.lo);
      axis.lo = std::max(0.05, centre - half);
      axis.hi = centre + half;
    }
  }
}

}  // namespace

ParameterBox PlanningBox(const model::Vehicle& vehicle, model::Dof dof,
                         const std::vector<std::string>& names, const BoxOptions& options,
                         std::vector<std::string>* notes) {
  const auto model = vehicle.models.find(dof);
  if (model == vehicle.models.end() || !model->second.identified()) {
    return APrioriBox(vehicle, dof, names, options, notes);
  }
  const ParameterBox apriori = APrioriBox(vehicle, dof, names, options, nullptr);
  if (notes) {
    const std::string about = model->second.origin.empty()
                                  ? "the identified model of the vehicle file"
                                  : model->second.origin;
    notes->push_back(std::string(model::DofName(dof)) + ": planned about " + about + " ± " +
                     model::Significant(options.estimate_sigmas, 3) +
                     "σ, no wider than the a priori box (" +
                     EstimatesText(dof, model->second, names) + ")");
  }
  ParameterBox box = BoxAboutEstimates(apriori, names, model->second.params, model->second.sigma,
                                       options.estimate_sigmas, options);
  NoWiderThan(apriori, &box);
  ClampToLeastInertia(vehicle, dof, apriori, &box, notes);
  return box;
}

double LeastInertia(const model::Vehicle& vehicle, model::Dof dof) {
  return (model::IsRotational(dof) ? 0.5 : 1.0) * vehicle.RigidInertia(dof);
}

void ClampToLeastInertia(const model::Vehicle& vehicle, model::Dof dof, const ParameterBox& apriori,
                         ParameterBox* box, std::vector<std::string>* notes) {
  const double least = LeastInertia(vehicle, dof);
  const std::string& mass = model::param::kMass;
  const double nominal = box->Nominal(mass);
  if (!(least > 0) || !(nominal > 0)) return;
  for (BoxAxis& axis : box->axes) {
    if (axis.name != "m") continue;
    if (axis.hi * nominal >= least) {
      axis.lo = std::max(axis.lo, least / nominal);
      if (axis.lo > 1.0) {  // the centre moves into what is left of the axis
        const double centre = 0.5 * (axis.lo + axis.hi);
        box->nominal[mass] = centre * nominal;
        axis.lo /= centre;
        axis.hi /= centre;
      }
      return;
    }
    const double top = axis.hi * nominal;
    for (const BoxAxis& a : apriori.axes) {
      if (a.name == "m") axis = a;
    }
    box->nominal[mass] = apriori.Nominal(mass);
    if (notes) {
      const std::string unit = model::Unit(mass, dof);
      notes->push_back(std::string(model::DofName(dof)) + ": the estimate of m (" +
                       model::Significant(nominal, 3) + " " + unit + ", box up to " +
                       model::Significant(top, 3) + ") lies below the least physical " +
                       model::Significant(least, 3) + " " + unit +
                       ": planned over the m of the vehicle file instead");
    }
    return;
  }
}

}  // namespace uuvplan::planner
