// Builds the triangles of a synthetic room. Every planar piece is a rectangle (o, U, V) meshed as a grid of
// cells; its front face (counter-clockwise) faces U x V: walls face into the room, the floor up, the
// ceiling down, furniture outwards.
#include "roomsense/synthetic.h"

#include "roomsense/error.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace roomsense::synth {
namespace {

glm::vec2 rotate(glm::vec2 p, float yaw) {
  const float c = std::cos(yaw), s = std::sin(yaw);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// Splits [0, 1] at the given cuts, so a coarse mesh still follows window edges.
std::vector<float> breakpoints(std::vector<float> cuts) {
  cuts.push_back(0.0f);
  cuts.push_back(1.0f);
  for (float& c : cuts) c = std::clamp(c, 0.0f, 1.0f);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

class MeshBuilder {
 public:
  explicit MeshBuilder(const RoomSpec& spec) : spec_(spec), rng_(spec.seed), jitter_(0.0f, 1.0f) {}

  // A rectangle o + s U + t V, s,t in [0,1]; `keep(s, t)` can veto cells (by their centre) for openings.
  template <class Keep>
  void rectangle(glm::vec3 o, glm::vec3 u, glm::vec3 v, Keep&& keep) {
    const int nu = cells(glm::length(u)), nv = cells(glm::length(v));
    const std::uint32_t base = std::uint32_t(scan_.vertices.size());
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) scan_.vertices.push_back(o + u * (float(i) / float(nu)) + v * (float(j) / float(nv)));
    const auto at = [&](int i, int j) { return base + std::uint32_t(j * (nu + 1) + i); };
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const float s = (float(i) + 0.5f) / float(nu), t = (float(j) + 0.5f) / float(nv);
        if (!keep(s, t) || in_hole(o + u * s + v * t)) continue;
        scan_.indices.insert(scan_.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        scan_.indices.insert(scan_.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  void rectangle(glm::vec3 o, glm::vec3 u, glm::vec3 v) {
    rectangle(o, u, v, [](float, float) { return true; });
  }

  // A convex polygon as a fan, counter-clockwise as given.
  void fan(const std::vector<glm::vec3>& ring) {
    const std::uint32_t base = std::uint32_t(scan_.vertices.size());
    scan_.vertices.insert(scan_.vertices.end(), ring.begin(), ring.end());
    for (std::uint32_t i = 1; i + 1 < ring.size(); ++i) scan_.indices.insert(scan_.indices.end(), {base, base + i, base + i + 1});
  }

  std::size_t vertex_count() const { return scan_.vertices.size(); }
  // Vertices [from, end) above the ceiling's surface are moved down onto it (walls under a pitched roof), or
  // all of them onto it (the roof itself).
  void onto_ceiling(std::size_t from, bool all) {
    for (std::size_t i = from; i < scan_.vertices.size(); ++i) {
      glm::vec3& p = scan_.vertices[i];
      const float y = ceiling_at(spec_, {p.x, p.z});
      if (all || p.y > y) p.y = y;
    }
  }

  // A box hanging from the ceiling (a soffit, a beam): its underside facing down and its sides outwards.
  void hanging_box(glm::vec2 centre, glm::vec2 size, float yaw, float y0, float y1) {
    const glm::vec2 ax = rotate({size.x, 0.0f}, yaw), az = rotate({0.0f, size.y}, yaw);
    const glm::vec2 c0 = centre - 0.5f * ax - 0.5f * az;
    const glm::vec3 X(ax.x, 0.0f, ax.y), Z(az.x, 0.0f, az.y), Y(0.0f, y1 - y0, 0.0f);
    const glm::vec3 o(c0.x, y0, c0.y);
    rectangle(o, X, Z);                 // X x Z = -Y: the underside
    sides(o, X, Y, Z);
  }

  // An upright box without a bottom, faces outwards.
  void box(glm::vec2 centre, glm::vec2 size, float yaw, float y0, float y1) {
    const glm::vec2 ax = rotate({size.x, 0.0f}, yaw), az = rotate({0.0f, size.y}, yaw);
    const glm::vec2 c0 = centre - 0.5f * ax - 0.5f * az;
    const glm::vec3 X(ax.x, 0.0f, ax.y), Z(az.x, 0.0f, az.y), Y(0.0f, y1 - y0, 0.0f);
    const glm::vec3 o(c0.x, y0, c0.y);
    rectangle(o + Y, Z, X);             // top, facing +Y
    sides(o, X, Y, Z);
  }

  // The four sides of a box at o spanned by X, Y (up) and Z, facing outwards.
  void sides(glm::vec3 o, glm::vec3 X, glm::vec3 Y, glm::vec3 Z) {
    rectangle(o, Y, X);                 // Y x X = -Z: the side at the footprint's start
    rectangle(o + Z, X, Y);             // X x Y = +Z
    rectangle(o, Z, Y);                 // Z x Y = -X
    rectangle(o + X, Y, Z);             // Y x Z = +X
  }

  // Risers face down the stair, treads up (stair_footprint's frame: along = the way up, side to its left).
  void stair(const Stair& st, float floor_y) {
    const glm::vec2 d = rotate({1.0f, 0.0f}, st.yaw);
    const glm::vec3 along(d.x, 0.0f, d.y), side(-d.y, 0.0f, d.x);
    const float h = st.rise / float(st.steps);
    const glm::vec3 foot(st.start.x, floor_y, st.start.y);
    for (int k = 0; k < st.steps; ++k) {
      const glm::vec3 o = foot + along * (float(k) * st.tread) - side * (0.5f * st.width) + glm::vec3(0.0f, float(k) * h, 0.0f);
      rectangle(o, side * st.width, glm::vec3(0.0f, h, 0.0f));  // side x up = -along
      if (k + 1 < st.steps) rectangle(o + glm::vec3(0.0f, h, 0.0f), side * st.width, along * st.tread);  // side x along = +Y
    }
  }

  // Both faces of an interior wall with its doorways, the doorways' jambs and lintels, and its two ends.
  void partition(const Partition& w, float floor_y, float ceiling_y) {
    const glm::vec2 along2 = w.b - w.a;
    const float length = glm::length(along2);
    const glm::vec2 d = along2 / length;
    const glm::vec3 U(d.x, 0.0f, d.y), N(-d.y, 0.0f, d.x), V(0.0f, ceiling_y - floor_y, 0.0f);
    const glm::vec3 start(w.a.x, floor_y, w.a.y);
    const float half = 0.5f * w.thickness, height = ceiling_y - floor_y;
    std::vector<float> cuts;
    for (const Doorway& door : w.doorways) {
      cuts.push_back(door.u0 / length);
      cuts.push_back(door.u1 / length);
    }
    const std::vector<float> su = breakpoints(cuts);
    for (std::size_t i = 0; i + 1 < su.size(); ++i) {
      const float u0 = su[i] * length, u1 = su[i + 1] * length, mid = 0.5f * (u0 + u1);
      const auto door = std::find_if(w.doorways.begin(), w.doorways.end(),
                                     [&](const Doorway& dw) { return mid > dw.u0 && mid < dw.u1; });
      const float bottom = door == w.doorways.end() ? 0.0f : door->height;
      const glm::vec3 lo = start + U * u0 + glm::vec3(0.0f, bottom, 0.0f);
      const glm::vec3 run = U * (u1 - u0), up = V * ((height - bottom) / height);
      rectangle(lo + N * half, run, up);         // U x Y = N
      rectangle(lo - N * half + run, -run, up);  // -U x Y = -N
      if (door != w.doorways.end()) rectangle(lo - N * half, run, N * w.thickness);  // U x N = -Y: the lintel
    }
    const glm::vec3 across = N * w.thickness;
    for (const Doorway& door : w.doorways) {
      const glm::vec3 rise(0.0f, door.height, 0.0f);
      rectangle(start + U * door.u0 - N * half + across, -across, rise);  // -N x Y = U: into the doorway
      rectangle(start + U * door.u1 - N * half, across, rise);            // N x Y = -U
    }
    rectangle(start - N * half, across, V);                          // the ends, facing away along -U and +U
    rectangle(start + U * length + N * half, -across, V);
  }

  Scan finish() {
    if (spec_.noise > 0.0f)
      for (glm::vec3& p : scan_.vertices) {
        // One draw per statement: the order in which a call's arguments are evaluated is unspecified (GCC goes
        // right to left, clang left to right), and a room must not depend on the compiler. z, y, x is the order
        // GCC gave the rooms every test and figure was made with.
        const float z = jitter_(rng_);
        const float y = jitter_(rng_);
        const float x = jitter_(rng_);
        p += spec_.noise * glm::vec3(x, y, z);
      }
    return std::move(scan_);
  }

 private:
  int cells(float length) const {
    if (spec_.cell <= 0.0f) return 1;
    return std::max(1, int(std::lround(length / spec_.cell)));
  }
  bool in_hole(glm::vec3 p) const {
    return std::any_of(spec_.holes.begin(), spec_.holes.end(),
                       [&](const Hole& h) { return glm::length(p - h.centre) < h.radius; });
  }

  const RoomSpec& spec_;
  Scan scan_;
  std::mt19937 rng_;
  std::normal_distribution<float> jitter_;
};

void add_floor_or_ceiling(MeshBuilder& mesh, const RoomSpec& spec, float y, bool ceiling) {
  if (spec.cell <= 0.0f) {
    // Few large triangles: a fan over the convex outline, which turns counter-clockwise seen from above.
    std::vector<glm::vec3> ring;
    for (glm::vec2 p : spec.outline) ring.emplace_back(p.x, y, p.y);
    if (ceiling) std::reverse(ring.begin(), ring.end());
    mesh.fan(ring);
    return;
  }
  glm::vec2 lo = spec.outline.front(), hi = lo;
  for (glm::vec2 p : spec.outline) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 o(lo.x, y, lo.y), X(hi.x - lo.x, 0.0f, 0.0f), Z(0.0f, 0.0f, hi.y - lo.y);
  const std::vector<Rect>& openings = ceiling ? spec.ceiling_openings : spec.floor_openings;
  const auto inside = [&](float sx, float sz) {
    const glm::vec2 p{lo.x + sx * (hi.x - lo.x), lo.y + sz * (hi.y - lo.y)};
    return inside_outline(spec, p) && std::none_of(openings.begin(), openings.end(), [&](const Rect& r) {
             return p.x > r.lo.x && p.x < r.hi.x && p.y > r.lo.y && p.y < r.hi.y;
           });
  };
  const std::size_t first = mesh.vertex_count();
  if (ceiling) mesh.rectangle(o, X, Z, [&](float s, float t) { return inside(s, t); });  // X x Z = -Y
  else mesh.rectangle(o, Z, X, [&](float s, float t) { return inside(t, s); });          // Z x X = +Y
  if (ceiling && spec.pitch) mesh.onto_ceiling(first, true);  // the flat grid bent onto the roof
}

void add_wall(MeshBuilder& mesh, const RoomSpec& spec, int wall) {
  const glm::vec2 a = spec.outline[std::size_t(wall)];
  const glm::vec2 b = spec.outline[(std::size_t(wall) + 1) % spec.outline.size()];
  const float length = glm::length(b - a), height = spec.ceiling_y - spec.floor_y;
  // Seen from above the outline runs counter-clockwise, so the room lies to the left of a -> b; with U along
  // the wall and V up, U x V points to the right. Walk b -> a instead so the wall faces into the room.
  const glm::vec3 o(b.x, spec.floor_y, b.y), U(a.x - b.x, 0.0f, a.y - b.y), V(0.0f, height, 0.0f);
  std::vector<float> us, vs;
  std::vector<Window> windows;
  for (const Window& w : spec.windows)
    if (w.wall == wall) {
      windows.push_back(w);
      us.push_back(1.0f - w.u1 / length);
      us.push_back(1.0f - w.u0 / length);
      vs.push_back(w.y0 / height);
      vs.push_back(w.y1 / height);
    }
  const auto open = [&](float s, float t) {
    const float u = (1.0f - s) * length, y = t * height;
    return std::any_of(windows.begin(), windows.end(),
                       [&](const Window& w) { return u > w.u0 && u < w.u1 && y > w.y0 && y < w.y1; });
  };
  // Mesh each piece between window edges on its own, so even two-triangle pieces follow the openings.
  const std::vector<float> su = breakpoints(us), sv = breakpoints(vs);
  const std::size_t first = mesh.vertex_count();
  for (std::size_t i = 0; i + 1 < su.size(); ++i)
    for (std::size_t j = 0; j + 1 < sv.size(); ++j) {
      const float s0 = su[i], s1 = su[i + 1], t0 = sv[j], t1 = sv[j + 1];
      if (open(0.5f * (s0 + s1), 0.5f * (t0 + t1))) continue;
      const glm::vec3 po = o + U * s0 + V * t0, pu = U * (s1 - s0), pv = V * (t1 - t0);
      // Under a pitched roof: cells wholly above it are left out, the rest end at it (onto_ceiling).
      mesh.rectangle(po, pu, pv, [&](float s, float t) {
        const glm::vec3 p = po + pu * s + pv * t;
        return !spec.pitch || p.y - 0.5f * spec.cell <= ceiling_at(spec, {p.x, p.z});
      });
    }
  if (spec.pitch) mesh.onto_ceiling(first, false);
}

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// Corners of a yawed rectangle footprint, counter-clockwise seen from above (+Y): in (x, z) that is the
// negative sense, since +Z points towards the viewer's bottom when looking down on the X-Z plane.
std::vector<glm::vec2> footprint(glm::vec2 centre, glm::vec2 size, float yaw) {
  std::vector<glm::vec2> out;
  for (glm::vec2 c : {glm::vec2(-0.5f, -0.5f), glm::vec2(-0.5f, 0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(0.5f, -0.5f)})
    out.push_back(centre + rotate(c * size, yaw));
  return out;
}

bool inside_convex(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const float c = cross2(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]);
    pos = pos || c > 0.0f;
    neg = neg || c < 0.0f;
  }
  return !(pos && neg);
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

float distance_to_polygon_edges(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  float d = INFINITY;
  for (std::size_t i = 0; i < poly.size(); ++i) d = std::min(d, distance_to_segment(p, poly[i], poly[(i + 1) % poly.size()]));
  return d;
}

}  // namespace

std::vector<glm::vec2> rectangle(float width, float depth, float yaw) {
  return footprint(glm::vec2(0.0f), {width, depth}, yaw);
}

Scan generate(const RoomSpec& spec) {
  MeshBuilder mesh(spec);
  add_floor_or_ceiling(mesh, spec, spec.floor_y, false);
  add_floor_or_ceiling(mesh, spec, spec.ceiling_y, true);
  for (int w = 0; w < int(spec.outline.size()); ++w) add_wall(mesh, spec, w);
  for (const Box& b : spec.boxes) mesh.box(b.centre, b.size, b.yaw, spec.floor_y, spec.floor_y + b.height);
  constexpr float kTop = 0.04f, kLeg = 0.05f;
  for (const Table& t : spec.tables) {
    mesh.box(t.centre, t.size, t.yaw, spec.floor_y + t.height - kTop, spec.floor_y + t.height);
    for (glm::vec2 corner : footprint(t.centre, t.size - glm::vec2(3.0f * kLeg), t.yaw))
      mesh.box(corner, glm::vec2(kLeg), t.yaw, spec.floor_y, spec.floor_y + t.height - kTop);
  }
  for (const Stair& st : spec.stairs) mesh.stair(st, spec.floor_y);
  for (const Partition& w : spec.partitions) mesh.partition(w, spec.floor_y, spec.ceiling_y);
  for (const Box& b : spec.hanging) mesh.hanging_box(b.centre, b.size, b.yaw, spec.ceiling_y - b.height, spec.ceiling_y);
  return mesh.finish();
}

Scan generate(const HouseSpec& spec) {
  Scan out;
  for (const RoomSpec& storey : spec.storeys) {
    const Scan part = generate(storey);
    const std::uint32_t base = std::uint32_t(out.vertices.size());
    out.vertices.insert(out.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const std::uint32_t i : part.indices) out.indices.push_back(base + i);
  }
  return out;
}

std::vector<glm::vec2> stair_footprint(const Stair& st) {
  const float run = float(st.steps - 1) * st.tread;
  return footprint(st.start + rotate({0.5f * run, 0.0f}, st.yaw), {run, st.width}, st.yaw);
}

bool inside_outline(const RoomSpec& spec, glm::vec2 p) { return inside_convex(spec.outline, p); }

float distance_to_walls(const RoomSpec& spec, glm::vec2 p) {
  float d = distance_to_polygon_edges(spec.outline, p);
  for (const Partition& w : spec.partitions) d = std::min(d, std::max(0.0f, distance_to_segment(p, w.a, w.b) - 0.5f * w.thickness));
  return d;
}

float ceiling_at(const RoomSpec& spec, glm::vec2 p) {
  float y = spec.ceiling_y;
  if (spec.pitch) {
    glm::vec2 lo = spec.outline.front(), hi = lo;
    for (glm::vec2 q : spec.outline) {
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
    // The distance from the ridge, 0 there and 1 at the eaves.
    const float t = spec.pitch->ridge_along_x ? std::fabs(p.y - 0.5f * (lo.y + hi.y)) / (0.5f * (hi.y - lo.y))
                                              : std::fabs(p.x - 0.5f * (lo.x + hi.x)) / (0.5f * (hi.x - lo.x));
    y = spec.ceiling_y - std::clamp(t, 0.0f, 1.0f) * (spec.ceiling_y - spec.pitch->eave_y);
  }
  for (const Box& b : spec.hanging)
    if (inside_convex(footprint(b.centre, b.size, b.yaw), p)) y = std::min(y, spec.ceiling_y - b.height);
  return y;
}

std::optional<float> furniture_top_at(const RoomSpec& spec, glm::vec2 p) {
  std::optional<float> top;
  for (const Box& b : spec.boxes)
    if (inside_convex(footprint(b.centre, b.size, b.yaw), p)) top = std::max(top.value_or(0.0f), b.height);
  for (const Table& t : spec.tables)
    if (inside_convex(footprint(t.centre, t.size, t.yaw), p)) top = std::max(top.value_or(0.0f), t.height);
  return top;
}

float distance_to_furniture(const RoomSpec& spec, glm::vec2 p) {
  float d = INFINITY;
  const auto consider = [&](const std::vector<glm::vec2>& f) {
    d = std::min(d, inside_convex(f, p) ? 0.0f : distance_to_polygon_edges(f, p));
  };
  for (const Box& b : spec.boxes) consider(footprint(b.centre, b.size, b.yaw));
  for (const Table& t : spec.tables) consider(footprint(t.centre, t.size, t.yaw));
  return d;
}

RoomSpec default_room() {
  RoomSpec r;
  r.name = "default";
  r.outline = rectangle(5.0f, 4.0f);
  r.ceiling_y = 2.6f;
  r.tables.push_back({{0.6f, 0.4f}, {1.4f, 0.8f}, 0.75f, 0.0f});
  r.boxes.push_back({{-1.3f, -1.4f}, {2.0f, 0.9f}, 0.45f, 0.0f});   // sofa along the back wall
  r.boxes.push_back({{2.15f, -1.5f}, {0.6f, 0.5f}, 2.0f, 0.0f});   // tall cabinet: reads as wall
  r.windows.push_back({1, 1.0f, 2.6f, 0.7f, 2.3f});                // in the +Z wall, 1.6 m tall
  r.holes.push_back({{-2.5f, 1.6f, 1.0f}, 0.25f});                  // a scan gap in the -X wall
  r.noise = 0.005f;
  r.seed = 7;
  return r;
}

RoomSpec large_triangle_room() {
  RoomSpec r = default_room();
  r.name = "large-triangles";
  r.cell = 0.0f;
  r.noise = 0.0f;
  r.holes.clear();
  return r;
}

RoomSpec rotated_room(float yaw_degrees) {
  RoomSpec r = default_room();
  r.name = "rotated-" + std::to_string(int(yaw_degrees));
  const float yaw = glm::radians(yaw_degrees);
  for (glm::vec2& p : r.outline) p = rotate(p, yaw);
  for (Box& b : r.boxes) {
    b.centre = rotate(b.centre, yaw);
    b.yaw += yaw;
  }
  for (Table& t : r.tables) {
    t.centre = rotate(t.centre, yaw);
    t.yaw += yaw;
  }
  for (Hole& h : r.holes) {
    const glm::vec2 c = rotate({h.centre.x, h.centre.z}, yaw);
    h.centre = {c.x, h.centre.y, c.y};
  }
  return r;
}

RoomSpec pentagon_room() {
  RoomSpec r;
  r.name = "pentagon";
  for (int i = 0; i < 5; ++i) {
    const float a = glm::radians(90.0f + 72.0f * float(i));
    r.outline.emplace_back(3.2f * std::cos(a), -3.2f * std::sin(a));  // counter-clockwise seen from +Y
  }
  r.ceiling_y = 2.8f;
  r.tables.push_back({{0.0f, 0.0f}, {1.0f, 1.0f}, 0.72f, glm::radians(20.0f)});
  r.noise = 0.004f;
  r.seed = 11;
  return r;
}

RoomSpec hall_room(float width, float depth) {
  RoomSpec r;
  r.name = "hall";
  r.outline = rectangle(width, depth);
  r.ceiling_y = 3.5f;
  r.cell = 0.1f;
  for (int i = 0; i < 4; ++i) {
    r.tables.push_back({{-width / 4.0f, -depth / 3.0f + float(i) * depth / 5.0f}, {2.0f, 0.9f}, 0.75f, 0.0f});
    r.boxes.push_back({{width / 4.0f, -depth / 3.0f + float(i) * depth / 5.0f}, {1.6f, 0.8f}, 1.1f, 0.0f});
  }
  r.windows.push_back({0, 2.0f, 6.0f, 1.0f, 2.5f});
  r.noise = 0.005f;
  r.seed = 3;
  return r;
}

RoomSpec thesis_room1() {
  RoomSpec r = default_room();
  r.name = "thesis-room1";
  r.outline = rectangle(6.0f, 7.0f);
  r.ceiling_y = 2.7f;
  r.boxes[1].centre = {2.65f, -3.0f};
  r.cell = 0.047f;  // about 78k vertices
  return r;
}

HouseSpec two_storey_house() {
  HouseSpec house;
  house.name = "house";
  RoomSpec ground;
  ground.outline = rectangle(7.0f, 5.0f);
  ground.ceiling_y = 2.5f;
  ground.boxes.push_back({{1.6f, 1.8f}, {2.0f, 0.9f}, 0.45f, 0.0f});  // sofa along the front wall
  ground.tables.push_back({{1.4f, -0.2f}, {1.4f, 0.8f}, 0.75f, 0.0f});
  ground.windows.push_back({1, 1.0f, 2.5f, 0.9f, 2.1f});
  // Along the back wall, up +X: 15 risers of 0.183 m, 3.64 m of run. The stairwell leaves 1.95 m of head room
  // over the third tread.
  ground.stairs.push_back({{-2.8f, -2.0f}, 0.0f, 0.9f, 0.26f, 2.75f, 15});
  const Rect well{{-2.3f, -2.5f}, {0.84f, -1.5f}};
  ground.ceiling_openings.push_back(well);
  ground.noise = 0.005f;
  ground.seed = 17;
  RoomSpec upper;
  upper.outline = ground.outline;
  upper.floor_y = 2.75f;
  upper.ceiling_y = 5.15f;
  upper.floor_openings.push_back(well);
  upper.boxes.push_back({{1.9f, 1.2f}, {1.6f, 2.0f}, 0.5f, 0.0f});   // a bed
  upper.boxes.push_back({{-2.9f, 1.9f}, {0.8f, 0.5f}, 1.9f, 0.0f});  // a wardrobe: reads as wall
  upper.noise = 0.005f;
  upper.seed = 19;
  house.storeys = {ground, upper};
  for (RoomSpec& storey : house.storeys) storey.name = house.name;
  return house;
}

std::optional<HouseSpec> builtin_house(const std::string& name) {
  if (name == "house") return two_storey_house();
  return std::nullopt;
}

std::vector<std::string> builtin_house_names() { return {"house"}; }

RoomSpec three_room_flat() {
  RoomSpec r;
  r.name = "flat";
  r.outline = rectangle(9.0f, 6.0f);
  r.ceiling_y = 2.5f;
  // From the bedroom's corner (0.5, -3) down to the bathroom's (0.5, 3): doorways into the bedroom and the
  // bathroom; then the wall between those two, from (0.5, 0) to (4.5, 0), without a door.
  r.partitions.push_back({{0.5f, -3.0f}, {0.5f, 3.0f}, 0.1f, {{0.8f, 1.7f, 2.0f}, {4.4f, 5.3f, 2.0f}}});
  r.partitions.push_back({{0.5f, 0.0f}, {4.5f, 0.0f}, 0.1f, {}});
  r.boxes.push_back({{-2.0f, 2.4f}, {2.2f, 0.9f}, 0.45f, 0.0f});   // sofa
  r.tables.push_back({{-2.0f, -0.5f}, {1.4f, 0.8f}, 0.75f, 0.0f});
  r.boxes.push_back({{3.4f, -1.9f}, {1.6f, 2.0f}, 0.5f, 0.0f});    // bed
  r.boxes.push_back({{3.6f, 2.5f}, {1.7f, 0.75f}, 0.55f, 0.0f});   // bathtub
  r.windows.push_back({0, 1.0f, 3.0f, 0.9f, 2.1f});
  r.noise = 0.005f;
  r.seed = 23;
  return r;
}

RoomSpec pitched_loft() {
  RoomSpec r;
  r.name = "loft";
  r.outline = rectangle(6.0f, 5.0f);
  r.ceiling_y = 3.2f;
  r.pitch = Pitch{1.2f, true};
  r.boxes.push_back({{-1.5f, 0.0f}, {2.0f, 1.6f}, 0.5f, 0.0f});  // a bed under the ridge
  r.tables.push_back({{1.8f, -0.2f}, {1.2f, 0.7f}, 0.75f, 0.0f});
  r.noise = 0.005f;
  r.seed = 31;
  return r;
}

RoomSpec soffit_room() {
  RoomSpec r = default_room();
  r.name = "soffit";
  r.hanging.push_back({{0.0f, -1.4f}, {5.0f, 1.2f}, 0.35f, 0.0f});  // along the -Z wall, 2.25 m above the floor
  return r;
}

RoomSpec beam_room() {
  RoomSpec r = default_room();
  r.name = "beam";
  r.hanging.push_back({{0.3f, 0.0f}, {0.25f, 4.0f}, 0.3f, 0.0f});  // across the room, from wall to wall
  return r;
}

std::vector<Rect> three_room_flat_rooms() {
  return {{{-4.5f, -3.0f}, {0.45f, 3.0f}}, {{0.55f, -3.0f}, {4.5f, -0.05f}}, {{0.55f, 0.05f}, {4.5f, 3.0f}}};
}

std::optional<RoomSpec> builtin(const std::string& name) {
  if (name == "default") return default_room();
  if (name == "large-triangles") return large_triangle_room();
  if (name == "rotated") return rotated_room(30.0f);
  if (name == "pentagon") return pentagon_room();
  if (name == "hall") return hall_room();
  if (name == "thesis-room1") return thesis_room1();
  if (name == "flat") return three_room_flat();
  if (name == "loft") return pitched_loft();
  if (name == "soffit") return soffit_room();
  if (name == "beam") return beam_room();
  return std::nullopt;
}

bool is_builtin_source(const std::string& source) { return source.rfind(kSourcePrefix, 0) == 0; }

Scan generate_builtin_source(const std::string& source) {
  const std::string name = is_builtin_source(source) ? source.substr(std::string(kSourcePrefix).size()) : source;
  if (const auto spec = builtin(name)) return generate(*spec);
  if (const auto house = builtin_house(name)) return generate(*house);
  std::string names;
  for (const auto& list : {builtin_names(), builtin_house_names()})
    for (const std::string& n : list) names += (names.empty() ? "" : ", ") + n;
  throw Error(ErrorCode::BadParameter, "no built-in room '" + name + "' (there are: " + names + ")");
}

std::vector<std::string> builtin_names() {
  return {"default", "large-triangles", "rotated", "pentagon", "hall", "thesis-room1", "flat", "loft", "soffit", "beam"};
}

}  // namespace roomsense::synth
