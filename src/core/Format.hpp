#pragma once
// Numbers in messages: the shortest text that reads back as the same double (1e-07, not
// 0.000000 or -9.9999999999999995e-08).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <sstream>
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

// Durations in progress lines: "12.3 s", "4 min 7 s", "2 h 13 min".
inline std::string formatSeconds(double s) {
  std::ostringstream out;
  if (s < 60) {
    out << std::fixed << std::setprecision(1) << s << " s";
  } else if (s < 3600) {
    out << static_cast<int>(s / 60) << " min " << static_cast<int>(std::fmod(s, 60)) << " s";
  } else if (s < 1e6 * 3600) {
    out << static_cast<long long>(s / 3600) << " h " << static_cast<int>(std::fmod(s, 3600) / 60)
        << " min";
  } else {
    out << "more than a million hours";  // also inf/NaN: no cast of a value an int cannot hold
  }
  return out.str();
}

// The progress line of a long run: "  step 120/5000  t = 0.0012  elapsed 5.0 s  remaining ~3 min".
inline std::string progressLine(long long step, long long lastStep, double time, double elapsed,
                                double remaining) {
  std::ostringstream out;
  out << "  step " << step << "/" << lastStep << "  t = " << time << "  elapsed "
      << formatSeconds(elapsed) << "  remaining ~" << formatSeconds(remaining);
  return out.str();
}

}  // namespace peridot
