// Errors of the room pipeline. Bad input throws roomsense::Error with a code and one clear line.
#pragma once
#include <stdexcept>
#include <string>

namespace roomsense {

enum class ErrorCode {
  // The thesis's StartRoomUnderstanding codes (§3.8): 1 = no input or size < 1, 2 = size not divisible by 3.
  EmptyInput = 1,
  SizeNotMultipleOfThree = 2,
  // Ours, beyond the thesis.
  BadIndices = 10,      // index out of range, or an index count that is not a multiple of 3
  NoValidVertices = 11, // every vertex was NaN/Inf or an outlier
  GridTooLarge = 12,    // extents need more voxels than the memory budget allows
  BadParameter = 13,    // voxel size or another option out of its range
  Io = 14,              // a file could not be read or written
  TooMuchWork = 15,     // voxelization needs more triangle-voxel tests than the work budget allows
  Cancelled = 16,       // the caller asked the analysis to stop
};

class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

}  // namespace roomsense
