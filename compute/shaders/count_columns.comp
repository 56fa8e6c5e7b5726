#version 450
#extension GL_GOOGLE_include_directive : require
// Eq. 3.11/3.12: |V_xz|, the active voxels of a column in y in [I_Floor, I_Ceiling], and the any-voxel mask
// behind B_Room. One invocation per four columns, so the packed mask word needs no atomics. The column's
// bits are contiguous (columns are contiguous in y), so each word is counted with bitCount.
#include "common.glsl"

uint count_bits(uint begin, uint end) {  // active voxels with index in [begin, end)
  uint n = 0u;
  uint i = begin;
  while (i < end) {
    const uint word = i >> 5;
    const uint lo = i & 31u;
    const uint hi = min(32u, lo + (end - i));                 // bits [lo, hi) of this word
    const uint mask = (hi == 32u ? 0xFFFFFFFFu : ((1u << hi) - 1u)) & ~((1u << lo) - 1u);
    n += uint(bitCount(bits[word] & mask));
    i += hi - lo;
  }
  return n;
}

void main() {
  const uint groups = (pc.column_count + 3u) / 4u;
  const bool found = out_words[pc.select_offset] != 0u;
  const int floor_level = int(out_words[pc.select_offset + 1u]);
  const int ceiling_level = int(out_words[pc.select_offset + 2u]);
  const uint g = item_index();
  if (g >= groups) return;
  uint any_word = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    const uint col = 4u * g + k;
    if (col >= pc.column_count) break;
    uint n = 0u;
    if (found && floor_level <= ceiling_level) {
      const uint base = col * uint(pc.ny);
      n = count_bits(base + uint(floor_level), base + uint(ceiling_level) + 1u);
    }
    out_words[pc.columns_offset + col] = n;
    if (n > 0u) any_word |= 1u << (8u * k);
  }
  out_words[pc.any_offset + g] = any_word;
}
