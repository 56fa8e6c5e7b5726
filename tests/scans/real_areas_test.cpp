// Placement areas on the labelled Quest captures: each area checked against the labelled walls, floor and
// furniture volumes of its room (validity), and how much of the labelled free floor the floor areas cover.
// The figures are printed per room; the assertions hold what every room reaches with a margin.
#include "roomsense/analysis.h"
#include "roomsense/quest_capture.h"
#include "roomsense/scanio.h"
#include "rooms.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace roomsense {
namespace {

using scanio::OrientedRect;

// p in the rectangle's frame: x, y within the extents (grown by `margin`), z the height above its plane.
glm::vec3 local(const OrientedRect& r, const glm::vec3& p) {
  return glm::inverse(r.pose.orientation) * (p - r.pose.position);
}
bool over(const OrientedRect& r, const glm::vec3& p, float margin) {
  const glm::vec3 l = local(r, p);
  return std::abs(l.x) <= 0.5f * r.width + margin && std::abs(l.y) <= 0.5f * r.height + margin;
}
glm::vec3 normal_of(const OrientedRect& r) { return r.pose.orientation * glm::vec3(0, 0, 1); }

bool is_wall_label(const std::string& l) {
  return l == "WALL_FACE" || l == "INNER_WALL_FACE" || l == "INVISIBLE_WALL_FACE";
}

struct Labels {
  std::vector<OrientedRect> walls, floors, tops, footprints;
};

bool is_furniture_label(const std::string& l) {
  return l == "TABLE" || l == "COUCH" || l == "BED" || l == "STORAGE" || l == "CHAIR" || l == "OTHER";
}

Labels labels_of(const scanio::QuestCapture& c) {
  Labels out;
  for (const scanio::QuestPlane& p : c.planes) {
    if (is_wall_label(p.label)) out.walls.push_back(scanio::plane_rect(p));
    if (p.label == "FLOOR") out.floors.push_back(scanio::plane_rect(p));
    // A furniture plane is its seat or top (a couch's seat lies below its volume's top, the backrest).
    if (is_furniture_label(p.label)) out.tops.push_back(scanio::plane_rect(p));
  }
  for (const scanio::QuestVolume& v : c.volumes) {
    const OrientedRect top = scanio::volume_top_rect(v);
    out.tops.push_back(top);
    OrientedRect footprint = top;
    footprint.pose.position.y = 0.0f;
    out.footprints.push_back(footprint);
  }
  return out;
}

bool under_furniture(const Labels& l, glm::vec2 p, float margin) {
  return std::any_of(l.footprints.begin(), l.footprints.end(), [&](const OrientedRect& f) {
    return over(f, glm::vec3(p.x, f.pose.position.y, p.y), margin);
  });
}

// Areas per type as valid (on a labelled surface of their type), wrong (where the labels say something else:
// in front of a labelled wall but not on it, on the floor under labelled furniture, on labelled furniture at
// another height) or unlabelled (no label covers them: the far side of a wall, a window sill, an unlabelled
// shelf). The scans hold more than their labels, so only "wrong" is an error.
struct Tally {
  int valid = 0, wrong = 0, unlabelled = 0;
  int all() const { return valid + wrong + unlabelled; }
};

struct Figures {
  Tally walls, floors, furniture;
  double floor_coverage = 0;
};

Figures measure(const AnalysisResult& r, const Labels& l) {
  Figures f;
  for (const Area& a : r.areas) {
    if (a.type == AreaType::Wall) {
      // On a labelled wall: within 0.25 m of its plane (a voxel and the scan's offset from the label), over it,
      // facing the same way. Sides of labelled furniture tall enough to read as walls count too.
      bool on_wall = false, before_wall = false;
      for (const OrientedRect& w : l.walls) {
        if (!over(w, a.center, 0.1f)) continue;
        const float z = local(w, a.center).z;
        on_wall = on_wall || (std::abs(z) < 0.25f && glm::dot(normal_of(w), a.normal) > 0.7f);
        before_wall = before_wall || (z > 0.0f && z < 0.5f);
      }
      const bool by_furniture = under_furniture(l, {a.center.x, a.center.z}, 0.3f);
      (on_wall || by_furniture ? f.walls.valid : before_wall ? f.walls.wrong : f.walls.unlabelled) += 1;
    } else if (a.type == AreaType::Floor) {
      // On the labelled floor, at its height, and not over a labelled furniture footprint (a voxel's margin).
      const bool on_floor = std::any_of(l.floors.begin(), l.floors.end(), [&](const OrientedRect& fl) {
        return std::abs(local(fl, a.center).z) < 0.1f && over(fl, a.center, 0.1f);
      });
      bool free = !under_furniture(l, {a.center.x, a.center.z}, -0.1f);
      for (const glm::vec3& c : a.corners) free = free && !under_furniture(l, {c.x, c.z}, -0.1f);
      (on_floor && free ? f.floors.valid : f.floors.wrong) += 1;
    } else if (a.type == AreaType::Furniture) {
      // On the top or seat of labelled furniture, within a voxel and a half of its height.
      bool over_any = false, at_height = false;
      for (const OrientedRect& t : l.tops) {
        if (!over(t, glm::vec3(a.center.x, t.pose.position.y, a.center.z), 0.1f)) continue;
        over_any = true;
        at_height = at_height || std::abs(a.center.y - t.pose.position.y) < 0.15f;
      }
      (at_height ? f.furniture.valid : over_any ? f.furniture.wrong : f.furniture.unlabelled) += 1;
    }
  }
  // Coverage: 5 cm raster over the labelled floor, away from its edge and from furniture footprints.
  int free_points = 0, covered = 0;
  for (const OrientedRect& fl : l.floors)
    for (float u = -0.5f * fl.width + 0.15f; u < 0.5f * fl.width - 0.15f; u += 0.05f)
      for (float v = -0.5f * fl.height + 0.15f; v < 0.5f * fl.height - 0.15f; v += 0.05f) {
        const glm::vec3 p = fl.pose.apply(glm::vec3(u, v, 0.0f));
        if (under_furniture(l, {p.x, p.z}, 0.15f)) continue;
        ++free_points;
        covered += std::any_of(r.areas.begin(), r.areas.end(), [&](const Area& a) {
          if (a.type != AreaType::Floor) return false;
          const glm::vec3 d = p - a.center;
          return std::abs(glm::dot(d, a.x_axis())) <= a.half_width && std::abs(glm::dot(d, a.y_axis())) <= a.half_height;
        }) ? 1 : 0;
      }
  f.floor_coverage = free_points ? double(covered) / free_points : 0.0;
  return f;
}

class QuestAreas : public testing::TestWithParam<const char*> {};

TEST_P(QuestAreas, AreasLieOnTheirLabelledSurfaces) {
  ROOMSENSE_REQUIRE_ROOM(path, std::string("quest-iwer/") + GetParam() + ".json");
  const scanio::QuestCapture capture = scanio::load_quest_capture(path.string());
  const AnalysisResult r = analyze(capture.mesh);
  ASSERT_TRUE(r.ok()) << r.status_message;
  const Labels labels = labels_of(capture);
  ASSERT_FALSE(labels.walls.empty());
  ASSERT_FALSE(labels.floors.empty());
  const Figures f = measure(r, labels);
  const auto row = [](const Tally& t) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%3d valid %2d wrong %2d unlabelled", t.valid, t.wrong, t.unlabelled);
    return std::string(buf);
  };
  std::printf("[ figures  ] %-13s walls %s | floors %s | furniture %s | free floor covered %5.1f %%\n", GetParam(),
              row(f.walls).c_str(), row(f.floors).c_str(), row(f.furniture).c_str(), 100 * f.floor_coverage);
  RecordProperty("floor_coverage_percent", int(std::lround(100 * f.floor_coverage)));
  EXPECT_GT(f.walls.valid, 0);
  EXPECT_GT(f.floors.valid, 0);
  // At most 5 % of the areas the labels can judge contradict them (none in most rooms).
  for (const Tally* t : {&f.walls, &f.floors, &f.furniture}) EXPECT_LE(t->wrong, 0.05 * (t->valid + t->wrong) + 0.5);
  EXPECT_GE(f.floor_coverage, 0.15);
}

INSTANTIATE_TEST_SUITE_P(Rooms, QuestAreas,
                         testing::Values("living_room", "meeting_room", "music_room", "office_large", "office_small"));

// Every scan, labelled or not: areas of each kind a room has, classified by the rules of §3.5.
class ScanAreas : public testing::TestWithParam<const char*> {};

TEST_P(ScanAreas, ClassifiedAreasOfEveryKind) {
  ROOMSENSE_REQUIRE_ROOM(path, GetParam());
  const AnalysisResult r = analyze(scanio::load_mesh_file(path.string()));
  ASSERT_TRUE(r.ok()) << r.status_message;
  std::array<int, 4> by_type{};
  for (const Area& a : r.areas) {
    ++by_type[std::size_t(a.type) - 1];
    EXPECT_EQ(a.flags, category_flags(a.type, a.size, a.reach));
    if (a.type == AreaType::Floor) {
      EXPECT_NEAR(a.center.y, r.floor_y, 1e-4f);
      EXPECT_EQ(a.reach, Reach::Close);
    }
    if (a.type == AreaType::Ceiling) {
      EXPECT_NEAR(a.center.y, r.ceiling_y, 1e-4f);
    }
    if (a.type == AreaType::Wall) {
      EXPECT_NEAR(a.normal.y, 0.0f, 1e-6f);
    }
  }
  std::printf("[ figures  ] %s: %zu areas: %d wall, %d floor, %d ceiling, %d furniture\n", GetParam(), r.areas.size(),
              by_type[0], by_type[1], by_type[2], by_type[3]);
  EXPECT_GT(by_type[0], 0);
  EXPECT_GT(by_type[1], 0);
  EXPECT_GT(by_type[2], 0);
}

INSTANTIATE_TEST_SUITE_P(Rooms, ScanAreas,
                         testing::Values("hololens1/holotoolkit_fake_spatial_mapping.obj",
                                         "hololens1/mrtk_example_spatial_mesh.obj",
                                         "hololens2-su/SU_Kitchen_world_mesh.obj",
                                         "hololens2-su/SU_Apartment_world_mesh.obj"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace roomsense
