#version 450
#extension GL_GOOGLE_include_directive : require
// Bit-packed V to the byte grid the caller gets (one byte 0/1 per voxel, GridSpec::index order): each
// invocation writes one word, that is four voxels. Bytes are little-endian within a word on every host
// Vulkan runs on that we support.
#include "common.glsl"

void main() {
  const uint words = (pc.voxel_count + 3u) / 4u;
  const uint w = item_index();
  if (w >= words) return;
  const uint first = 4u * w;
  const uint nibble = (bits[first >> 5] >> (first & 31u)) & 0xFu;  // 4 | 32: never straddles a word
  out_words[pc.grid_offset + w] = (nibble & 1u) | ((nibble & 2u) << 7) | ((nibble & 4u) << 14) | ((nibble & 8u) << 21);
}
