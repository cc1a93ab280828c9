#pragma once
// Numbers in messages: the shortest text that reads back as the same double (1e-07, not
// 0.000000 or -9.9999999999999995e-08).
#include <cstdio>
#include <cstdlib>
#include <string>

namespace peridot {

inline std::string formatNumber(double value) {
  char buffer[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

}  // namespace peridot
