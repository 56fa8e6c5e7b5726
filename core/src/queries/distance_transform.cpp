#include "distance_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomsense::detail {
namespace {

// One pass: d[q] = min_p (f[p] + (q - p)²), squared distances in and out. f[0] is finite (a padding cell), so the
// lower envelope is never empty; cells with no feature hold kFar, far beyond any real squared distance.
void envelope_1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v, std::vector<double>& z) {
  const int n = int(f.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto at = [&](int i) { return f[std::size_t(i)]; };
  const auto meet = [&](int q, int p) { return ((at(q) + double(q) * q) - (at(p) + double(p) * p)) / (2.0 * (q - p)); };
  std::size_t k = 0;
  v[0] = 0;
  z[0] = -kInf;
  z[1] = kInf;
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (s <= z[k]) s = meet(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[std::size_t(q)] = double(q - v[k]) * double(q - v[k]) + at(v[k]);
  }
}

}  // namespace

std::vector<float> distance_to_unmasked(int nx, int nz, const std::vector<std::uint8_t>& mask) {
  constexpr double kFar = 1e20;
  // Padded by one cell of 0 on every side: the raster's edge is an edge.
  const int px = nx + 2, pz = nz + 2;
  std::vector<double> grid(std::size_t(px) * std::size_t(pz), 0.0);
  for (int z = 0; z < nz; ++z)
    for (int x = 0; x < nx; ++x)
      grid[std::size_t(z + 1) * std::size_t(px) + std::size_t(x + 1)] =
          mask[std::size_t(z) * std::size_t(nx) + std::size_t(x)] ? kFar : 0.0;
  const std::size_t longest = std::size_t(std::max(px, pz));
  std::vector<double> f(longest), d(longest), zs(longest + 1);
  std::vector<int> v(longest);
  // One pass along every line of `count` cells, `stride` apart, starting at each of `lines` starts `step` apart.
  const auto pass = [&](int lines, std::size_t step, int count, std::size_t stride) {
    f.resize(std::size_t(count));
    d.resize(std::size_t(count));
    for (int line = 0; line < lines; ++line) {
      double* cells = grid.data() + std::size_t(line) * step;
      for (int i = 0; i < count; ++i) f[std::size_t(i)] = cells[std::size_t(i) * stride];
      envelope_1d(f, d, v, zs);
      for (int i = 0; i < count; ++i) cells[std::size_t(i) * stride] = d[std::size_t(i)];
    }
  };
  pass(pz, std::size_t(px), px, 1);  // rows
  pass(px, 1, pz, std::size_t(px));  // columns
  std::vector<float> out(std::size_t(nx) * std::size_t(nz));
  for (int z = 0; z < nz; ++z)
    for (int x = 0; x < nx; ++x)
      out[std::size_t(z) * std::size_t(nx) + std::size_t(x)] =
          float(std::sqrt(grid[std::size_t(z + 1) * std::size_t(px) + std::size_t(x + 1)]));
  return out;
}

std::vector<std::uint8_t> farther_than(int nx, int nz, const std::vector<std::uint8_t>& mask, float limit) {
  std::vector<std::uint8_t> out(std::size_t(nx) * std::size_t(nz), 0);
  if (!(limit < kFartherThanRows)) {  // far or NaN: the transform itself
    const std::vector<float> distance = distance_to_unmasked(nx, nz, mask);
    for (std::size_t c = 0; c < out.size(); ++c) out[c] = distance[c] > limit ? 1 : 0;
    return out;
  }
  // The transform's distances are float(sqrt(d)) of whole squared distances d, so `> limit` holds exactly from the
  // least such d on: `least`. A cell passes where no unmasked cell (nor the raster's outside) lies at a squared
  // distance below it: in each row dz away (dz² < least), none within `reach[dz]` = the largest dx with
  // dx² + dz² < least of the cell's x.
  const auto passes = [limit](long d) { return float(std::sqrt(double(d))) > limit; };
  long least = limit > 0.0f ? std::max(0L, long(std::floor(double(limit) * double(limit))) - 2) : 0;
  while (!passes(least)) ++least;
  std::vector<int> reach;
  for (int dz = 0; long(dz) * dz < least; ++dz) {
    int dx = 0;
    while (long(dx + 1) * (dx + 1) + long(dz) * dz < least) ++dx;
    reach.push_back(dx);
  }
  // Per cell, the distance along its row to the nearest unmasked cell or the raster's side (0 where unmasked).
  std::vector<int> along(out.size(), 0);
  for (int z = 0; z < nz; ++z) {
    int* row = along.data() + std::size_t(z) * std::size_t(nx);
    const std::uint8_t* m = mask.data() + std::size_t(z) * std::size_t(nx);
    for (int x = 0, run = 0; x < nx; ++x) row[x] = run = m[x] ? run + 1 : 0;
    for (int x = nx - 1, run = 0; x >= 0; --x) row[x] = std::min(row[x], run = m[x] ? run + 1 : 0);
  }
  // Row by row, each row dz away tested across the whole row at once (a loop that vectorizes).
  for (int z = 0; z < nz; ++z) {
    std::uint8_t* row = out.data() + std::size_t(z) * std::size_t(nx);
    std::fill(row, row + nx, std::uint8_t{1});
    for (std::size_t dz = 0; dz < reach.size(); ++dz)
      for (const long r : {long(z) - long(dz), long(z) + long(dz)}) {
        if (r < 0 || r >= nz) {
          std::fill(row, row + nx, std::uint8_t{0});
          break;
        }
        const int* other = along.data() + std::size_t(r) * std::size_t(nx);
        const int most = reach[dz];
        for (int x = 0; x < nx; ++x) row[x] &= std::uint8_t(other[x] > most);
      }
  }
  return out;
}

}  // namespace roomsense::detail
