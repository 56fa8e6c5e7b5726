// Rigid transforms between OpenXR poses and glm (computed in double), and the checks the spec puts on a pose.
#pragma once
#include <openxr/openxr.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace roomsense::xr {

struct Rigid {
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 translation{0.0};

  glm::dvec3 apply(const glm::dvec3& p) const { return rotation * p + translation; }
  Rigid operator*(const Rigid& rhs) const { return {rotation * rhs.rotation, rotation * rhs.translation + translation}; }
  Rigid inverse() const {
    const glm::dquat inv = glm::conjugate(rotation);
    return {inv, inv * -translation};
  }
  bool identity() const { return rotation == glm::dquat(1.0, 0.0, 0.0, 0.0) && translation == glm::dvec3(0.0); }
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

inline glm::vec3 vec3_of(const XrVector3f& v) { return {v.x, v.y, v.z}; }
inline XrVector3f xr_vector(const glm::vec3& v) { return {v.x, v.y, v.z}; }
inline XrQuaternionf xr_quaternion(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

// A unit quaternion and a finite position, as the spec requires of every pose an application passes in
// (XR_ERROR_POSE_INVALID otherwise).
inline bool is_valid_pose(const XrPosef& p) {
  const double n = std::sqrt(double(p.orientation.x) * p.orientation.x + double(p.orientation.y) * p.orientation.y +
                             double(p.orientation.z) * p.orientation.z + double(p.orientation.w) * p.orientation.w);
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) && std::fabs(n - 1.0) < 1e-3;
}

// True when the pose keeps +Y up (a yaw-only rotation): a gravity-aligned frame stays gravity-aligned.
inline bool is_yaw_only(const XrPosef& p) {
  const glm::dvec3 up = to_rigid(p).rotation * glm::dvec3(0.0, 1.0, 0.0);
  return up.y > 1.0 - 1e-4;
}

}  // namespace roomsense::xr
