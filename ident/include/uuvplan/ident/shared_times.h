// Sample times that several signals share: a velocity estimate's times are its positions'
// (8 bytes a sample of a long log, issue #16). A read-only std::vector<double> held by
// reference count; copies share it, and a change detaches the changed copy first (copy on
// write), so a SharedTimes behaves as a value. Reads go through the vector's own data pointer,
// cached, so that a loop over t[i] costs what it costs on a std::vector.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

namespace uuvplan::ident {

class SharedTimes {
 public:
  using value_type = double;
  using const_iterator = std::vector<double>::const_iterator;

  SharedTimes() = default;
  SharedTimes(const SharedTimes&) = default;
  SharedTimes& operator=(const SharedTimes&) = default;
  SharedTimes(SharedTimes&& o) noexcept { *this = std::move(o); }
  SharedTimes& operator=(SharedTimes&& o) noexcept {
    times_ = std::move(o.times_);
    Cache();
    o.Cache();
    return *this;
  }
  SharedTimes(std::vector<double> t) { *this = std::move(t); }  // NOLINT: a vector is times
  SharedTimes(std::initializer_list<double> t) : SharedTimes(std::vector<double>(t)) {}
  SharedTimes& operator=(std::vector<double> t) {
    times_ = std::make_shared<std::vector<double>>(std::move(t));
    Cache();
    return *this;
  }

  operator const std::vector<double>&() const { return vector(); }  // NOLINT: read as a vector
  const std::vector<double>& vector() const { return times_ ? *times_ : Empty(); }
  /// True when `other` holds the very same times (not a copy of them).
  bool SharesWith(const SharedTimes& other) const { return times_ && times_ == other.times_; }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  double operator[](std::size_t i) const { return data_[i]; }
  const double* data() const { return data_; }
  double front() const { return data_[0]; }
  double back() const { return data_[size_ - 1]; }
  const_iterator begin() const { return vector().begin(); }
  const_iterator end() const { return vector().end(); }

  // Changes (each detaches this copy from the others first).
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
    if (times_) out = times_.use_count() == 1 ? std::move(*times_) : *times_;
    times_.reset();
    Cache();
    return out;
  }
  /// Any other change of the times in place, change(std::vector<double>&).
  template <class F>
  void Change(const F& change) {
    if (!times_) {
      times_ = std::make_shared<std::vector<double>>();
    } else if (times_.use_count() > 1) {
      times_ = std::make_shared<std::vector<double>>(*times_);
    }
    change(*times_);
    Cache();
  }

 private:
  static const std::vector<double>& Empty() {
    static const std::vector<double> empty;
    return empty;
  }
  void Cache() {
    data_ = times_ ? times_->data() : nullptr;
    size_ = times_ ? times_->size() : 0;
  }

  std::shared_ptr<std::vector<double>> times_;
  const double* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace uuvplan::ident
