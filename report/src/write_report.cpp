// write_report: the report folder with plan.svg and scene.glb.
#include "roomsense/error.h"
#include "roomsense/report.h"

#include <filesystem>
#include <fstream>
#include <system_error>

namespace roomsense {

void write_report(const ReportInput& input, const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path folder(dir);
  std::error_code ec;
  if (dir.empty()) throw Error(ErrorCode::Io, "no report folder given");
  if (!fs::is_directory(folder, ec)) {
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder, ec))
      throw Error(ErrorCode::Io, "cannot create report folder '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  }
  const std::string svg_path = (folder / kPlanSvgName).string();
  {
    const std::string svg = plan_svg(input);
    std::ofstream file(svg_path, std::ios::binary);
    if (!file || !file.write(svg.data(), std::streamsize(svg.size())) || !file.flush())
      throw Error(ErrorCode::Io, "cannot write '" + svg_path + "'");
  }
  scene_glb(input).write((folder / kSceneGlbName).string());
}

}  // namespace roomsense
