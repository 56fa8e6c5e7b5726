// The standard spatial-entity API through the layer when the runtime has plane tracking of its own
// (ROOMSENSE_SIM_EXTENSIONS=XR_EXT_spatial_entity,XR_EXT_spatial_plane_tracking): an application that enables only
// XR_EXT_future, XR_EXT_spatial_entity and XR_EXT_spatial_plane_tracking sees exactly the runtime's planes (same
// ids, labels, alignments, poses, extents and polygons as with DISABLE_XR_APILAYER_ROOMSENSE=1), and every step
// of the API answers as the runtime does.
#include "spatial_client.h"  // first: the registry's declarations before the layer's header

#include "rooms.h"
#include "test_process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace {

using namespace layertest;

const std::string kPlanesOnly = "XR_EXT_spatial_entity,XR_EXT_spatial_plane_tracking";

// What an app saw: the plane-tracking components, the capabilities and the planes.
struct Seen {
  std::vector<XrSpatialCapabilityEXT> capabilities;
  std::vector<SpatialComponent> components;
  std::vector<Plane> planes;
};

Seen read_scene(bool with_layer) {
  std::optional<ScopedEnv> disable;
  if (!with_layer) disable.emplace("DISABLE_XR_APILAYER_ROOMSENSE", std::string("1"));
  SpatialClient app;
  EXPECT_EQ(layer_library_loaded(), with_layer);
  Seen seen;
  seen.capabilities = app.capabilities();
  seen.components = app.component_types(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT);
  seen.planes = app.read_planes();
  return seen;
}

bool same_pose(const XrPosef& a, const XrPosef& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;  // passed through: bit for bit
}

// The app with the layer sees what it sees without it: the same planes, in the same order, bit for bit.
void expect_runtime_planes(const std::string& scene) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv room("ROOMSENSE_SIM_SCENE", scene);
  const Seen want = read_scene(false);  // first: the layer's library is not yet in the process
  const Seen got = read_scene(true);
  ASSERT_FALSE(want.planes.empty()) << scene;

  // The runtime's capability is there; the layer may add its own, never take one away.
  for (XrSpatialCapabilityEXT c : want.capabilities)
    EXPECT_NE(std::find(got.capabilities.begin(), got.capabilities.end(), c), got.capabilities.end()) << "capability " << c;
  EXPECT_EQ(got.components, want.components);

  ASSERT_EQ(got.planes.size(), want.planes.size()) << scene;
  for (std::size_t i = 0; i < want.planes.size(); ++i) {
    const Plane& w = want.planes[i];
    const Plane& g = got.planes[i];
    SCOPED_TRACE("plane " + std::to_string(i) + ", id " + std::to_string(w.id));
    EXPECT_EQ(g.id, w.id);
    EXPECT_EQ(g.label, w.label);
    EXPECT_EQ(g.alignment, w.alignment);
    EXPECT_TRUE(same_pose(g.pose, w.pose));
    EXPECT_EQ(g.extents.width, w.extents.width);
    EXPECT_EQ(g.extents.height, w.extents.height);
    ASSERT_EQ(g.polygon.size(), w.polygon.size());
    for (std::size_t k = 0; k < w.polygon.size(); ++k) {
      EXPECT_EQ(g.polygon[k].x, w.polygon[k].x);
      EXPECT_EQ(g.polygon[k].y, w.polygon[k].y);
    }
  }
}

TEST(SpatialPassthrough, DefaultRoomPlanesAreTheRuntimes) { expect_runtime_planes("synthetic:default"); }

TEST(SpatialPassthrough, QuestCapturePlanesAreTheRuntimes) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/living_room.json");
  expect_runtime_planes(path.string());
}

// The default room's planes are the room's: one floor facing up, one ceiling facing down, walls.
TEST(SpatialPassthrough, DefaultRoomPlanesHaveTheirLabels) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  SpatialClient app;
  ASSERT_TRUE(app.lists(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT));
  int floors = 0, ceilings = 0, walls = 0;
  for (const Plane& p : app.read_planes()) {
    floors += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT;
    ceilings += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT;
    walls += p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT;
    if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT) {
      EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_UPWARD_EXT);
    } else if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT) {
      EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_HORIZONTAL_DOWNWARD_EXT);
    } else if (p.label == XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT) {
      EXPECT_EQ(p.alignment, XR_SPATIAL_PLANE_ALIGNMENT_VERTICAL_EXT);
    }
    EXPECT_GE(p.polygon.size(), 3u);
    EXPECT_GT(p.extents.width, 0.0f);
    EXPECT_GT(p.extents.height, 0.0f);
  }
  EXPECT_EQ(floors, 1);
  EXPECT_EQ(ceilings, 1);
  EXPECT_GE(walls, 4);
}

// Update snapshots of entities made from the discovered ids, 2D meshes, the discovery event, a cancelled future
// and a future completed while still pending answer with the layer as without it.
struct Steps {
  XrResult cancelled_complete = XR_RESULT_MAX_ENUM;  // completing a context whose future was cancelled
  XrResult pending_complete = XR_RESULT_MAX_ENUM;     // completing a discovery right after starting it (may be ready)
  bool recommended = false;                           // XrEventDataSpatialDiscoveryRecommendedEXT for the context
  std::vector<XrSpatialEntityIdEXT> update_ids;
  std::vector<XrSpatialBounded2DDataEXT> update_bounds;
  std::vector<std::size_t> mesh_triangles;
  std::vector<std::size_t> mesh_vertices;
};

bool operator==(const Steps& a, const Steps& b) {
  return a.cancelled_complete == b.cancelled_complete && a.pending_complete == b.pending_complete &&
         a.recommended == b.recommended && a.update_ids == b.update_ids && a.mesh_triangles == b.mesh_triangles &&
         a.mesh_vertices == b.mesh_vertices && a.update_bounds.size() == b.update_bounds.size() &&
         std::memcmp(a.update_bounds.data(), b.update_bounds.data(), a.update_bounds.size() * sizeof(XrSpatialBounded2DDataEXT)) == 0;
}

std::ostream& operator<<(std::ostream& out, const Steps& s) {
  return out << "cancelled complete " << s.cancelled_complete << ", pending complete " << s.pending_complete
             << ", recommended " << s.recommended << ", " << s.update_ids.size() << " updated, " << s.mesh_triangles.size()
             << " meshes";
}

Steps run_steps(bool with_layer) {
  std::optional<ScopedEnv> disable;
  if (!with_layer) disable.emplace("DISABLE_XR_APILAYER_ROOMSENSE", std::string("1"));
  SpatialClient app;
  Steps s;

  // A future cancelled before completion is gone.
  ContextSteps cancelled = app.start_context(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, kPlaneComponents);
  EXPECT_EQ(cancelled.start, XR_SUCCESS);
  EXPECT_EQ(app.cancel(cancelled.future), XR_SUCCESS);
  app.complete_context(cancelled);
  s.cancelled_complete = cancelled.complete;

  const ContextSteps steps = app.create_context(XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT, kPlaneComponents);
  EXPECT_TRUE(steps.ok()) << steps.failure();
  if (!steps.ok()) return s;
  const XrSpatialContextEXT context = steps.context;

  // The runtime's recommendation reaches the app (the layer's own requests would not).
  for (int i = 0; i < 100 && !s.recommended; ++i) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER, nullptr};
    while (xrPollEvent(app.instance, &event) == XR_SUCCESS) {
      if (event.type == XR_TYPE_EVENT_DATA_SPATIAL_DISCOVERY_RECOMMENDED_EXT &&
          reinterpret_cast<const XrEventDataSpatialDiscoveryRecommendedEXT&>(event).spatialContext == context)
        s.recommended = true;
      event = {XR_TYPE_EVENT_DATA_BUFFER, nullptr};
    }
    if (!s.recommended) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }

  const XrSpatialSnapshotEXT snapshot = app.snapshot(context);
  const SpatialQuery found = app.query(snapshot, {XR_SPATIAL_COMPONENT_TYPE_MESH_2D_EXT});
  EXPECT_EQ(found.result, XR_SUCCESS);
  for (const XrSpatialMeshDataEXT& mesh : found.meshes2d) {
    s.mesh_vertices.push_back(app.vector2f(snapshot, mesh.vertexBuffer.bufferId).size());
    s.mesh_triangles.push_back(app.indices(snapshot, mesh.indexBuffer).size() / 3);
  }
  LT_CHECK(app.fn.destroySnapshot(snapshot));

  // Entities from the ids, an update snapshot of their bounds.
  std::vector<XrSpatialEntityEXT> entities;
  for (XrSpatialEntityIdEXT id : found.ids) {
    XrSpatialEntityEXT e = XR_NULL_HANDLE;
    EXPECT_EQ(app.entity(context, id, e), XR_SUCCESS);
    entities.push_back(e);
  }
  XrSpatialSnapshotEXT update = XR_NULL_HANDLE;
  EXPECT_EQ(app.update(context, entities, {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT}, update), XR_SUCCESS);
  const SpatialQuery updated = app.query(update, {XR_SPATIAL_COMPONENT_TYPE_BOUNDED_2D_EXT});
  EXPECT_EQ(updated.result, XR_SUCCESS);
  s.update_ids = updated.ids;
  s.update_bounds = updated.bounds;
  LT_CHECK(app.fn.destroySnapshot(update));
  for (XrSpatialEntityEXT e : entities) LT_CHECK(app.fn.destroyEntity(e));

  // A discovery started and completed at once (the runtime's futures are ready after its compute delay).
  SnapshotSteps early = app.start_discovery(context, {});
  EXPECT_EQ(early.start, XR_SUCCESS);
  app.complete_discovery(context, early);
  s.pending_complete = early.complete;
  if (early.complete == XR_SUCCESS && early.future_result == XR_SUCCESS) LT_CHECK(app.fn.destroySnapshot(early.snapshot));
  else EXPECT_EQ(app.cancel(early.future), XR_SUCCESS);

  LT_CHECK(app.fn.destroyContext(context));
  return s;
}

TEST(SpatialPassthrough, EveryStepAnswersAsTheRuntimeDoes) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  ScopedEnv delay("ROOMSENSE_SIM_COMPUTE_DELAY_MS", std::string("20"));  // futures really pending for a while
  const Steps want = run_steps(false);
  const Steps got = run_steps(true);
  EXPECT_EQ(want.cancelled_complete, XR_ERROR_FUTURE_INVALID_EXT);
  EXPECT_EQ(want.pending_complete, XR_ERROR_FUTURE_PENDING_EXT);
  EXPECT_TRUE(want.recommended);
  EXPECT_FALSE(want.update_ids.empty());
  EXPECT_EQ(want.update_ids.size(), want.mesh_triangles.size());
  EXPECT_EQ(got, want);
}

// ---- roomsense-demo --spatial-entities prints and writes what the runtime serves

const char* label_name(XrSpatialPlaneSemanticLabelEXT l) {
  switch (l) {
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_FLOOR_EXT: return "FLOOR";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_WALL_EXT: return "WALL";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_CEILING_EXT: return "CEILING";
    case XR_SPATIAL_PLANE_SEMANTIC_LABEL_TABLE_EXT: return "TABLE";
    default: return "UNCATEGORIZED";
  }
}

TEST(SpatialPassthrough, DemoWritesTheRuntimesPlanes) {
  ScopedEnv only("ROOMSENSE_SIM_EXTENSIONS", kPlanesOnly);
  ScopedEnv room("ROOMSENSE_SIM_SCENE", std::string("synthetic:default"));
  const Seen want = read_scene(false);

  // As a user runs it: the test's layer directory (XDG_DATA_HOME) left out, the demo finds the layer beside itself.
  const auto dir = roomsense::test::scratch_dir() / "spatial_demo";
  std::filesystem::create_directories(dir);
  const std::string command = std::string("env -u XDG_DATA_HOME '") + ROOMSENSE_DEMO + "' --spatial-entities --runtime-extensions " +
                              kPlanesOnly + " --output '" + dir.string() + "' > '" + (dir / "stdout.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream printed(dir / "stdout.txt");
  const std::string text((std::istreambuf_iterator<char>(printed)), std::istreambuf_iterator<char>());
  ASSERT_EQ(status, 0) << command << "\n" << text;
  EXPECT_NE(text.find("XR_SPATIAL_CAPABILITY_PLANE_TRACKING_EXT"), std::string::npos) << text;

  std::ifstream file(dir / "spatial_entities.json");
  ASSERT_TRUE(file) << "no spatial_entities.json in " << dir;
  const nlohmann::json json = nlohmann::json::parse(file);
  EXPECT_FALSE(json.at("layer").get<std::string>().empty()) << "the demo ran without the layer";
  const auto& planes = json.at("planes");
  ASSERT_EQ(planes.size(), want.planes.size());
  for (std::size_t i = 0; i < want.planes.size(); ++i) {
    const Plane& w = want.planes[i];
    const auto& g = planes[i];
    SCOPED_TRACE("plane " + std::to_string(i));
    EXPECT_EQ(g.at("id").get<XrSpatialEntityIdEXT>(), w.id);
    EXPECT_EQ(g.at("label").get<std::string>(), label_name(w.label));
    EXPECT_EQ(g.at("extents")[0].get<float>(), w.extents.width);
    EXPECT_EQ(g.at("extents")[1].get<float>(), w.extents.height);
    const auto& position = g.at("pose").at("position");
    EXPECT_EQ(position[0].get<float>(), w.pose.position.x);
    EXPECT_EQ(position[1].get<float>(), w.pose.position.y);
    EXPECT_EQ(position[2].get<float>(), w.pose.position.z);
    const auto& polygon = g.at("polygon");
    ASSERT_EQ(polygon.size(), w.polygon.size());
    for (std::size_t k = 0; k < w.polygon.size(); ++k) {
      EXPECT_EQ(polygon[k][0].get<float>(), w.polygon[k].x);
      EXPECT_EQ(polygon[k][1].get<float>(), w.polygon[k].y);
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
