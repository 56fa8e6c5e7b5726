#include "options.h"

#include "roomsense/grid.h"

#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace roomsense::cli {

const char* const kUsage = R"(usage: roomsense analyze SCAN [options]

Finds the floor, ceiling, walls, furniture tops and free tiles of a room scan and builds a closed,
simplified room-bounds mesh (the voxel pipeline of the thesis, chapter 3).

SCAN                  an OBJ, PLY, glTF or GLB file, a Quest scene capture or a Meta MRUK
                      room (.json), or synthetic:NAME for a built-in room
                      (NAME: default, large-triangles, rotated, pentagon, hall, thesis-room1,
                      flat, loft, soffit, beam, house)
options:
  --json OUT.json     write the analysis (schema roomsense.analysis/1); without it, print a summary
  --bounds OUT.obj    write the room-bounds mesh (.obj or .glb)
  --room-bounds DIR   write each room's own bounds mesh (closed across its doorways) into DIR
                      (created if needed) as room_K.obj, K the room's index in the JSON's rooms
  --report DIR        write pictures into DIR (created if needed): plan.svg, a top view of
                      footprint, walls, furniture tops and areas coloured by reach; scene.glb,
                      the scan, the bounds and the areas as glTF nodes a viewer can toggle
  --up y|z            the scan's up axis (default y)
  --units m|cm|mm     the scan's length unit (default m)
  --left-handed       the scan is left-handed (Unity with --up y, Unreal with --up z)
  --voxel SIZE        voxel edge in metres (default 0.1, range 0.01 to 1)
  --no-labels         ignore a capture's or room's semantic labels (walls, windows, doors,
                      furniture) and analyse the bare mesh; by default they are used: no wall
                      areas over windows, doors or screens, furniture areas only on
                      furniture tops
  --exact-sizes       areas of exactly the thesis's class sizes (2, 1, 0.5 m); by default
                      they grow into the free surface around them and are at least that
  --min-plateau AREA  in the bounds, flatten furniture-top and ceiling plateaus smaller than
                      AREA m² to their neighbours' height: scan jitter and specks (default
                      0.04; 0 keeps the thesis's volume as it is)
  --mode vertices|triangles
                      voxelize vertices only (the thesis) or whole triangles (default when the
                      scan has triangles)
  --backend auto|cpu|vulkan
                      voxelization backend (default auto; also ROOMSENSE_BACKEND)
  --threads N         worker threads (default: one per core); results do not depend on it
  -h, --help          this text

Output coordinates are in the scan's frame after --up/--units/--left-handed conversion:
right-handed, +Y up, metres. Exit status: 0 on success, 1 on bad input, 2 on bad usage.
)";

// The help text states the voxel range in words: keep it in step with core's definition.
static_assert(kMinVoxelSize == 0.01f && kMaxVoxelSize == 1.0f, "update --voxel in kUsage");

namespace {

// A whole number in C syntax; an overflow reads as ±inf, for the caller's range check to refuse.
double parse_number(const std::string& flag, const std::string& value) {
  char* end = nullptr;
  const double v = value.empty() || std::isspace(static_cast<unsigned char>(value[0])) ? 0.0 : std::strtod(value.c_str(), &end);
  if (end != nullptr && end != value.c_str() && *end == '\0') return v;
  throw std::invalid_argument(flag + " needs a number, not '" + value + "'");
}

}  // namespace

AnalyzeOptions parse_analyze_options(const std::vector<std::string>& args) {
  AnalyzeOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "--json") o.json_path = value();
    else if (a == "--bounds") o.bounds_path = value();
    else if (a == "--room-bounds") o.room_bounds_dir = value();
    else if (a == "--report") o.report_dir = value();
    else if (a == "--up") {
      const std::string& v = value();
      if (v == "y") o.frame.up = UpAxis::Y;
      else if (v == "z") o.frame.up = UpAxis::Z;
      else throw std::invalid_argument("--up takes y or z, not '" + v + "'");
    } else if (a == "--units") {
      const std::string& v = value();
      if (v == "m") o.frame.units = Units::Metres;
      else if (v == "cm") o.frame.units = Units::Centimetres;
      else if (v == "mm") o.frame.units = Units::Millimetres;
      else throw std::invalid_argument("--units takes m, cm or mm, not '" + v + "'");
    } else if (a == "--left-handed") o.frame.left_handed = true;
    else if (a == "--no-labels") o.use_labels = false;
    else if (a == "--exact-sizes") o.grow_areas = false;
    else if (a == "--voxel") {
      // Checked here, with core's range (make_grid_spec would refuse it too, but only after the scan is read).
      const std::string& v = value();
      const double size = parse_number(a, v);
      if (!(size >= double(kMinVoxelSize) && size <= double(kMaxVoxelSize)))
        throw std::invalid_argument("--voxel takes a size from 0.01 to 1 m, not '" + v + "'");
      o.voxel_size = float(size);
    }
    else if (a == "--min-plateau") {
      const std::string& v = value();
      const double area = parse_number(a, v);
      if (!(area >= 0.0 && area <= 100.0))
        throw std::invalid_argument("--min-plateau takes an area from 0 to 100 m², not '" + v + "'");
      o.min_plateau = float(area);
    }
    else if (a == "--backend") {
      o.backend = value();
      if (o.backend != "auto" && o.backend != "cpu" && o.backend != "vulkan")
        throw std::invalid_argument("--backend takes auto, cpu or vulkan, not '" + o.backend + "'");
    } else if (a == "--mode") {
      o.mode = value();
      if (*o.mode != "vertices" && *o.mode != "triangles")
        throw std::invalid_argument("--mode takes vertices or triangles, not '" + *o.mode + "'");
    } else if (a == "--threads") {
      const std::string& v = value();
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), o.threads);
      if (ec != std::errc() || end != v.data() + v.size() || o.threads > 256)
        throw std::invalid_argument("--threads needs a count from 0 to 256, not '" + v + "'");
    } else if (!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option '" + a + "'");
    else if (o.scan.empty()) o.scan = a;
    else throw std::invalid_argument("one SCAN only; '" + a + "' is extra");
  }
  if (o.scan.empty()) throw std::invalid_argument("analyze needs a SCAN (a mesh file or synthetic:NAME)");
  return o;
}

}  // namespace roomsense::cli
