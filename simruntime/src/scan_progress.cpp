#include "scan_progress.h"
#include "process_state.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace roomsense::sim {

XrTime ScanStep::update_time(const ChunkCell& cell, XrTime otherwise) const {
  const auto it = changed.find(cell);
  return it == changed.end() ? otherwise : it->second;
}

std::shared_ptr<const ScanStep> whole_room(const std::shared_ptr<const Room>& room, double chunk_size) {
  struct Kept {
    std::mutex mutex;
    std::map<std::pair<const Room*, double>, std::weak_ptr<const ScanStep>> steps;
  };
  Kept& held = process_wide<Kept>();
  auto& kept = held.steps;
  std::lock_guard lock(held.mutex);
  std::erase_if(kept, [](const auto& entry) { return entry.second.expired(); });
  std::weak_ptr<const ScanStep>& entry = kept[{room.get(), chunk_size}];
  if (std::shared_ptr<const ScanStep> step = entry.lock()) return step;
  auto step = std::make_shared<ScanStep>();
  step->room = room;
  for (Chunk& chunk : split_into_chunks(room->mesh, chunk_size)) step->chunks.push_back(std::make_shared<const Chunk>(std::move(chunk)));
  entry = step;
  return step;
}

ScanProgress::ScanProgress(std::shared_ptr<const Room> room, double chunk_size, const glm::dvec3& head, double seconds,
                           XrTime start)
    : whole_room_(whole_room(room, chunk_size)) {
  // The coarse chunks: every second triangle of each cell, on the vertices they use, split as the room is.
  const Scan& mesh = room->mesh;
  Scan coarse;
  std::map<ChunkCell, bool> keep_next;  // per cell: whether its next triangle is kept
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  std::vector<std::uint32_t> index_of(mesh.vertices.size(), kUnset);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const auto [next, is_new] = keep_next.try_emplace(triangle_cell(mesh, t, chunk_size), true);
    if (next->second)
      for (std::size_t k = t; k < t + 3; ++k) {
        std::uint32_t& v = index_of[mesh.indices[k]];
        if (v == kUnset) {
          v = std::uint32_t(coarse.vertices.size());
          coarse.vertices.push_back(mesh.vertices[mesh.indices[k]]);
        }
        coarse.indices.push_back(v);
      }
    next->second = !next->second;
  }
  std::map<ChunkCell, SharedChunk> coarse_of, whole_of;
  for (Chunk& chunk : split_into_chunks(coarse, chunk_size)) {
    const ChunkCell cell = chunk.cell;
    coarse_of[cell] = std::make_shared<const Chunk>(std::move(chunk));
  }
  for (const SharedChunk& chunk : whole_room_->chunks) whole_of[chunk->cell] = chunk;
  // The cells with triangles, nearest the head first (their own centres: where the user looks to see them).
  for (const auto& [cell, chunk] : coarse_of) order_.push_back(cell);
  const auto centre = [&](const ChunkCell& c) {
    return (glm::dvec3(double(c.x), double(c.y), double(c.z)) + 0.5) * chunk_size;
  };
  std::stable_sort(order_.begin(), order_.end(), [&](const ChunkCell& a, const ChunkCell& b) {
    return glm::distance(centre(a), head) < glm::distance(centre(b), head);
  });
  by_cell_.resize(order_.size());
  std::iota(by_cell_.begin(), by_cell_.end(), std::size_t{0});
  std::sort(by_cell_.begin(), by_cell_.end(), [&](std::size_t a, std::size_t b) { return order_[a] < order_[b]; });
  const double n = double(std::max<std::size_t>(order_.size(), 1));
  const double half_ns = 0.5 * seconds * 1e9;
  for (std::size_t r = 0; r < order_.size(); ++r) {
    coarse_.push_back(coarse_of.at(order_[r]));
    whole_chunks_.push_back(whole_of.at(order_[r]));
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
    cached_ = build(step);  // the step before is let go: what was built of it stays only while something holds it
    cached_step_ = step;
  }
  return cached_;
}

std::shared_ptr<const ScanStep> ScanProgress::build(std::size_t step) const {
  const std::size_t n = order_.size();
  const std::size_t shown = std::min(step, n), whole = step > n ? step - n : 0;
  auto out = std::make_shared<ScanStep>();
  out->room = whole_room_->room;
  for (std::size_t r = 0; r < shown; ++r) out->changed[order_[r]] = r < whole ? whole_[r] : shown_[r];
  if (whole == n) {  // the whole room (with any chunks of vertices alone), each chunk at the time it became whole
    out->chunks = whole_room_->chunks;
    return out;
  }
  for (std::size_t r : by_cell_)
    if (r < shown) out->chunks.push_back(r < whole ? whole_chunks_[r] : coarse_[r]);
  return out;
}

}  // namespace roomsense::sim
