// The session state machine, its events, and the headless frame loop.
#include "xr_harness.h"

#include <gtest/gtest.h>

namespace {

using namespace simtest;

std::vector<XrSessionState> poll_states(App& app) {
  std::vector<XrSessionState> states;
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(app.instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
      EXPECT_EQ(changed.session, app.session);
      states.push_back(changed.state);
    }
    event = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  return states;
}

TEST(SimSession, StateMachineAndFrames) {
  App app;
  using V = std::vector<XrSessionState>;
  EXPECT_EQ(poll_states(app), (V{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY}));
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  EXPECT_EQ(xrPollEvent(app.instance, &event), XR_EVENT_UNAVAILABLE);

  XrFrameState frame{XR_TYPE_FRAME_STATE};
  EXPECT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(xrEndSession(app.session), XR_ERROR_SESSION_NOT_RUNNING);
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO;
  EXPECT_EQ(xrBeginSession(app.session, &begin), XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  ASSERT_EQ(xrBeginSession(app.session, &begin), XR_SUCCESS);
  EXPECT_EQ(xrBeginSession(app.session, &begin), XR_ERROR_SESSION_RUNNING);
  EXPECT_EQ(poll_states(app), (V{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED}));
  EXPECT_EQ(xrEndSession(app.session), XR_ERROR_SESSION_NOT_STOPPING);

  EXPECT_EQ(xrBeginFrame(app.session, nullptr), XR_ERROR_CALL_ORDER_INVALID);
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  XrTime previous = 0;
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_SUCCESS);
    EXPECT_GT(frame.predictedDisplayTime, previous);
    EXPECT_EQ(frame.shouldRender, XR_FALSE);
    previous = frame.predictedDisplayTime;
    ASSERT_EQ(xrBeginFrame(app.session, nullptr), XR_SUCCESS);
    end.displayTime = 0;
    EXPECT_EQ(xrEndFrame(app.session, &end), XR_ERROR_TIME_INVALID);
    end.displayTime = frame.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_ADDITIVE;
    EXPECT_EQ(xrEndFrame(app.session, &end), XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED);
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ASSERT_EQ(xrEndFrame(app.session, &end), XR_SUCCESS);
  }
  EXPECT_EQ(xrEndFrame(app.session, &end), XR_ERROR_CALL_ORDER_INVALID);
  // Two begins after two waits: the second discards the first frame.
  ASSERT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_SUCCESS);
  ASSERT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_SUCCESS);
  EXPECT_EQ(xrBeginFrame(app.session, nullptr), XR_SUCCESS);
  EXPECT_EQ(xrBeginFrame(app.session, nullptr), XR_FRAME_DISCARDED);
  end.displayTime = frame.predictedDisplayTime;
  EXPECT_EQ(xrEndFrame(app.session, &end), XR_SUCCESS);

  XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO, nullptr, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, frame.predictedDisplayTime, app.local};
  XrViewState view_state{XR_TYPE_VIEW_STATE};
  std::vector<XrView> views(2, {XR_TYPE_VIEW});
  uint32_t count = 0;
  ASSERT_EQ(xrLocateViews(app.session, &locate, &view_state, 2, &count, views.data()), XR_SUCCESS);
  EXPECT_NEAR(views[0].pose.position.y, 1.6f, 1e-6);  // default head pose
  EXPECT_NEAR(views[1].pose.position.x - views[0].pose.position.x, 0.064f, 1e-6);

  ASSERT_EQ(xrRequestExitSession(app.session), XR_SUCCESS);
  EXPECT_EQ(poll_states(app), (V{XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_STOPPING}));
  ASSERT_EQ(xrEndSession(app.session), XR_SUCCESS);
  EXPECT_EQ(poll_states(app), (V{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
  EXPECT_EQ(xrDestroySession(app.session), XR_SUCCESS);
  EXPECT_EQ(xrDestroySession(app.session), XR_ERROR_HANDLE_INVALID);
  app.session = XR_NULL_HANDLE;
}

}  // namespace
