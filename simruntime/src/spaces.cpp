// Reference spaces and xrLocateSpace. Nothing moves: every location is valid and tracked.
#include "spaces.h"

#include "functions.h"
#include "validate.h"

namespace roomsense::sim {

bool is_reference_space_type(XrReferenceSpaceType type) {
  return type == XR_REFERENCE_SPACE_TYPE_VIEW || type == XR_REFERENCE_SPACE_TYPE_LOCAL || type == XR_REFERENCE_SPACE_TYPE_STAGE ||
         type == XR_REFERENCE_SPACE_TYPE_UNBOUNDED_MSFT || type == XR_REFERENCE_SPACE_TYPE_COMBINED_EYE_VARJO;
}

bool is_supported_reference_space(XrReferenceSpaceType type) {
  return type == XR_REFERENCE_SPACE_TYPE_VIEW || type == XR_REFERENCE_SPACE_TYPE_LOCAL || type == XR_REFERENCE_SPACE_TYPE_STAGE;
}

Rigid reference_in_world(const Config& config, XrReferenceSpaceType type) {
  return type == XR_REFERENCE_SPACE_TYPE_VIEW ? to_rigid(config.head_pose) : Rigid{};
}

bool space_in_world(const SpaceState& space, Rigid& out) {
  Runtime& rt = runtime();
  const SessionState* session = Runtime::find(rt.sessions, space.session);
  const InstanceState* instance = session ? Runtime::find(rt.instances, session->instance) : nullptr;
  if (instance == nullptr) return false;
  if (space.action != 0) return false;  // action spaces are never located
  out = reference_in_world(instance->config, space.type) * to_rigid(space.pose_in_reference);
  return true;
}

XrResult XRAPI_CALL xrEnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* countOutput, XrReferenceSpaceType* spaces) {
  return guarded("xrEnumerateReferenceSpaces", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    return two_call(capacity, countOutput, spaces,
                    std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                                      XR_REFERENCE_SPACE_TYPE_STAGE});
  });
}

XrResult XRAPI_CALL xrCreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* createInfo, XrSpace* space) {
  return guarded("xrCreateReferenceSpace", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_REFERENCE_SPACE_CREATE_INFO) || space == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    // Any other value, defined or not, is unsupported (the CTS asks for this code for ..._MAX_ENUM too).
    if (!is_supported_reference_space(createInfo->referenceSpaceType)) return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    if (!is_valid_pose(createInfo->poseInReferenceSpace)) return XR_ERROR_POSE_INVALID;
    auto state = std::make_unique<SpaceState>();
    state->session = id_of(session);
    state->type = createInfo->referenceSpaceType;
    state->pose_in_reference = createInfo->poseInReferenceSpace;
    const std::uint64_t id = runtime().new_id();
    runtime().spaces.emplace(id, std::move(state));
    *space = handle_of<XrSpace>(id);
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrGetReferenceSpaceBoundsRect(XrSession session, XrReferenceSpaceType type, XrExtent2Df* bounds) {
  return guarded("xrGetReferenceSpaceBoundsRect", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    if (runtime().session(session) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (bounds == nullptr || !is_reference_space_type(type)) return XR_ERROR_VALIDATION_FAILURE;
    if (!is_supported_reference_space(type)) return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    // No play area is configured: the room file's frame need not be centred on a stage.
    *bounds = {0.0f, 0.0f};
    return XR_SPACE_BOUNDS_UNAVAILABLE;
  });
}

XrResult XRAPI_CALL xrLocateSpace(XrSpace space, XrSpace baseSpace, XrTime time, XrSpaceLocation* location) {
  return guarded("xrLocateSpace", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    const SpaceState* target = runtime().space(space);
    const SpaceState* base = runtime().space(baseSpace);
    if (target == nullptr || base == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (target->session != base->session) return XR_ERROR_VALIDATION_FAILURE;
    if (!has_type(location, XR_TYPE_SPACE_LOCATION)) return XR_ERROR_VALIDATION_FAILURE;
    if (time <= 0) return XR_ERROR_TIME_INVALID;
    if (target->action != 0 || base->action != 0) {
      // An action space follows a device, and there is none: not located.
      location->pose = {{0, 0, 0, 1}, {0, 0, 0}};
      location->locationFlags = 0;
      if (auto* velocity = find_next<XrSpaceVelocity>(location->next, XR_TYPE_SPACE_VELOCITY)) velocity->velocityFlags = 0;
      return XR_SUCCESS;
    }
    Rigid target_world, base_world;
    if (!space_in_world(*target, target_world) || !space_in_world(*base, base_world)) return XR_ERROR_HANDLE_INVALID;
    location->pose = to_pose(base_world.inverse() * target_world);
    location->locationFlags = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
                              XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;
    if (auto* velocity = find_next<XrSpaceVelocity>(location->next, XR_TYPE_SPACE_VELOCITY)) {
      velocity->linearVelocity = {0, 0, 0};
      velocity->angularVelocity = {0, 0, 0};
      velocity->velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT;
    }
    return XR_SUCCESS;
  });
}

XrResult XRAPI_CALL xrDestroySpace(XrSpace space) {
  return guarded("xrDestroySpace", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    return runtime().spaces.erase(id_of(space)) == 1 ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
  });
}

}  // namespace roomsense::sim
