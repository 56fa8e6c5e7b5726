// xrCreateActionSpace: a space that follows a pose action. With no device the action is never active, so
// these spaces are never located (xrLocateSpace reports no flags); they are destroyed with xrDestroySpace.
#include "action_paths.h"
#include "functions.h"
#include "pose_math.h"
#include "runtime.h"
#include "validate.h"

namespace roomsense::sim {

XrResult XRAPI_CALL xrCreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* createInfo, XrSpace* space) {
  return guarded("xrCreateActionSpace", [&]() -> XrResult {
    std::lock_guard lock(runtime().mutex);
    Runtime& rt = runtime();
    const SessionState* state = rt.session(session);
    if (state == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(createInfo, XR_TYPE_ACTION_SPACE_CREATE_INFO) || space == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const ActionState* action = Runtime::find(rt.input.actions, id_of(createInfo->action));
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->instance != state->instance) return XR_ERROR_VALIDATION_FAILURE;
    if (action->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    const InstanceState& owner = *Runtime::find(rt.instances, state->instance);
    if (XrResult r = check_query_subaction_path(owner, action->subaction_paths, createInfo->subactionPath); r != XR_SUCCESS) return r;
    if (!is_valid_pose(createInfo->poseInActionSpace)) return XR_ERROR_POSE_INVALID;
    auto created = std::make_unique<SpaceState>();
    created->session = id_of(session);
    created->action = id_of(createInfo->action);
    created->pose_in_reference = createInfo->poseInActionSpace;
    const std::uint64_t id = rt.new_id();
    rt.spaces.emplace(id, std::move(created));
    *space = handle_of<XrSpace>(id);
    return XR_SUCCESS;
  });
}

}  // namespace roomsense::sim
