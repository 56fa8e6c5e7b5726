// A room scan as the pipeline takes it: world-space vertices and, optionally, triangle indices.
#pragma once
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace roomsense {

struct Scan {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;  // triangles, 3 per face; empty for a point cloud (thesis input)
};

// Thesis Eq. 3.1: a flattened array x1,y1,z1,x2,... of `size` floats. Throws Error with the thesis's codes:
// EmptyInput (null data or size < 1) and SizeNotMultipleOfThree.
Scan scan_from_flat_array(const float* data, long long size);

enum class UpAxis { Y, Z };
enum class Units { Metres, Centimetres, Millimetres };

// Where the scan comes from. Our frame is right-handed, +Y up, metres (OpenXR STAGE/LOCAL).
struct SourceFrame {
  UpAxis up = UpAxis::Y;
  Units units = Units::Metres;
  bool left_handed = false;  // Unity (with up Y) or Unreal (with up Z)
};

// Converts positions in place to our frame (thesis Eq. 3.2 generalised; see scan.cpp for each mapping).
void convert_to_roomsense_frame(Scan& scan, const SourceFrame& frame);

}  // namespace roomsense
