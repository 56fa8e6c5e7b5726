// Writing results: the bounds mesh as OBJ or GLB, a multi-mesh GLB scene, and the CLI's analysis JSON
// (DESIGN.md, schema roomsense.analysis/1). Writers throw Error(Io) when a file cannot be written.
#pragma once
#include "roomsense/analysis.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace roomsense {

void write_obj(const BoundsMesh& mesh, const std::string& path);

// A glTF 2.0 binary scene of named meshes, each its own node, so viewers can toggle them.
class GlbScene {
 public:
  void add_mesh(std::string name, const std::vector<glm::vec3>& vertices, const std::vector<std::uint32_t>& indices,
                std::optional<std::array<float, 4>> rgba = std::nullopt);
  std::vector<std::uint8_t> encode() const;
  void write(const std::string& path) const;

 private:
  struct Mesh {
    std::string name;
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices;
    std::optional<std::array<float, 4>> rgba;
  };
  std::vector<Mesh> meshes_;
};

void write_glb(const BoundsMesh& mesh, const std::string& path);

// Writes OBJ or GLB by the path's extension (.obj, .glb); throws Error(BadParameter) for any other.
void write_bounds(const BoundsMesh& mesh, const std::string& path);

struct JsonSource {
  std::string file;
  double load_ms = 0.0;
};
// `members`: more top-level members, each a name and its value as JSON text (the layer's "openxr"), written in the
// one pass: parsing the document to add them and printing it again cost more than writing it (6.3 against 4 ms for
// thesis-room1). A value that is not JSON throws Error(BadParameter).
std::string analysis_json(const AnalysisResult& result, const JsonSource& source,
                          const std::vector<std::pair<std::string, std::string>>& members = {});

}  // namespace roomsense
