// Beyond the thesis (issue 19): the bounds of an IncrementalAnalysis derived again only where the cells changed and
// meshed again only where the volume changed.
#pragma once
#include "roomsense/bounds.h"
#include "column_levels.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <stop_token>
#include <vector>

namespace roomsense::detail {

// What build_bounds kept of one storey's volume (bounds_volume.cpp): what it read but the grid's cells, G and H
// (Eq. 3.60, 3.61) as the columns gave them and as flattened, and the volume with its plane holes filled. The
// next volume finds G and H again only in the columns whose cells, room or ceiling changed (a column's G and H
// read those alone), flattens them again only where they or the room changed, and writes again only the columns
// whose flattened G or H changed and their neighbours: each column of the volume, its filled holes included, is
// a function of its own and its four neighbours' G and H.
struct StoreyVolumeMemo {
  GridSpec spec{};
  FloorCeiling levels{};
  int y_end = 0;
  std::vector<std::uint8_t> room;
  std::vector<int> ceiling;  // empty: none
  std::uint32_t min_plateau_area_bits = 0;  // BoundsParams, bit for bit
  std::vector<int> g_found, h_found, g, h;
  std::vector<std::uint8_t> volume;
  // The storage of the volume this memo gave out last, handed back once read (give_back): the next volume is
  // written into it. A home's volume is a megabyte, allocated and freed each update: fresh pages, each a page
  // fault on this project's VM (a SU_Apartment block update took 150-350 of them, 13-57 with the storage kept).
  std::vector<std::uint8_t> spare;
  void give_back(std::vector<std::uint8_t>&& storage) { spare = std::move(storage); }
};

// What fill_edge_contacts kept of the volume it filled last: that volume as it was given (before the fill), each
// column's lowest and highest solid level, and which blocks of four columns could fill in it. Whether a block can
// fill is a function of its four columns (over the solid box's levels) alone, so the next volume asks it again
// only of the blocks with a column that changed, as long as the solid box keeps its levels.
struct EdgeContactMemo {
  GridSpec spec{};
  std::vector<std::uint8_t> volume;
  std::vector<std::int32_t> lowest, highest;  // per column: ny and -1 where it holds no solid voxel
  int y_lo = 0, y_hi = -1;                    // the solid box's levels that may_fill was found over
  std::vector<std::uint8_t> may_fill;
  std::vector<std::uint8_t> filled;  // per column: whether it is one of a block the passes filled in
};

// What fill_edge_contacts tells mesh_volume of the volume it filled: its solid box, and the columns where it may
// differ from the volume the memo filled last (the columns that changed before the fill, or that either fill
// reached; the others are equal), empty where that is not known.
struct FilledVolume {
  SolidBox box{};
  std::vector<std::uint8_t> may_differ;
};

// What mesh_volume kept of the volume it meshed last: the volume, and each slice's polygons (their points and
// triangles). A slice between two voxel layers that are as they were meshes as it did (its mask, and the surface
// corners in its plane, come from those two layers alone), so mesh_volume meshes again only the slices through
// a change and replays the others, with the same result as meshing them all.
//
// build_room_bounds also keeps what it built a room's mesh from (`room`: the room's crop of the grid, its masks,
// ceilings, levels and parameters) and the mesh: the same inputs give the same mesh, which a change elsewhere in
// the home leaves to the rooms it did not reach; and the room's volume, which a change within the room derives
// again only in the columns it changed.
class MeshMemo {
 public:
  MeshMemo();
  ~MeshMemo();
  MeshMemo(MeshMemo&&) noexcept;
  MeshMemo& operator=(MeshMemo&&) noexcept;
  struct State;

  struct RoomInputs {
    GridSpec crop{};
    std::vector<std::uint8_t> cells, room, storey;
    std::vector<int> ceiling;
    FloorCeiling levels{};
    int y_end = 0;
    std::uint32_t min_plateau_area_bits = 0;  // BoundsParams, bit for bit
    bool operator==(const RoomInputs&) const = default;
  };
  std::optional<RoomInputs> room;  // where the mesh below is a room's
  std::vector<std::uint8_t> spare_cells;  // the storage of the room's cells before `room`'s (StoreyVolumeMemo::spare)
  BoundsMesh room_mesh;
  StoreyVolumeMemo room_volume;  // the room's volume, derived again only where its crop's cells changed
  // build_bounds's: the grid it read (its spec and cells), and each storey's volume.
  GridSpec volume_spec{};
  std::vector<std::uint8_t> volume_cells;
  std::vector<StoreyVolumeMemo> storey_volumes;
  EdgeContactMemo contacts;  // build_bounds's or build_room_bounds's, of the volume this memo meshes

 private:
  friend BoundsMesh mesh_volume(const GridSpec&, const std::vector<std::uint8_t>&, unsigned, std::stop_token,
                                MeshMemo*, const FilledVolume*);
  std::unique_ptr<State> state_;
};

// mesh_volume, build_bounds and build_room_bounds (bounds.h), served by `memo` where it is not null: they read
// it, and keep this volume's slices in it once they finish.
// `filled`, where not null, is what fill_edge_contacts told of `volume` (through memo->contacts where there is a
// memo): its solid box is not found again, nor its columns compared where they cannot differ.
BoundsMesh mesh_volume(const GridSpec& spec, const std::vector<std::uint8_t>& volume, unsigned threads,
                       std::stop_token stop, MeshMemo* memo, const FilledVolume* filled = nullptr);
BoundsMesh build_bounds(const VoxelGrid& grid, std::span<const BoundsStorey> storeys, const BoundsParams& params,
                        unsigned threads, std::stop_token stop, MeshMemo* memo);
// fill_edge_contacts (bounds.h), through `memo` where it is not null (EdgeContactMemo): the same volume it would
// fill without.
FilledVolume fill_edge_contacts(const GridSpec& spec, std::vector<std::uint8_t>& volume, unsigned threads,
                                EdgeContactMemo* memo);
// bounds_volume (bounds.h), each storey's volume derived again only where the cells changed since the volume
// `memo` kept (StoreyVolumeMemo), where it is not null; keeps this one's.
std::vector<std::uint8_t> bounds_volume(const VoxelGrid& grid, std::span<const BoundsStorey> storeys,
                                        const BoundsParams& params, unsigned threads, const std::stop_token& stop,
                                        MeshMemo* memo);
BoundsMesh build_room_bounds(const VoxelGrid& grid, const BoundsStorey& storey,
                             const std::vector<std::uint8_t>& room_columns, const BoundsParams& params,
                             unsigned threads, std::stop_token stop, MeshMemo* memo);
// room_bounds_volume (bounds.h) through `memo` where it is not null, and `changed` (per column, whether its cells
// changed since the volume the memo kept) where that is not null, as storey_volume reads them.
std::vector<std::uint8_t> room_bounds_volume(const VoxelGrid& grid, const BoundsStorey& storey,
                                             const std::vector<std::uint8_t>& room_columns, const BoundsParams& params,
                                             unsigned threads, const std::stop_token& stop, StoreyVolumeMemo* memo,
                                             const std::vector<std::uint8_t>* changed);

}  // namespace roomsense::detail
