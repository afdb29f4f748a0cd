#include "uuvplan/model/excitation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rotating_sine.h"

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
      : offset_(offset),
        amplitude_(amplitude),
        sine_(omega, 0.0),
        mapping_(mapping),
        duration_(duration) {}
  double Force(double t) const override { return offset_ + amplitude_ * sine_.At(t); }
  int Mapping(double) const override { return mapping_; }
  double duration() const override { return duration_; }

 private:
  double offset_, amplitude_;
  mutable internal::RotatingSine sine_;
  int mapping_;
  double duration_;
};

// Piecewise constant on [t_i, t_{i+1}) (before t_0 the first row holds); used both for segments
// and for held log samples. Each row is a command of its own (its force or mapping differs from
// the previous row's), so every row after the first is a jump, and the breakpoints are the rows'
// times within (0, duration): a slice, not a list. The rows are views: of the rows it owns, or
// of the caller's (MakeHeldExcitationOver).
class HeldExcitation final : public Excitation {
 public:
  struct Rows {
    std::vector<double> t, force;
    std::vector<int> mapping;
  };
  explicit HeldExcitation(Rows owned, double duration)
      : owned_(std::move(owned)),
        t_(owned_.t),
        force_(owned_.force.data()),
        mapping_(owned_.mapping.data()),
        duration_(duration),
        breaks_(Jumps()) {}
  HeldExcitation(TimesView t, const double* force, const int* mapping, double duration)
      : t_(t), force_(force), mapping_(mapping), duration_(duration), breaks_(Jumps()) {}
  HeldExcitation(const HeldExcitation&) = delete;  // the views may refer to owned_
  HeldExcitation& operator=(const HeldExcitation&) = delete;
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
  TimesView Breakpoints() const override { return breaks_; }
  bool piecewise_constant() const override { return true; }
  double duration() const override { return duration_; }

 private:
  // The rows' times after the first within (0, duration) (t_ ascends).
  TimesView Jumps() const {
    std::size_t lo = 1, hi = t_.size();
    while (lo < hi && !(t_[lo] > 0)) ++lo;
    while (hi > lo && !(t_[hi - 1] < duration_)) --hi;
    return lo < hi ? t_.Slice(lo, hi) : TimesView();
  }
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
  Rows owned_;
  TimesView t_;
  const double* force_;
  const int* mapping_;
  double duration_;
  TimesView breaks_;
  mutable std::size_t last_ = 0;
};

class SwitchedExcitation final : public Excitation {
 public:
  SwitchedExcitation(SwitchedWave wave, double duration)
      : wave_(std::move(wave)),
        duration_(duration),
        switches_(wave_.Switches(duration)),
        rotating_(wave_) {}
  SwitchedExcitation(const SwitchedExcitation&) = delete;  // rotating_ refers to wave_
  SwitchedExcitation& operator=(const SwitchedExcitation&) = delete;
  double Force(double t) const override {
    int mapping = -1;
    return wave_.Switch(rotating_.At(t), &mapping);
  }
  int Mapping(double t) const override {
    int mapping = -1;
    wave_.Switch(rotating_.At(t), &mapping);
    return mapping;
  }
  void Sample(double t, double* force, int* mapping) const override {
    *force = wave_.Switch(rotating_.At(t), mapping);
  }
  TimesView Breakpoints() const override { return switches_; }
  double duration() const override { return duration_; }

 private:
  SwitchedWave wave_;
  double duration_;
  std::vector<double> switches_;
  mutable internal::RotatingWave rotating_;
};

}  // namespace

double SwitchedWave::Wave(double t) const {
  double w = offset;
  for (const SineComponent& c : components) w += c.amplitude * std::sin(c.omega * t + c.phase);
  return w;
}

double SwitchedWave::Force(double t, int* mapping) const { return Switch(Wave(t), mapping); }

double SwitchedWave::Switch(double w, int* mapping) const {
  if (w >= 0) {
    *mapping = mapping_pos;
    return std::max(w, floor_pos);
  }
  *mapping = mapping_neg;
  return std::min(w, -floor_neg);
}

std::vector<double> SwitchedWave::Switches(double duration) const {
  // Sampled at 1/100 of the shortest period (at most 0.05 s), each sign change bisected
  // (Illinois regula falsi took 8% off a pool verdict but moved the switches within their
  // 1e-9 s, and DIRECT then chose other designs: the numbers are kept).
  double h = 0.05;
  for (const SineComponent& c : components) {
    if (c.omega > 0 && c.amplitude != 0) h = std::min(h, 2 * M_PI / c.omega / 100.0);
  }
  std::vector<double> out;
  if (!(duration > 0)) return out;
  internal::RotatingWave scanned(*this);  // the scan's samples are h apart: rotated sines
  const std::size_t n = static_cast<std::size_t>(std::ceil(duration / h));
  double t0 = 0.0, w0 = scanned.At(0.0);
  for (std::size_t i = 1; i <= n; ++i) {
    const double t1 = std::min(duration, i * h), w1 = scanned.At(t1);
    if ((w0 >= 0) != (w1 >= 0)) {
      double a = t0, b = t1;
      while (b - a > 1e-9) {
        const double c = 0.5 * (a + b);
        ((Wave(c) >= 0) == (w0 >= 0) ? a : b) = c;
      }
      if (b > 0 && b < duration) out.push_back(b);
    }
    t0 = t1;
    w0 = w1;
  }
  return out;
}

std::unique_ptr<Excitation> MakeSwitchedExcitation(SwitchedWave wave, double duration) {
  return std::make_unique<SwitchedExcitation>(std::move(wave), duration);
}

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
  return MakeHeldExcitation(t, force, mapping, now);
}

namespace {

// The mapping of row i (-1 past the end of `mapping`).
int RowMapping(const std::vector<int>& mapping, std::size_t i) {
  return i < mapping.size() ? mapping[i] : -1;
}

// Calls keep(i) on each row the zero-order hold keeps, in order: a row without a force value is
// skipped (the previous command holds), and so is a row that repeats the previous kept command
// (a log at 100 Hz of legs of 10–40 s holds 1,000–4,000 rows per command).
template <class Keep>
void ForEachKeptRow(std::size_t rows, const std::vector<double>& force,
                    const std::vector<int>& mapping, const Keep& keep) {
  std::size_t last = rows;
  for (std::size_t i = 0; i < rows; ++i) {
    if (std::isnan(force[i])) continue;
    if (last < rows && force[i] == force[last] &&
        RowMapping(mapping, i) == RowMapping(mapping, last)) {
      continue;
    }
    keep(i);
    last = i;
  }
}

}  // namespace

std::unique_ptr<Excitation> MakeHeldExcitation(TimesView t, const std::vector<double>& force,
                                               const std::vector<int>& mapping, double duration) {
  // The rows kept: counted first, so that each array is allocated once at its size.
  std::size_t kept = 0;
  ForEachKeptRow(t.size(), force, mapping, [&](std::size_t) { ++kept; });
  HeldExcitation::Rows rows;
  rows.t.reserve(kept);
  rows.force.reserve(kept);
  rows.mapping.reserve(kept);
  ForEachKeptRow(t.size(), force, mapping, [&](std::size_t i) {
    rows.t.push_back(t[i]);
    rows.force.push_back(force[i]);
    rows.mapping.push_back(RowMapping(mapping, i));
  });
  return std::make_unique<HeldExcitation>(std::move(rows), duration);
}

std::unique_ptr<Excitation> MakeHeldExcitationOver(TimesView t, const std::vector<double>& force,
                                                   const std::vector<int>& mapping,
                                                   double duration) {
  std::size_t kept = 0;
  if (force.size() == t.size() && mapping.size() == force.size()) {
    ForEachKeptRow(t.size(), force, mapping, [&](std::size_t) { ++kept; });
  }
  if (kept != t.size()) return MakeHeldExcitation(t, force, mapping, duration);
  return std::make_unique<HeldExcitation>(t, force.data(), mapping.data(), duration);
}

}  // namespace uuvplan::model
