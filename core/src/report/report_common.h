// Shared by the report's writers.
#pragma once
#include "roomsense/areas.h"

namespace roomsense::report_detail {

// Areas whose type, size or reach is outside its enum (an app can build any Area) are left out of the
// pictures: their names and colours are undefined.
inline bool drawable(const Area& a) {
  const int t = int(a.type), s = int(a.size), r = int(a.reach);
  return t >= 1 && t <= 4 && s >= 1 && s <= 3 && r >= 1 && r <= 3;
}

}  // namespace roomsense::report_detail
