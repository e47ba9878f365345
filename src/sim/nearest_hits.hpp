#pragma once
// The nearest point of each other element to one query vertex (thesis 4.5 and 5.5.1): one
// hit per element (or per periodic clone of one), at most Capacity of them, in a fixed array
// on the stack so the force pass allocates nothing. Both simulators sum their repulsion over
// such a list and test overlaps against it.
//
// Hit supplies `key()`, what it is a hit of (compared with ==), and `nearerThan(other)`, a
// strict order. Offers keep, per key, the nearest hit offered. When the list is full, a hit
// of a new key replaces the farthest hit if it is nearer, so a crowded vertex keeps its
// nearest neighbours rather than whichever came first.
#include <array>
#include <cassert>
#include <utility>

namespace pak {

template <class Hit, int Capacity>
class NearestHitList {
 public:
  static_assert(Capacity > 0);
  using Key = decltype(std::declval<const Hit&>().key());

  // Index of the hit of `key`, or -1.
  int find(const Key& key) const {
    for (int k = 0; k < count_; ++k)
      if (hits_[k].key() == key) return k;
    return -1;
  }

  void offer(const Hit& hit) {
    if (const int k = find(hit.key()); k >= 0) {
      if (hit.nearerThan(hits_[k])) hits_[k] = hit;
      return;
    }
    if (count_ < Capacity) {
      hits_[count_++] = hit;
      return;
    }
    int farthest = 0;  // the first of equally far ones
    for (int k = 1; k < count_; ++k)
      if (hits_[farthest].nearerThan(hits_[k])) farthest = k;
    if (hit.nearerThan(hits_[farthest])) hits_[farthest] = hit;
  }

  int size() const { return count_; }
  bool full() const { return count_ == Capacity; }
  const Hit& operator[](int k) const {
    assert(k >= 0 && k < count_);
    return hits_[k];
  }
  const Hit* begin() const { return hits_.data(); }
  const Hit* end() const { return hits_.data() + count_; }

 private:
  std::array<Hit, Capacity> hits_;
  int count_ = 0;
};

}  // namespace pak
