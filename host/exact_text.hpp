#pragma once
// A double as text that reads back to the same bits (17 significant digits): for CSV, XDMF and gnuplot
// data, where a value must survive the round trip.
#include <cstdio>
#include <string>

namespace peristep::host {

inline std::string exactText(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

}  // namespace peristep::host
