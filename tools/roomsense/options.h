// Command-line options of `roomsense analyze`.
#pragma once
#include "roomsense/bounds.h"
#include "roomsense/scan.h"

#include <optional>
#include <string>
#include <vector>

namespace roomsense::cli {

struct AnalyzeOptions {
  std::string scan;  // a file, or synthetic:NAME
  std::optional<std::string> json_path;
  std::optional<std::string> bounds_path;
  std::optional<std::string> room_bounds_dir;
  std::optional<std::string> report_dir;  // plan.svg and scene.glb go there
  SourceFrame frame;
  float voxel_size = 0.10f;
  float min_plateau = BoundsParams{}.min_plateau_area;
  std::string backend;  // empty: ROOMSENSE_BACKEND, else auto
  std::optional<std::string> mode;  // "vertices" | "triangles"
  unsigned threads = 0;
  bool use_labels = true;  // a capture's or MRUK room's semantic labels (Scan::labels)
  bool grow_areas = true;  // AreaParams::grow
};

// Throws std::invalid_argument with a one-line message for the user.
AnalyzeOptions parse_analyze_options(const std::vector<std::string>& args);

extern const char* const kUsage;

}  // namespace roomsense::cli
