#version 450
#extension GL_GOOGLE_include_directive : require
// Eq. 3.9/3.10 with the surface-band rule: select_floor_ceiling of voxelize_cpu.cpp on one invocation, so
// the column pass that needs I_Floor/I_Ceiling stays in the same submission. H_Grid is small: a serial
// scan costs microseconds (H_Grid <= kMaxLevels keeps it inside lavapipe's loop budget).
#include "common.glsl"

uint level(int y) { return out_words[pc.levels_offset + uint(y)]; }

// kSurfaceBandDivisor * counts[y] >= counts[peak] with kSurfaceBandDivisor = 4, without overflow: 4c >= p
// is c >= ceil(p / 4). A level outside the grid counts 0 (the CPU never reads one when min_separation >= 1).
bool in_band(int y, int peak) {
  if (y < 0 || y >= pc.ny) return false;
  const uint p = level(peak);
  return level(y) >= (p >> 2) + ((p & 3u) != 0u ? 1u : 0u);
}

void main() {
  if (item_index() != 0u) return;
  const uint base = pc.select_offset;
  int first = -1;
  for (int y = 0; y < pc.ny; ++y)
    if (level(y) > 0u && (first < 0 || level(y) > level(first))) first = y;  // ties go to the lower level
  const int min_separation = max(1, pc.min_separation);  // as the CPU: a floor is never its own ceiling
  int second = -1;
  if (first >= 0)
    for (int y = 0; y < pc.ny; ++y)
      if (level(y) > 0u && abs(y - first) >= min_separation && (second < 0 || level(y) > level(second))) second = y;
  if (second < 0) {
    out_words[base] = 0u;
    return;
  }
  const int floor_peak = min(first, second);
  const int ceiling_peak = max(first, second);
  int floor_level = floor_peak;
  int ceiling_level = ceiling_peak;
  if (floor_level + 1 < ceiling_level && in_band(floor_level + 1, floor_peak)) ++floor_level;
  if (ceiling_level - 1 > floor_level && in_band(ceiling_level - 1, ceiling_peak)) --ceiling_level;
  out_words[base] = 1u;
  out_words[base + 1u] = uint(floor_level);
  out_words[base + 2u] = uint(ceiling_level);
  out_words[base + 3u] = uint(floor_peak);
  out_words[base + 4u] = uint(ceiling_peak);
}
