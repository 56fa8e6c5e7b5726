#include "scan_progress.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomsense::sim {

XrTime ScanStep::update_time(const ChunkCell& cell, XrTime otherwise) const {
  const auto it = changed.find(cell);
  return it == changed.end() ? otherwise : it->second;
}

ScanProgress::ScanProgress(std::shared_ptr<const Room> room, double chunk_size, const glm::dvec3& head, double seconds,
                           XrTime start)
    : room_(std::move(room)), chunk_size_(chunk_size) {
  const Scan& mesh = room_->mesh;
  std::vector<ChunkCell> triangle_cells;
  triangle_cells.reserve(mesh.indices.size() / 3);
  std::map<ChunkCell, glm::dvec3> centres;  // the cells' own centres: where the user looks to see them
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const ChunkCell cell = triangle_cell(mesh, t, chunk_size);
    triangle_cells.push_back(cell);
    centres.emplace(cell, (glm::dvec3(double(cell.x), double(cell.y), double(cell.z)) + 0.5) * chunk_size);
  }
  for (const auto& [cell, centre] : centres) order_.push_back(cell);
  std::stable_sort(order_.begin(), order_.end(), [&](const ChunkCell& a, const ChunkCell& b) {
    return glm::distance(centres[a], head) < glm::distance(centres[b], head);
  });
  for (std::size_t r = 0; r < order_.size(); ++r) rank_[order_[r]] = r;
  triangle_rank_.reserve(triangle_cells.size());
  for (const ChunkCell& cell : triangle_cells) triangle_rank_.push_back(rank_[cell]);
  const double n = double(std::max<std::size_t>(order_.size(), 1));
  const double half_ns = 0.5 * seconds * 1e9;
  for (std::size_t r = 0; r < order_.size(); ++r) {
    shown_.push_back(start + XrTime(std::llround(half_ns * double(r) / n)));
    whole_.push_back(start + XrTime(std::llround(half_ns + half_ns * double(r) / n)));
  }
}

std::size_t ScanProgress::step_at(XrTime now) const {
  // Both lists rise with the rank, and every chunk is shown before the first is made whole.
  const auto passed = [now](const std::vector<XrTime>& times) {
    return std::size_t(std::upper_bound(times.begin(), times.end(), now) - times.begin());
  };
  return passed(shown_) + passed(whole_);
}

std::shared_ptr<const ScanStep> ScanProgress::at(XrTime now) {
  const std::size_t step = step_at(now);
  std::lock_guard lock(mutex_);
  if (!cached_ || cached_step_ != step) {
    cached_ = build(step);  // the step before is let go: a built scene of it stays only while a snapshot holds it
    cached_step_ = step;
  }
  return cached_;
}

std::shared_ptr<const ScanStep> ScanProgress::build(std::size_t step) const {
  auto out = std::make_shared<ScanStep>();
  const std::size_t n = order_.size();
  const std::size_t shown = std::min(step, n), whole = step > n ? step - n : 0;
  for (std::size_t r = 0; r < shown; ++r) out->changed[order_[r]] = r < whole ? whole_[r] : shown_[r];
  if (whole == n) {
    out->room = room_;
    return out;
  }
  // The chunks shown: a whole one's triangles, or every second triangle of a coarse one, in the room's order, on
  // the vertices they use (in order of first use, so a chunk made whole is the room's own chunk).
  const Scan& mesh = room_->mesh;
  auto room = std::make_shared<Room>();
  room->source = room_->source;
  room->objects = room_->objects;
  room->mesh.labels = mesh.labels;
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> index_of(mesh.vertices.size(), kUnset);
  std::vector<std::uint8_t> odd(n, 0);  // per coarse chunk: whether its next triangle is dropped
  for (std::size_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t) {
    const std::size_t r = triangle_rank_[t];
    if (r >= shown) continue;
    if (r >= whole && (odd[r] ^= 1) == 0) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.indices[3 * t + k];
      if (index_of[v] == kUnset) {
        index_of[v] = std::uint32_t(room->mesh.vertices.size());
        room->mesh.vertices.push_back(mesh.vertices[v]);
      }
      room->mesh.indices.push_back(index_of[v]);
    }
  }
  out->room = std::move(room);
  return out;
}

}  // namespace roomsense::sim
