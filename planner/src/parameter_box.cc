// The a priori box of a DOF's parameters (see parameter_box.h).
#include "uuvplan/planner/parameter_box.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {

bool IsEta(const std::string& name) { return model::StartsWith(name, model::param::kEtaPrefix); }

// The planner's nominal-θ policy for a parameter with neither an a priori value nor an
// estimate: eta_nominal for installation coefficients, 0 for the rest (bias, bias_step: no a
// priori value). ident/src/identify.cc has its own; issue #12 moves one policy into the model,
// which will replace this function.
double NominalWithoutValue(const std::string& name, const BoxOptions& options) {
  return IsEta(name) ? options.eta_nominal : 0.0;
}

// The drag axis (k and kq scaled together by [drag_lo, drag_hi]) and, when the box has free
// installation coefficients, their axis over the options' eta range.
void AddDragAndEtaAxes(double drag_lo, double drag_hi, const std::vector<std::string>& etas,
                       const BoxOptions& options, ParameterBox* box) {
  box->axes.push_back({"drag",
                       {model::param::kLinearDrag, model::param::kQuadraticDrag},
                       drag_lo,
                       drag_hi,
                       true});
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

ParameterBox APrioriBox(const model::Vehicle& vehicle, model::Dof dof,
                        const std::vector<std::string>& names, const BoxOptions& options,
                        std::vector<std::string>* notes) {
  ParameterBox box;
  const auto mb = vehicle.InertiaBounds(dof);
  const double m_mid = 0.5 * (mb[0] + mb[1]);
  double k = 0.0, kq = 0.0, rel = options.fallback_drag_rel_sigma;
  auto prior = vehicle.priors.find(dof);
  if (prior != vehicle.priors.end() && prior->second.drag) {
    k = prior->second.drag->k;
    kq = prior->second.drag->kq;
    rel = prior->second.drag->rel_sigma;
  } else {
    // Bluff body: kq = ½·ρ·C_D·A (translation), ρ = 1000 kg/m³, C_D = 1 (open frame). For a
    // rotation, a plate of length l and height h about its centre: torque = ρ·C_D·h·l⁴/64·r².
    const double l = vehicle.size[0], w = vehicle.size[1], h = vehicle.size[2];
    constexpr double kRho = 1000.0, kCd = 1.0;
    switch (dof) {
      case model::Dof::kSurge:
        kq = 0.5 * kRho * kCd * w * h;
        break;
      case model::Dof::kSway:
        kq = 0.5 * kRho * kCd * l * h;
        break;
      case model::Dof::kHeave:
        kq = 0.5 * kRho * kCd * l * w;
        break;
      case model::Dof::kRoll:
        kq = kRho * kCd * l * std::pow(std::max(w, h), 4) / 64.0;
        break;
      case model::Dof::kPitch:
        kq = kRho * kCd * w * std::pow(std::max(l, h), 4) / 64.0;
        break;
      case model::Dof::kYaw:
        kq = kRho * kCd * h * std::pow(std::max(l, w), 4) / 64.0;
        break;
    }
    k = 0.1 * kq;
    if (notes) {
      std::ostringstream s;
      s << model::DofName(dof) << ": no a priori drag (dofs." << model::DofName(dof)
        << ".drag in the vehicle file); planned with a bluff-body estimate k = " << k
        << ", kq = " << kq << " (C_D = 1 on the frontal area of `size`), rel_sigma " << rel
        << ". Give the drag of a previous fit to plan better.";
      notes->push_back(s.str());
    }
  }
  std::vector<std::string> etas;
  for (const auto& n : names) {
    if (n == model::param::kMass) {
      box.nominal[n] = m_mid;
    } else if (n == model::param::kLinearDrag) {
      box.nominal[n] = k;
    } else if (n == model::param::kQuadraticDrag) {
      box.nominal[n] = kq;
    } else {
      box.nominal[n] = NominalWithoutValue(n, options);
      if (IsEta(n)) etas.push_back(n);
    }
  }
  box.axes.push_back({"m", {model::param::kMass}, mb[0] / m_mid, mb[1] / m_mid, true});
  const double half = options.drag_sigmas * rel;
  AddDragAndEtaAxes(std::max(0.05, 1.0 - half), 1.0 + half, etas, options, &box);
  return box;
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

}  // namespace uuvplan::planner
