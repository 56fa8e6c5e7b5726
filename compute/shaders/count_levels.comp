#version 450
#extension GL_GOOGLE_include_directive : require
// Eq. 3.8: |V_y|, the active voxels of each level. Work item (y, chunk) sums bit y of kChunk consecutive
// columns and adds the partial sum atomically; integer addition commutes, so the order does not matter.
#include "common.glsl"

const uint kChunk = 64u;

void main() {
  const uint ny = uint(pc.ny);
  const uint chunks = (pc.column_count + kChunk - 1u) / kChunk;
  const uint items = ny * chunks;
  const uint item = item_index();
  if (item >= items) return;
  const uint y = item % ny;  // neighbouring invocations read neighbouring bits
  const uint chunk = item / ny;
  const uint end = min(pc.column_count, (chunk + 1u) * kChunk);
  uint sum = 0u;
  for (uint col = chunk * kChunk; col < end; ++col) {
    const uint index = col * ny + y;
    sum += (bits[index >> 5] >> (index & 31u)) & 1u;
  }
  if (sum != 0u) atomicAdd(out_words[pc.levels_offset + y], sum);
}
