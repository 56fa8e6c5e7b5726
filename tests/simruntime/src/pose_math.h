// XrPosef <-> glm, and the few rigid-transform operations the runtime needs.
#pragma once
#include <openxr/openxr.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace roomsense::sim {

struct Rigid {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 translation{0.0};

  glm::dvec3 apply(const glm::dvec3& p) const { return rotation * p + translation; }
  Rigid operator*(const Rigid& rhs) const { return {rotation * rhs.rotation, rotation * rhs.translation + translation}; }
  Rigid inverse() const {
    const glm::dquat inv = glm::conjugate(rotation);
    return {inv, inv * -translation};
  }
};

inline Rigid to_rigid(const XrPosef& p) {
  return {glm::normalize(glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z)),
          {p.position.x, p.position.y, p.position.z}};
}

inline XrPosef to_pose(const Rigid& r) {
  XrPosef p{};
  p.orientation = {static_cast<float>(r.rotation.x), static_cast<float>(r.rotation.y), static_cast<float>(r.rotation.z),
                   static_cast<float>(r.rotation.w)};
  p.position = {static_cast<float>(r.translation.x), static_cast<float>(r.translation.y), static_cast<float>(r.translation.z)};
  return p;
}

// The spec requires a unit quaternion in every pose an application passes in (XR_ERROR_POSE_INVALID otherwise).
inline bool is_valid_pose(const XrPosef& p) {
  const double n = std::sqrt(double(p.orientation.x) * p.orientation.x + double(p.orientation.y) * p.orientation.y +
                             double(p.orientation.z) * p.orientation.z + double(p.orientation.w) * p.orientation.w);
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) && std::fabs(n - 1.0) < 1e-3;
}

}  // namespace roomsense::sim
