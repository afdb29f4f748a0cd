// Sample times as the simulator and the estimators read them: a sorted array of doubles, or a
// uniform decimal clock held as its parameters (8 bytes a sample of a long log).
// An array is not owned (its owner outlives the view); a clock is held by value.
//
// A uniform clock: t_k = (n0 + k·step)/scale − offset, with n0, step and scale = 10^d integers
// exact in a double, so that (n0 + k·step)/scale is one correctly rounded division — the nearest
// double to the decimal text, what a CSV parser reads — and the offset subtracted as the log's
// reader subtracts it: the very doubles of the logged times, computed instead of stored.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

namespace uuvplan::model {

struct UniformClock {
  double n0 = 0, step = 0, scale = 1, offset = 0;
  double operator()(std::size_t k) const {
    return (n0 + static_cast<double>(k) * step) / scale - offset;
  }
  bool operator==(const UniformClock& o) const {
    return n0 == o.n0 && step == o.step && scale == o.scale && offset == o.offset;
  }
};

class TimesView {
 public:
  class const_iterator;

  TimesView() = default;
  TimesView(const std::vector<double>& t) : data_(t.data()), size_(t.size()) {}  // NOLINT: a view
  TimesView(const double* data, std::size_t size) : data_(data), size_(size) {}
  TimesView(const UniformClock& clock, std::size_t size) : clock_(clock), size_(size) {}

  double operator[](std::size_t i) const { return data_ ? data_[i] : clock_(i); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  double front() const { return (*this)[0]; }
  double back() const { return (*this)[size_ - 1]; }
  const_iterator begin() const;
  const_iterator end() const;
  /// The clock the times are computed from, or null when they are an array.
  const UniformClock* clock() const { return data_ ? nullptr : &clock_; }
  /// Times [begin, end) of these (the same doubles: a clock's n0 moves by begin·step, integers
  /// exact in a double).
  TimesView Slice(std::size_t begin, std::size_t end) const {
    if (data_) return {data_ + begin, end - begin};
    UniformClock c = clock_;
    c.n0 += static_cast<double>(begin) * c.step;
    return {c, end - begin};
  }
  std::vector<double> ToVector() const {
    std::vector<double> v(size_);
    for (std::size_t i = 0; i < size_; ++i) v[i] = (*this)[i];
    return v;
  }

 private:
  const double* data_ = nullptr;
  UniformClock clock_;
  std::size_t size_ = 0;
};

/// Random access by index (a time on a clock is computed, so `reference` is a value).
class TimesView::const_iterator {
 public:
  using iterator_category = std::random_access_iterator_tag;
  using value_type = double;
  using difference_type = std::ptrdiff_t;
  using pointer = const double*;
  using reference = double;

  const_iterator() = default;
  const_iterator(const TimesView& v, std::size_t i) : v_(v), i_(static_cast<difference_type>(i)) {}
  double operator*() const { return v_[static_cast<std::size_t>(i_)]; }
  double operator[](difference_type n) const { return v_[static_cast<std::size_t>(i_ + n)]; }
  const_iterator& operator++() { return *this += 1; }
  const_iterator& operator--() { return *this -= 1; }
  const_iterator operator++(int) {
    const_iterator old = *this;
    ++*this;
    return old;
  }
  const_iterator operator--(int) {
    const_iterator old = *this;
    --*this;
    return old;
  }
  const_iterator& operator+=(difference_type n) {
    i_ += n;
    return *this;
  }
  const_iterator& operator-=(difference_type n) {
    i_ -= n;
    return *this;
  }
  friend const_iterator operator+(const_iterator a, difference_type n) { return a += n; }
  friend const_iterator operator+(difference_type n, const_iterator a) { return a += n; }
  friend const_iterator operator-(const_iterator a, difference_type n) { return a -= n; }
  friend difference_type operator-(const const_iterator& a, const const_iterator& b) {
    return a.i_ - b.i_;
  }
  friend bool operator==(const const_iterator& a, const const_iterator& b) { return a.i_ == b.i_; }
  friend bool operator!=(const const_iterator& a, const const_iterator& b) { return a.i_ != b.i_; }
  friend bool operator<(const const_iterator& a, const const_iterator& b) { return a.i_ < b.i_; }
  friend bool operator>(const const_iterator& a, const const_iterator& b) { return a.i_ > b.i_; }
  friend bool operator<=(const const_iterator& a, const const_iterator& b) { return a.i_ <= b.i_; }
  friend bool operator>=(const const_iterator& a, const const_iterator& b) { return a.i_ >= b.i_; }

 private:
  TimesView v_;
  difference_type i_ = 0;
};

inline TimesView::const_iterator TimesView::begin() const { return {*this, 0}; }
inline TimesView::const_iterator TimesView::end() const { return {*this, size_}; }

}  // namespace uuvplan::model
