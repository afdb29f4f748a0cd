// Sample times that several signals share: a velocity estimate's times are its positions'
// (8 bytes a sample of a long log). A read-only std::vector<double> held by
// reference count; copies share it, and a change detaches the changed copy first (copy on
// write), so a SharedTimes behaves as a value. Times logged on a uniform decimal clock can be
// held as that clock instead (CompactUniform; model::UniformClock: the very same doubles,
// computed, 0 bytes a sample). Read them as a model::TimesView (view(), or t[i]).
#pragma once

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <memory>
#include <vector>

#include "uuvplan/model/times_view.h"

namespace uuvplan::ident {

class SharedTimes {
 public:
  using value_type = double;
  using const_iterator = model::TimesView::const_iterator;

  SharedTimes() = default;
  SharedTimes(const SharedTimes&) = default;
  SharedTimes& operator=(const SharedTimes&) = default;
  SharedTimes(SharedTimes&& o) noexcept { *this = std::move(o); }
  SharedTimes& operator=(SharedTimes&& o) noexcept {
    times_ = std::move(o.times_);
    view_ = o.view_;
    o.view_ = {};
    return *this;
  }
  SharedTimes(std::vector<double> t) { *this = std::move(t); }  // NOLINT: a vector is times
  SharedTimes(std::initializer_list<double> t) : SharedTimes(std::vector<double>(t)) {}
  SharedTimes& operator=(std::vector<double> t) {
    times_ = std::make_shared<std::vector<double>>(std::move(t));
    view_ = *times_;
    return *this;
  }

  operator model::TimesView() const { return view_; }  // NOLINT: read as times
  const model::TimesView& view() const { return view_; }
  /// True when `other` holds the very same times (not a copy of them): the same vector, or the
  /// same uniform clock.
  bool SharesWith(const SharedTimes& other) const {
    if (uniform()) {
      return other.uniform() && *view_.clock() == *other.view_.clock() && size() == other.size();
    }
    return times_ && times_ == other.times_;
  }
  /// Whether the times are held as a uniform clock (no vector).
  bool uniform() const { return !times_ && !view_.empty(); }

  std::size_t size() const { return view_.size(); }
  bool empty() const { return view_.empty(); }
  double operator[](std::size_t i) const { return view_[i]; }
  double front() const { return view_.front(); }
  double back() const { return view_.back(); }
  const_iterator begin() const { return view_.begin(); }
  const_iterator end() const { return view_.end(); }

  /// Holds the times as their uniform clock when every time is (n0 + k·step)/10^d − offset bit
  /// for bit (d ≤ 9; `offset` is what was subtracted from the logged times); else unchanged.
  void CompactUniform(double offset);
  /// The `n` times at(0), …, at(n − 1), ascending, held as CompactUniform(offset) would hold
  /// them, with no vector made on the way when they are a uniform clock.
  static SharedTimes Of(std::size_t n, const std::function<double(std::size_t)>& at, double offset);

  // Changes (each detaches this copy from the others first; a clock becomes a vector again).
  void push_back(double t) {
    Change([t](std::vector<double>& v) { v.push_back(t); });
  }
  void reserve(std::size_t n) {
    Change([n](std::vector<double>& v) { v.reserve(n); });
  }
  void resize(std::size_t n) {
    Change([n](std::vector<double>& v) { v.resize(n); });
  }
  void clear() {
    Change([](std::vector<double>& v) { v.clear(); });
  }
  void set(std::size_t i, double t) {
    Change([i, t](std::vector<double>& v) { v[i] = t; });
  }
  /// The times as a vector, moved out when no other copy shares them (else copied); this copy
  /// is left empty. How times lent to signals go back to their owner (CheckInputSanity).
  std::vector<double> Release() && {
    std::vector<double> out;
    if (uniform()) {
      out = view_.ToVector();
    } else if (times_) {
      out = times_.use_count() == 1 ? std::move(*times_) : *times_;
    }
    times_.reset();
    view_ = {};
    return out;
  }
  /// Any other change of the times in place, change(std::vector<double>&).
  template <class F>
  void Change(const F& change) {
    if (uniform()) {
      times_ = std::make_shared<std::vector<double>>(view_.ToVector());
    } else if (!times_) {
      times_ = std::make_shared<std::vector<double>>();
    } else if (times_.use_count() > 1) {
      times_ = std::make_shared<std::vector<double>>(*times_);
    }
    change(*times_);
    view_ = *times_;
  }

 private:
  std::shared_ptr<std::vector<double>> times_;
  model::TimesView view_;  // of *times_, or of a uniform clock
};

}  // namespace uuvplan::ident
