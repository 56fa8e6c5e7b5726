// Result reduction of §3.4: centre deduplication (Eq. 3.42-3.44), then, beyond the thesis, packing in place
// of its overlap reduction (Eq. 3.45-3.53).
#pragma once
#include "../key_table.h"
#include "candidate.h"

#include "roomsense/grid.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stop_token>

namespace roomsense::detail {

struct Sized {
  PackedCandidate packed;
  AreaSize size = AreaSize::Large;
  Candidate c() const { return packed.unpack(); }
};

class SampleRaster;

// Eq. 3.44: large, then medium, then small; a rectangle is kept when none of its centre voxels (Eq. 3.43) is
// already marked by a kept one. One size at a time, so that a type's sizes need not all be held at once.
// Packing and deduplication check the stop token every this many candidates (a floor's are millions).
inline constexpr std::size_t kStopEvery = 4096;

class CentreDeduplicator {
 public:
  explicit CentreDeduplicator(const GridSpec& spec, std::stop_token stop = {});  // the corners lie in the grid
  ~CentreDeduplicator();
  // The rectangles of the next size, in order. Calls keep(rectangle) for each rectangle kept, in order; returns
  // how many. A floor's are many: the caller keeps what it needs of each, not the list.
  std::size_t add(const Candidates& rects, AreaSize size, const std::function<void(const Sized&)>& keep);

 private:
  // A bit per voxel a centre may lie in, rows along x, per level from -1 to ny (a top's y_Actual lies a level
  // above its tiles): a level's bits exist from its first mark, so a floor's list marks one level.
  int nx_, nz_;
  std::vector<std::optional<BitSet>> levels_;
  std::stop_token stop_;
};

// The room's main direction, in degrees in [0, 90): the length-weighted mode of the wall rectangles' top edges
// modulo 90°. 0 without walls.
double dominant_direction_deg(const std::vector<Sized>& walls);

// The angle between a square's first edge and the main direction, modulo 90°: in [0, 45].
double misalignment_deg(const Candidate& square, double dominant_deg);

// IncrementalAnalysis (search_cache.h): packing replayed against the previous analysis's. An item keeps its
// previous decision unless an item before it in packing order that is new, gone, or decided otherwise now lies
// within reach of its samples; only those are tested, so the result is the whole packing's.
struct PackReplay {
  // An item's previous packing: one byte, as SearchCache keeps it for the next analysis.
  static constexpr std::int8_t kUnknown = -1, kRefused = 0, kPacked = 1;
  std::vector<std::int8_t> previous;  // per item, in the list's order: kPacked, kRefused or kUnknown
  std::vector<Candidate> gone;        // packed by the previous analysis, not in the list now
  // Squares: per item, its rank in packing order where it is known to be as before (SquarePacker::pack's
  // `ranks`), else kUnknownRank.
  static constexpr std::uint32_t kUnknownRank = 0xffffffffu;
  std::vector<std::uint32_t> ranks;
};

// Where the items a replay tests again lie: blocks of 4 x 4 voxel columns around the items that changed, a bit
// each, in rows of 64-bit words (a test is a word or two per row of blocks), over the columns the items lie in.
// A box reaching past them counts at their edge: it may find more than it should, never less.
class ChangedRegion {
 public:
  struct Box {
    glm::ivec2 lo, hi;  // columns (x, z), inclusive
  };
  explicit ChangedRegion(const Box& columns);
  // A rectangle's samples, marks and conflicts lie within its corners' columns and two more around them.
  static Box around(const Candidate& c);
  // around() of each of a list's shapes with corner 1 at (0, 0), and around() of a rectangle of the list from it
  // and its corner 1: a packing's replay tests every rectangle, most far from what changed, without unpacking.
  static std::vector<Box> around_shapes(std::span<const Candidates::Shape> shapes);
  static Box around(const PackedCandidate& c, const Box& shape_box);
  void add(const Box& b);
  // Inline, with the box of the boxes added first: most of a replay's tests lie far from every change.
  bool touches(const Box& b) const {
    if (empty_ || b.hi.x < added_.lo.x || b.lo.x > added_.hi.x || b.hi.y < added_.lo.y || b.lo.y > added_.hi.y)
      return false;
    return touches_blocks(b);
  }
  // The box of the boxes added, column by column (lo > hi while none was).
  const Box& added() const { return added_; }

 private:
  static constexpr int kBlock = 4;
  struct Blocks {
    glm::ivec2 lo, hi;
  };
  Blocks blocks(const Box& b) const;  // clamped to the region's blocks
  bool touches_blocks(const Box& b) const;
  glm::ivec2 origin_;  // the first block's first column
  int columns_, rows_;  // blocks
  std::size_t words_per_row_;
  std::vector<std::uint64_t> bits_;
  bool empty_ = true;
  Box added_{glm::ivec2(1), glm::ivec2(0)};  // touches() tests it first: most tests lie outside it
};

// Whether SquarePacker's contact of square c may read a column of `columns` (inclusive). Its samples lie 0.75
// voxels outside the edges between the corners' cell centres (beside an edge along an axis, the next row of
// cells), so each lies in a column within a voxel of those edges: a test of the edges against the box grown by a
// voxel. It may say yes where contact reads none of the box, never no where it reads one.
bool contact_may_read(const Candidate& c, const ChangedRegion::Box& columns);

// Packing, beyond the thesis (issue 14). Eq. 3.45-3.53 keep a rectangle unless one of its corners or edge
// midpoints lies in a kept one (walls widened by 2 voxels), which both leaves gaps (the widening, strips no
// test point reaches) and lets rotated squares overlap. Here a rectangle is kept unless it shares any of its
// surface (sampled on a half-voxel raster) with a kept one, in order: large, medium, small, and within a size
// squares aligned with the room's main direction first, so that large areas tile the free surface and
// smaller ones fill what they leave.
// Walls in search order, one size at a time (large, then medium, then small), so that a size is packed as soon
// as it is found, beside the next size's search.
class WallPacker {
 public:
  // The walls' corners lie in the grid's columns, at levels in [y_lo, y_hi].
  WallPacker(const GridSpec& spec, int y_lo, int y_hi, std::stop_token stop = {});
  ~WallPacker();
  // The walls of the next size, in search order; returns the indices kept, ascending. With a replay
  // (PackReplay), the decisions of walls far from what changed are the previous analysis's; a size packed
  // without one leaves the sizes after it none either.
  std::vector<std::size_t> pack(const Candidates& walls, const PackReplay* replay = nullptr);

 private:
  std::unique_ptr<SampleRaster> taken_;
  ChangedRegion changed_;  // over all sizes: a large wall's change reaches the smaller ones after it
  bool replayable_ = true;
  std::stop_token stop_;
};
// The columns a square may rest on: free floor D or free ceiling E (`mask`), or a furniture top C at a square's
// level (`top`: the column's level, equal or one below, Eq. 3.41). Inline: packing asks it for every sample of
// every candidate's outline.
struct TileMap {
  const GridSpec& spec;
  std::span<const std::uint8_t> mask;  // D or E; empty for furniture
  std::span<const int> top;            // C; empty for floor and ceiling
  bool operator()(int x, int z, int level) const {
    if (x < 0 || z < 0 || x >= spec.nx || z >= spec.nz) return false;
    const std::size_t col = spec.column(x, z);
    if (!mask.empty()) return mask[col] != 0;
    return top[col] == level || top[col] == level + 1;
  }
};

// Each rotated square shape's sample runs relative to corner 1, found once: packing decides every sample with
// exact arithmetic (corners and sample centres are multiples of 1/4), so a square moved by whole voxels has the
// same samples moved by two cells each way. Beside them the cells its contact samples (SquarePacker::contact)
// fall in, where they fall in the same cells wherever the square lies. A size's squares have a few hundred
// shapes; an IncrementalAnalysis keeps them from one analysis to the next (search_cache.h).
class SquareSampleRuns {
 public:
  struct Run {
    int dz, dx0, dx1;  // sample row and cells from 2 x corner 1's (x, z)
  };
  struct ContactCell {
    int dx, dz;  // from corner 1's column
    int samples;  // contact's samples in it, one after another along an edge
  };
  // None where c's edges are not those of the shape kept under its key (not a square's: e3 not fixed by e1).
  std::optional<std::span<const Run>> of(const Candidate& c);
  // None there too, and where a contact sample lies so near a cell's border that rounding at c's own
  // coordinates may move it (contact then samples c itself).
  std::optional<std::span<const ContactCell>> contact_cells(const Candidate& c);

 private:
  static constexpr std::size_t kMaxRuns = std::size_t{1} << 20;  // 12 MB, and as many contact cells
  struct Shape {
    glm::ivec3 e1, e3;
    std::size_t begin, end;  // into runs_
    std::size_t contact_begin, contact_end;  // into contacts_
    bool contact_exact;  // every contact sample at least kBorder from a cell's border
  };
  const Shape* shape_of(const Candidate& c);
  KeyTable index_;
  std::vector<Shape> shapes_;
  std::vector<Run> runs_;
  std::vector<ContactCell> contacts_;
};

// Within a size and alignment, squares pressed against more unusable cells (not tiles: walls, clutter, the
// edge of a top) go first, leaving the free surface in one piece for the next ones. For furniture, squares
// more than `level_tolerance` levels apart never conflict (Eq. 3.49). One size at a time: the size leads the
// order, so a size's squares can be searched, packed and dropped before the next size's are searched.
class SquarePacker {
 public:
  // `shared_samples`, where not null, is used instead of the packer's own (one packer at a time).
  SquarePacker(const GridSpec& spec, int level_tolerance, double dominant_deg, const TileMap& is_tile,
               std::stop_token stop = {}, SquareSampleRuns* shared_samples = nullptr);
  ~SquarePacker();
  // The squares of the next size (large, then medium, then small), in search order; returns the indices kept,
  // ascending.
  // With a replay (PackReplay), the decisions of squares far from what changed are the previous analysis's.
  // `ranks`, where given, receives each square's rank (for the next analysis's replay).
  std::vector<std::size_t> pack(const Candidates& squares, const PackReplay* replay = nullptr,
                                std::vector<std::uint32_t>* ranks = nullptr);

 private:
  class NonTileCounts;
  int contact(const Candidate& c);
  int misalignment_step(const Candidate& c);
  bool free(const Candidate& c);
  // square_samples (reduce.cpp) of c by its shape's runs.
  template <class F>
  bool each_sample_run(const Candidate& c, F f);
  struct ShapeFacts {
    int step = 0;             // misalignment_step
    bool has_middle = false;  // a middle sample inside the square (middle_sample)
    long middle_x = 0, middle_z = 0;  // the middle sample of the square whose corner 1 is (0, 0, 0)
  };
  ShapeFacts shape_facts(const Candidates::Shape& shape);
  // Inlined: pack_fresh asks it of most squares (a replay, of those it tests), and GCC otherwise calls it.
  [[gnu::always_inline]] bool middle_taken(const ShapeFacts& f, const PackedCandidate& square) const;
  void take(const Candidate& c);
  std::vector<std::size_t> pack_fresh(const Candidates& squares);

  int level_tolerance_;
  double dominant_deg_;
  TileMap is_tile_;
  std::unique_ptr<NonTileCounts> runs_;  // floor and ceiling: contact along the axes by run, not by cell
  std::unique_ptr<SquareSampleRuns> own_samples_;
  SquareSampleRuns* samples_;  // own_samples_ or the caller's
  KeyTable steps_of_direction_;  // by pack_key(dx, 0, dz) of the first side
  std::unique_ptr<SampleRaster> taken_;
  ChangedRegion changed_;  // over all sizes: a large square's change reaches the smaller ones after it
  bool replayable_ = true;
  std::stop_token stop_;
};

}  // namespace roomsense::detail
