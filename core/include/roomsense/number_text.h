// Numbers in messages for people (the CLI's summary, the pipeline's status lines): fixed decimals for
// everyday magnitudes, %g beyond them, so a scan at 1e30 m or an infinite value prints as "1e+30" or
// "inf", not as forty digits.
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace roomsense {

// `decimals` fixed decimals when |v| < 1e7, else 4 significant digits in %g form (also for inf and nan).
inline std::string fixed_or_g(double v, int decimals) {
  char text[32];
  if (std::isfinite(v) && std::fabs(v) < 1e7) std::snprintf(text, sizeof text, "%.*f", decimals, v);
  else std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

}  // namespace roomsense
