// glTF/GLB through assimp. Its PLY and OBJ importers crashed on bad indices and needed several times the
// memory of the mesh, so they are no longer used; glTF keeps assimp for its scene graph, accessors and
// buffers, which a lean reader of our own would have to redo.
#include "read_gltf.h"

#include "scan_file.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstdint>
#include <limits>

namespace roomsense::scanio {
namespace {

void append_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, Scan& out,
                 const std::string& path) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    if (node.mMeshes[m] >= scene.mNumMeshes) throw_read_error(path, "a node refers to a mesh it does not have");
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::size_t base = out.vertices.size();
    if (base + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max())
      throw_read_error(path, "it has more vertices than 32-bit indices can address");
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      for (unsigned k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices)
          throw_read_error(path, "a face refers to vertex " + std::to_string(face.mIndices[k]) + " of a mesh with " +
                                     std::to_string(mesh.mNumVertices) + " vertices");
        out.indices.push_back(static_cast<std::uint32_t>(base + face.mIndices[k]));
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) append_node(scene, *node.mChildren[c], transform, out, path);
}

}  // namespace

Scan read_gltf_file(const std::string& path) {
  Assimp::Importer importer;
  // No normals, UVs or materials are needed: keep the import to positions and faces.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS | aiComponent_MATERIALS |
                                                          aiComponent_TANGENTS_AND_BITANGENTS);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    const std::string why = importer.GetErrorString();
    throw_read_error(path, why.empty() ? "it is not a glTF file assimp can read" : why.substr(0, why.find('\n')));
  }
  Scan scan;
  append_node(*scene, *scene->mRootNode, aiMatrix4x4(), scan, path);
  if (scan.vertices.empty()) throw_read_error(path, "it holds no vertices");
  return scan;
}

}  // namespace roomsense::scanio
