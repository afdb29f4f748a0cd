#include "uuvplan/model/excitation.h"

#include <algorithm>
#include <cmath>

namespace uuvplan::model {
namespace {

class SteadyExcitation final : public Excitation {
 public:
  SteadyExcitation(double force, int mapping, double duration)
      : force_(force), mapping_(mapping), duration_(duration) {}
  double Force(double) const override { return force_; }
  int Mapping(double) const override { return mapping_; }
  bool piecewise_constant() const override { return true; }
  double duration() const override { return duration_; }

 private:
  double force_;
  int mapping_;
  double duration_;
};

class SineExcitation final : public Excitation {
 public:
  SineExcitation(double offset, double amplitude, double omega, int mapping, double duration)
      : offset_(offset), amplitude_(amplitude), omega_(omega), mapping_(mapping),
        duration_(duration) {}
  double Force(double t) const override { return offset_ + amplitude_ * std::sin(omega_ * t); }
  int Mapping(double) const override { return mapping_; }
  double duration() const override { return duration_; }

 private:
  double offset_, amplitude_, omega_;
  int mapping_;
  double duration_;
};

// Piecewise constant on [t_i, t_{i+1}); used both for segments and for held log samples.
class HeldExcitation final : public Excitation {
 public:
  HeldExcitation(std::vector<double> t, std::vector<double> force, std::vector<int> mapping,
                 double duration)
      : t_(std::move(t)), force_(std::move(force)), mapping_(std::move(mapping)),
        duration_(duration) {}
  double Force(double t) const override { return t_.empty() ? 0.0 : force_[Find(t)]; }
  int Mapping(double t) const override { return t_.empty() ? -1 : mapping_[Find(t)]; }
  void Sample(double t, double* force, int* mapping) const override {
    if (t_.empty()) {
      *force = 0.0;
      *mapping = -1;
      return;
    }
    const std::size_t i = Find(t);
    *force = force_[i];
    *mapping = mapping_[i];
  }
  std::vector<double> Breakpoints() const override {
    std::vector<double> b;
    for (std::size_t i = 1; i < t_.size(); ++i) {
      if (t_[i] > 0 && t_[i] < duration_ &&
          (force_[i] != force_[i - 1] || mapping_[i] != mapping_[i - 1])) {
        b.push_back(t_[i]);
      }
    }
    return b;
  }
  bool piecewise_constant() const override { return true; }
  double duration() const override { return duration_; }

 private:
  // Index of the sample in force at t. Integration queries move forward in time, so the last
  // answer is tried first; a binary search handles the rest.
  std::size_t Find(double t) const {
    std::size_t i = last_;
    if (i < t_.size() && t_[i] <= t && (i + 1 == t_.size() || t < t_[i + 1])) return i;
    if (i + 1 < t_.size() && t_[i + 1] <= t && (i + 2 == t_.size() || t < t_[i + 2])) {
      return last_ = i + 1;
    }
    auto it = std::upper_bound(t_.begin(), t_.end(), t);
    last_ = it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
    return last_;
  }
  std::vector<double> t_, force_;
  std::vector<int> mapping_;
  double duration_;
  mutable std::size_t last_ = 0;
};

}  // namespace

std::unique_ptr<Excitation> MakeSteadyExcitation(double force, int mapping, double duration) {
  return std::make_unique<SteadyExcitation>(force, mapping, duration);
}

std::unique_ptr<Excitation> MakeSineExcitation(double offset, double amplitude, double omega,
                                               int mapping, double duration) {
  return std::make_unique<SineExcitation>(offset, amplitude, omega, mapping, duration);
}

std::unique_ptr<Excitation> MakeSegmentsExcitation(std::vector<Segment> segments) {
  std::vector<double> t, force;
  std::vector<int> mapping;
  double now = 0.0;
  for (const auto& s : segments) {
    t.push_back(now);
    force.push_back(s.force);
    mapping.push_back(s.mapping);
    now += s.duration;
  }
  return std::make_unique<HeldExcitation>(std::move(t), std::move(force), std::move(mapping), now);
}

std::unique_ptr<Excitation> MakeHeldExcitation(std::vector<double> t, std::vector<double> force,
                                               std::vector<int> mapping, double duration) {
  // Drop samples without a force value: the previous command holds (zero-order hold).
  std::vector<double> tt, ff;
  std::vector<int> mm;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isnan(force[i])) continue;
    tt.push_back(t[i]);
    ff.push_back(force[i]);
    mm.push_back(i < mapping.size() ? mapping[i] : -1);
  }
  if (!tt.empty()) tt.front() = std::min(tt.front(), 0.0);
  return std::make_unique<HeldExcitation>(std::move(tt), std::move(ff), std::move(mm), duration);
}

}  // namespace uuvplan::model
