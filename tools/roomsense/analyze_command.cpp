#include "analyze_command.h"

#include "options.h"
#include "roomsense/analysis.h"
#include "roomsense/error.h"
#include "roomsense/export.h"
#include "roomsense/report.h"
#include "roomsense/scanio.h"
#include "roomsense/mruk_room.h"
#include "roomsense/quest_capture.h"
#include "roomsense/synthetic.h"
#include "summary.h"
#if ROOMSENSE_HAVE_COMPUTE
#include "roomsense/voxel_stage_choice.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace roomsense::cli {
namespace {

// A scene capture (.json: a Quest capture or an MRUK room) comes with its labels unless `use_labels` is off.
Scan load_scan(const std::string& source, bool use_labels) {
  if (synth::is_builtin_source(source)) return synth::generate_builtin_source(source);
  if (scanio::is_quest_capture_path(source)) {
    const scanio::QuestCapture capture = scanio::load_scene_capture(source);
    Scan scan = capture.mesh;
    if (use_labels) scan.labels = scanio::scene_labels(capture);
    return scan;
  }
  return scanio::load_mesh_file(source);
}

std::string resolve_backend(const std::string& flag) {
  if (!flag.empty()) return flag;
  const char* env = std::getenv("ROOMSENSE_BACKEND");
  if (env == nullptr || *env == '\0') return "auto";
  const std::string v = env;
  if (v != "auto" && v != "cpu" && v != "vulkan")
    throw std::invalid_argument("ROOMSENSE_BACKEND takes auto, cpu or vulkan, not '" + v + "'");
  return v;
}


void write_text(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  if (!file || !(file << text << '\n')) throw Error(ErrorCode::Io, "cannot write '" + path + "'");
}

}  // namespace

std::string report_title(const std::string& source) {
  if (synth::is_builtin_source(source)) return source;
  const std::string name = std::filesystem::path(source).filename().string();
  return name.empty() ? source : name;
}

LoadedAnalysis load_and_analyze(const AnalyzeOptions& options, const char*& step) {
  const std::string backend = resolve_backend(options.backend);
  LoadedAnalysis out;
  step = "reading";
  const auto start = std::chrono::steady_clock::now();
  out.scan = load_scan(options.scan, options.use_labels);
  Scan& scan = out.scan;
  step = "analysing";
  convert_to_roomsense_frame(scan, options.frame);
  out.load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  AnalysisOptions analysis;
  analysis.voxel_size = options.voxel_size;
  analysis.bounds.min_plateau_area = options.min_plateau;
  analysis.threads = options.threads;
  analysis.areas.grow = options.grow_areas;
  if (options.mode) analysis.mode = *options.mode == "vertices" ? VoxelMode::Vertices : VoxelMode::Triangles;
  std::unique_ptr<VoxelStage> stage;
#if ROOMSENSE_HAVE_COMPUTE
  std::string note;
  VoxelWorkload workload = estimate_voxel_workload(scan, options.voxel_size);
  if (analysis.mode == VoxelMode::Vertices) workload.triangles = 0;
  stage = make_voxel_stage(parse_backend(backend), workload, &note);
  // Say why only when Vulkan was asked for and not given; auto's choice is in the JSON's grid.backend.
  if (backend == "vulkan" && stage->name() != "vulkan") std::fprintf(stderr, "roomsense analyze: %s\n", note.c_str());
#else
  if (backend == "vulkan")
    throw Error(ErrorCode::BadParameter, "this build has no Vulkan backend (use --backend cpu)");
#endif
  analysis.voxel_stage = stage.get();
  out.result = analyze(scan, analysis);
  return out;
}

int analyze_command(const std::vector<std::string>& args) {
  AnalyzeOptions options;
  try {
    options = parse_analyze_options(args);
    resolve_backend(options.backend);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "roomsense analyze: %s (see roomsense analyze --help)\n", e.what());
    return 2;
  }
  const char* step = "reading";  // for the out-of-memory line
  try {
    const LoadedAnalysis loaded = load_and_analyze(options, step);
    const Scan& scan = loaded.scan;
    const AnalysisResult& result = loaded.result;
    const double load_ms = loaded.load_ms;
    step = "writing the results of";

    if (options.bounds_path) {
      if (!result.ok()) throw Error(ErrorCode::BadParameter, "no bounds to write: " + result.status_message);
      write_bounds(result.bounds, *options.bounds_path);
    }
    if (options.room_bounds_dir) {
      if (!result.ok()) throw Error(ErrorCode::BadParameter, "no bounds to write: " + result.status_message);
      std::error_code ec;
      std::filesystem::create_directories(*options.room_bounds_dir, ec);
      if (ec) throw Error(ErrorCode::Io, "cannot create " + *options.room_bounds_dir + ": " + ec.message());
      for (std::size_t k = 0; k < result.room_bounds.size(); ++k)
        write_bounds(result.room_bounds[k],
                     (std::filesystem::path(*options.room_bounds_dir) / ("room_" + std::to_string(k) + ".obj")).string());
    }
    if (options.report_dir) {
      if (!result.ok()) throw Error(ErrorCode::BadParameter, "no report to write: " + result.status_message);
      write_report(report_input(result, scan, report_title(options.scan)), *options.report_dir);
    }
    if (options.json_path) write_text(*options.json_path, analysis_json(result, {options.scan, load_ms}));
    else std::fputs(summary(result, options.scan, load_ms).c_str(), stdout);
    if (!result.ok()) {
      std::fprintf(stderr, "roomsense analyze: %s: %s\n", options.scan.c_str(), result.status_message.c_str());
      return 1;
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "roomsense analyze: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "roomsense analyze: out of memory %s '%s'\n", step, options.scan.c_str());
    return 1;
  } catch (const std::length_error&) {  // a container asked for more than it can hold: memory, too
    std::fprintf(stderr, "roomsense analyze: out of memory %s '%s'\n", step, options.scan.c_str());
    return 1;
  } catch (const std::exception& e) {  // e.g. std::system_error when no thread can be started
    std::fprintf(stderr, "roomsense analyze: %s '%s': %s\n", step, options.scan.c_str(), e.what());
    return 1;
  }
}

}  // namespace roomsense::cli
