// Shared by the report's writers.
#pragma once
#include "roomsense/areas.h"

namespace roomsense::report_detail {

// Areas and placements whose type, size or reach is outside its enum (an app can build any Area or Placement)
// are left out of the pictures: their names and colours are undefined.
inline bool drawable_type(AreaType type) { return int(type) >= 1 && int(type) <= 4; }
inline bool drawable_reach(Reach reach) { return int(reach) >= 1 && int(reach) <= 3; }
inline bool drawable(const Area& a) {
  return drawable_type(a.type) && int(a.size) >= 1 && int(a.size) <= 3 && drawable_reach(a.reach);
}

}  // namespace roomsense::report_detail
