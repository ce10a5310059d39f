// A set of the values of an enum whose enumerators run 0, 1, 2, ...: what a resolve reads
// (ResolveInputSet), what a run reads back (CaptureSet).
#pragma once

#include <cstdint>
#include <initializer_list>

namespace taa {

template <class E>
class EnumSet {
 public:
  constexpr EnumSet() = default;
  constexpr EnumSet(std::initializer_list<E> values) {
    for (E v : values) bits_ |= bit(v);
  }
  constexpr bool has(E v) const { return (bits_ & bit(v)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr EnumSet& operator|=(EnumSet o) {
    bits_ |= o.bits_;
    return *this;
  }
  friend constexpr EnumSet operator|(EnumSet a, EnumSet b) { return a |= b; }
  friend constexpr bool operator==(EnumSet, EnumSet) = default;

 private:
  static constexpr uint64_t bit(E v) { return uint64_t(1) << uint64_t(v); }
  uint64_t bits_ = 0;
};

}  // namespace taa
