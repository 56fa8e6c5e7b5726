#include "roomsense/error.h"
#include "roomsense/scanio.h"
#include "ply_header_check.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>
#include <limits>

namespace roomsense::scanio {
namespace {

void append_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, Scan& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::size_t base = out.vertices.size();
    if (base + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max())
      throw Error(ErrorCode::Io, "the scan has more vertices than 32-bit indices can address");
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      for (unsigned k = 0; k < 3; ++k) out.indices.push_back(static_cast<std::uint32_t>(base + face.mIndices[k]));
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) append_node(scene, *node.mChildren[c], transform, out);
}

}  // namespace

Scan load_mesh_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorCode::Io, "cannot read '" + path + "': no such file");
  check_ply_header(path);
  Assimp::Importer importer;
  // No normals, UVs or materials are needed: keep the import to positions and faces.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS | aiComponent_MATERIALS |
                                                          aiComponent_TANGENTS_AND_BITANGENTS);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw Error(ErrorCode::Io, "cannot read '" + path + "': " + importer.GetErrorString());
  Scan scan;
  append_node(*scene, *scene->mRootNode, aiMatrix4x4(), scan);
  if (scan.vertices.empty()) throw Error(ErrorCode::Io, "cannot read '" + path + "': it holds no vertices");
  return scan;
}

}  // namespace roomsense::scanio
