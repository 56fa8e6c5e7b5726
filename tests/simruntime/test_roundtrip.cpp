// The main test: compute a scene through the real loader, read every mesh component, pose it, and
// compare with the room file read by scanio: every file vertex served (exact count), the same triangles,
// error below 1e-5 m. Also checks that the pose matters (a consumer that ignores it gets it wrong).
#include "mesh_compare.h"
#include "sim_env.h"
#include "rooms.h"

#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"

#include <gtest/gtest.h>

namespace {

using namespace simtest;

void expect_served_exactly(const roomsense::Scan& file, const std::string& scene_path, const char* chunk_size, bool uint16) {
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", scene_path);
  ScopedEnv chunk("ROOMSENSE_SIM_CHUNK_SIZE", std::string(chunk_size));
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  XrSceneObserverCreateInfoMSFT create{XR_TYPE_SCENE_OBSERVER_CREATE_INFO_MSFT};
  ASSERT_EQ(app.msft.createObserver(app.session, &create, &observer), XR_SUCCESS);
  XrSceneMSFT scene = compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_VISUAL_MESH_MSFT, XR_SCENE_COMPUTE_FEATURE_COLLIDER_MESH_MSFT});
  for (auto type : {XR_SCENE_COMPONENT_TYPE_VISUAL_MESH_MSFT, XR_SCENE_COMPONENT_TYPE_COLLIDER_MESH_MSFT}) {
    const auto meshes = read_meshes(app, scene, type, uint16);
    EXPECT_GT(meshes.size(), 1u) << "the room should be split into several chunks";
    const MeshComparison c = compare_with_file(file, meshes);
    EXPECT_EQ(c.matched_file_vertices, file.vertices.size());
    EXPECT_EQ(c.served_triangles, file.indices.size() / 3);
    EXPECT_TRUE(c.same_triangles);
    EXPECT_LT(c.max_error, 1e-5);
    EXPECT_GT(c.max_error_without_pose, 0.1) << "vertices must be in component space";
  }
  EXPECT_EQ(app.msft.destroyScene(scene), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);
}

TEST(SimRoundTrip, OwnObjRoom) {
  const auto path = write_box_room("roundtrip_box.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  expect_served_exactly(file, path.string(), "1.0", false);
}

TEST(SimRoundTrip, OwnObjRoomUint16Indices) {
  const auto path = write_box_room("roundtrip_box16.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  expect_served_exactly(file, path.string(), "1.5", true);
}

TEST(SimRoundTrip, QuestCapture) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/office_small.json");
  const roomsense::Scan file = roomsense::scanio::load_quest_capture(path.string()).mesh;
  expect_served_exactly(file, path.string(), "2.0", false);
}

TEST(SimRoundTrip, SharedObj) {
  ROOMSENSE_REQUIRE_ROOM(path, "hololens2-su/SU_Kitchen_world_mesh.obj");
  const roomsense::Scan file = simtest::join_identical_vertices(roomsense::scanio::load_mesh_file(path.string()));
  expect_served_exactly(file, path.string(), "3.0", true);
}

TEST(SimRoundTrip, QuestLabelsBecomeObjectsAndPlanes) {
  ROOMSENSE_REQUIRE_ROOM(path, "quest-iwer/office_small.json");
  ScopedEnv scene_env("ROOMSENSE_SIM_SCENE", path.string());
  App app;
  XrSceneObserverMSFT observer = XR_NULL_HANDLE;
  ASSERT_EQ(app.msft.createObserver(app.session, nullptr, &observer), XR_SUCCESS);
  XrSceneMSFT s = compute_scene(app, observer, {XR_SCENE_COMPUTE_FEATURE_PLANE_MSFT, XR_SCENE_COMPUTE_FEATURE_PLANE_MESH_MSFT});

  // Floors only, through the object-type filter, then their planes through the parent filter.
  XrSceneObjectTypeMSFT floor_kind = XR_SCENE_OBJECT_TYPE_FLOOR_MSFT;
  XrSceneObjectTypesFilterInfoMSFT kinds{XR_TYPE_SCENE_OBJECT_TYPES_FILTER_INFO_MSFT};
  kinds.objectTypeCount = 1;
  kinds.objectTypes = &floor_kind;
  XrSceneComponentsGetInfoMSFT get{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, &kinds, XR_SCENE_COMPONENT_TYPE_OBJECT_MSFT};
  XrSceneComponentMSFT floor{};
  XrSceneComponentsMSFT list{XR_TYPE_SCENE_COMPONENTS_MSFT, nullptr, 1, 0, &floor};
  ASSERT_EQ(app.msft.components(s, &get, &list), XR_SUCCESS);
  ASSERT_EQ(list.componentCountOutput, 1u);

  XrSceneComponentParentFilterInfoMSFT parent{XR_TYPE_SCENE_COMPONENT_PARENT_FILTER_INFO_MSFT, nullptr, floor.id};
  XrSceneComponentsGetInfoMSFT get_planes{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, &parent, XR_SCENE_COMPONENT_TYPE_PLANE_MSFT};
  XrScenePlaneMSFT plane{};
  XrScenePlanesMSFT planes{XR_TYPE_SCENE_PLANES_MSFT, nullptr, 1, &plane};
  XrSceneComponentMSFT plane_component{};
  XrSceneComponentsMSFT plane_list{XR_TYPE_SCENE_COMPONENTS_MSFT, &planes, 1, 0, &plane_component};
  ASSERT_EQ(app.msft.components(s, &get_planes, &plane_list), XR_SUCCESS);
  ASSERT_EQ(plane_list.componentCountOutput, 1u);
  EXPECT_EQ(plane.alignment, XR_SCENE_PLANE_ALIGNMENT_TYPE_HORIZONTAL_MSFT);
  EXPECT_NEAR(plane.size.width, 2.463, 0.01);
  EXPECT_NE(plane.meshBufferId, 0u);

  XrSceneComponentsLocateInfoMSFT locate{XR_TYPE_SCENE_COMPONENTS_LOCATE_INFO_MSFT, nullptr, app.local, app.now(), 1, &plane_component.id};
  XrSceneComponentLocationMSFT where{};
  XrSceneComponentLocationsMSFT located{XR_TYPE_SCENE_COMPONENT_LOCATIONS_MSFT, nullptr, 1, &where};
  ASSERT_EQ(app.msft.locate(s, &locate, &located), XR_SUCCESS);
  EXPECT_NEAR(where.pose.position.y, 0.049, 0.005);
  // The normal (+Z) of a floor points up, into the room.
  const glm::dvec3 normal = posed({where.pose.orientation, {0, 0, 0}}, {0, 0, 1});
  EXPECT_GT(normal.y, 0.99);

  // Every wall plane is vertical with its normal horizontal.
  const auto all_planes = [&](XrSceneObjectTypeMSFT kind) {
    XrSceneObjectTypesFilterInfoMSFT filter{XR_TYPE_SCENE_OBJECT_TYPES_FILTER_INFO_MSFT, nullptr, 1, &kind};
    XrSceneComponentsGetInfoMSFT g{XR_TYPE_SCENE_COMPONENTS_GET_INFO_MSFT, &filter, XR_SCENE_COMPONENT_TYPE_PLANE_MSFT};
    XrSceneComponentsMSFT l{XR_TYPE_SCENE_COMPONENTS_MSFT};
    EXPECT_EQ(app.msft.components(s, &g, &l), XR_SUCCESS);
    std::vector<XrScenePlaneMSFT> p(l.componentCountOutput);
    std::vector<XrSceneComponentMSFT> c(l.componentCountOutput);
    XrScenePlanesMSFT pl{XR_TYPE_SCENE_PLANES_MSFT, nullptr, uint32_t(p.size()), p.data()};
    l.next = &pl;
    l.componentCapacityInput = uint32_t(c.size());
    l.components = c.data();
    EXPECT_EQ(app.msft.components(s, &g, &l), XR_SUCCESS);
    return p;
  };
  const auto walls = all_planes(XR_SCENE_OBJECT_TYPE_WALL_MSFT);
  EXPECT_EQ(walls.size(), 4u);
  for (const auto& w : walls) EXPECT_EQ(w.alignment, XR_SCENE_PLANE_ALIGNMENT_TYPE_VERTICAL_MSFT);
  EXPECT_EQ(all_planes(XR_SCENE_OBJECT_TYPE_CEILING_MSFT).size(), 1u);
  EXPECT_GE(all_planes(XR_SCENE_OBJECT_TYPE_PLATFORM_MSFT).size(), 2u);  // the table, as a plane and as a box top

  EXPECT_EQ(app.msft.destroyScene(s), XR_SUCCESS);
  EXPECT_EQ(app.msft.destroyObserver(observer), XR_SUCCESS);
}

}  // namespace
