#pragma once
// A number in a message as a reader expects it: 0.5, 1e-05, 8e+10 (not 0.500000), to `digits` significant digits.
#include <cstdio>
#include <string>

namespace peristep {

inline std::string numberText(double x, int digits = 6) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace peristep
