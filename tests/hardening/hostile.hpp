// What the hardening tests pass and check at the C ABI (SPEC §9b.2):
// the doubles a hostile host passes, and outputs poisoned before a call so
// that a test can tell they were left untouched on error.
#pragma once

#include <cstddef>
#include <cstring>
#include <limits>

namespace hostile {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// NaN, +-Inf and two numbers beyond the input range |x| <= 1e100: each is
// CYC_E_NOT_FINITE, naming the argument or field.
constexpr double kBadDoubles[] = {kNaN, kInf, -kInf, 1e308, -1e101};

constexpr unsigned char kPoison = 0xA5;

template <class T>
void poison(T& x) {
  std::memset(static_cast<void*>(&x), kPoison, sizeof x);
}

template <class T>
bool poisoned(const T& x) {
  const unsigned char* p = reinterpret_cast<const unsigned char*>(&x);
  for (std::size_t i = 0; i < sizeof x; ++i)
    if (p[i] != kPoison) return false;
  return true;
}

}  // namespace hostile
