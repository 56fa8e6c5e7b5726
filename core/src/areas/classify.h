// Space classification of §3.5: a reduced rectangle in metres with its pose, size and category
// (Eq. 3.54-3.58), and its interaction level (§3.5.1/3.5.2, Eq. 3.59).
#pragma once
#include "reduce.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace roomsense::detail {

struct PlacementContext {
  const GridSpec& spec;
  const RoomFeatures& features;
  SurfaceLevels surfaces;
  const FeatureParams& feature_params;
};

// The horizontal direction (not normalized) the wall-normal bits of F point to (Alg. 1).
glm::vec3 normal_bits_direction(std::uint8_t bits);

// Everything of an Area but its reach (left None) and the reach bits of its flags.
Area to_area(const Sized& found, AreaType type, const PlacementContext& context);

// What reach reads of an area of V_Floor, in the X-Z plane: its centre and half width. A large floor has hundreds
// of thousands: 12 bytes each, not an Area's hundred.
struct ReachFloor {
  glm::vec2 center{0.0f};
  float half_width = 0.0f;
  explicit ReachFloor(const Area& a) : center(a.center.x, a.center.z), half_width(a.half_width) {}
  ReachFloor(glm::vec2 center_xz, float half) : center(center_xz), half_width(half) {}
};

// ReachFloor(to_area(found, AreaType::Floor, context)) without the rest of the Area (its rotation's atan2, its
// flags): V_Floor's areas are tens of thousands on a large floor.
ReachFloor reach_floor(const Sized& found, const PlacementContext& context);

// And of an area of V_Wall: the same, and its top edge.
struct ReachWall : ReachFloor {
  glm::vec2 top_left{0.0f}, top_right{0.0f};  // corners 3 and 2
  explicit ReachWall(const Area& a)
      : ReachFloor(a), top_left(a.corners[3].x, a.corners[3].z), top_right(a.corners[2].x, a.corners[2].z) {}
};

class WallSegments;  // reach.cpp: V_Wall's top edges bucketed in X-Z

// What assign_reach found in an IncrementalAnalysis's previous analysis of a storey (its SearchCache keeps it).
// What an area sees is a function of what reach reads of the area in X-Z, the set of V_Floor, V_Wall and two
// parameters: whether some floor area with a gap below the close distance is visible, else some other. (Heights
// decide only whether a wall seeing a near floor is low enough for Close, which is tested anew each time: a floor
// height refined by a re-sent chunk keeps the memo.) So where V_Wall and the parameters are the previous ones, an
// area found before keeps what it saw while the floor that showed it is still there, and only the floors V_Floor
// gained can make it see more. Empty (no segments) until an analysis wrote it.
struct ReachMemo {
  using AreaKey = std::array<std::uint32_t, 10>;   // the bits of what reach reads of an area in X-Z
  using FloorKey = std::array<std::uint32_t, 3>;   // of a ReachFloor
  // What the areas were seen against (ReachView::keep).
  std::vector<FloorKey> floors;  // V_Floor
  std::vector<ReachWall> walls;
  std::array<std::uint32_t, 2> scalars{};  // close_distance, wall_view_cone_deg
  std::shared_ptr<const WallSegments> segments;  // of `walls`
  // Per list of areas assigned on its own (the area search: one per area type), per area of the previous analysis:
  // its key, what it saw (FloorIndex::Visible in reach.cpp) and the floor that decided it (for None, none).
  struct Seen {
    std::vector<AreaKey> areas;
    std::vector<std::uint8_t> seen;
    std::vector<FloorKey> witness;
    std::vector<std::uint32_t> witness_at;  // its index in V_Floor; for None, none
    std::size_t searched = 0;  // of those areas, the ones whose floors were searched (not taken from the memo)
    bool same = false;  // as assign_reach's result: the list's areas and floors are the memo's, which holds
  };
  std::array<Seen, 4> lists;
};

// V_Wall's top edges bucketed for assign_reach's lines of sight: the memo's where its walls are these, else built.
// They depend on V_Wall alone, so the area search builds them as soon as V_Wall is final, beside its square
// searches, rather than after them (on the hall a quarter of a millisecond of one thread).
std::shared_ptr<const WallSegments> reach_segments(const std::vector<ReachWall>& walls, const ReachMemo* memo);

// What reach reads of V_Floor and V_Wall, found once for all of an analysis's areas, so that each list of them
// (the area search: each type's, as soon as it has grown) is assigned on its own, beside the others: the walls'
// segments, the floors' buckets (made by the first search that needs them) and, with a memo, how the floors
// differ from those its areas were seen against. Holds references to `floors` and `walls`.
class ReachView {
 public:
  // `wall_segments`: reach_segments(walls, memo), where the caller made them; none: made here.
  ReachView(const std::vector<ReachFloor>& floors, const std::vector<ReachWall>& walls, const AreaParams& params,
            const ReachMemo* memo = nullptr, std::shared_ptr<const WallSegments> wall_segments = nullptr);
  ~ReachView();
  ReachView(const ReachView&) = delete;
  ReachView& operator=(const ReachView&) = delete;
  // Once every list is assigned (next[i]: list i's, from assign_reach): what each saw and what they were seen
  // against, for the next analysis. An analysis that ends before leaves the memo as it was.
  void keep(ReachMemo& memo, std::span<ReachMemo::Seen> next) const;

 private:
  friend void assign_reach(std::vector<Area>& areas, const ReachView& view, float floor_y, const AreaParams& params,
                           unsigned threads, std::size_t list, ReachMemo::Seen* next);
  struct State;
  std::unique_ptr<State> state_;
};

// §3.5.1/3.5.2 for each area of `areas`, against the deduplicated (not overlap-reduced) floor and wall areas
// (V_Floor, V_Wall) of `view`. Sets reach and flags. Runs on up to `threads` threads; the result does not depend
// on it. With the view's memo, from the previous analysis's reach of its list `list` where it holds (ReachMemo),
// and this one's for the next analysis in `next` (ReachView::keep). `params` are the view's.
void assign_reach(std::vector<Area>& areas, const ReachView& view, float floor_y, const AreaParams& params,
                  unsigned threads, std::size_t list = 0, ReachMemo::Seen* next = nullptr);
// The same for one list against floors and walls of its own: with a memo, its first list, kept.
void assign_reach(std::vector<Area>& areas, const std::vector<ReachFloor>& floors, const std::vector<ReachWall>& walls,
                  float floor_y, const AreaParams& params, unsigned threads, ReachMemo* memo = nullptr,
                  std::shared_ptr<const WallSegments> wall_segments = nullptr);

}  // namespace roomsense::detail
