// What a headless session answers where a headset with a display would render: no swapchain formats, so no
// swapchains; frames whose layers are accepted and ignored; the system's limits; and the spec's error codes
// for enum values the runtime does not support.
#include "xr_harness.h"

#include <gtest/gtest.h>

namespace {

using namespace simtest;

TEST(SimHeadless, NoSwapchainFormatsAndNoSwapchains) {
  App app;
  uint32_t count = 99;
  ASSERT_EQ(xrEnumerateSwapchainFormats(app.session, 0, &count, nullptr), XR_SUCCESS);
  EXPECT_EQ(count, 0u);
  int64_t formats[4] = {};
  count = 99;
  ASSERT_EQ(xrEnumerateSwapchainFormats(app.session, 4, &count, formats), XR_SUCCESS);
  EXPECT_EQ(count, 0u);
  EXPECT_EQ(xrEnumerateSwapchainFormats(app.session, 0, nullptr, nullptr), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(xrEnumerateSwapchainFormats(reinterpret_cast<XrSession>(uintptr_t{0x1234}), 0, &count, nullptr), XR_ERROR_HANDLE_INVALID);

  XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
  info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT;
  info.format = 43;  // any format: none is supported
  info.sampleCount = info.faceCount = info.arraySize = info.mipCount = 1;
  info.width = info.height = 256;
  XrSwapchain swapchain = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateSwapchain(app.session, &info, &swapchain), XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
  EXPECT_EQ(swapchain, XR_NULL_HANDLE);
  info.type = XR_TYPE_SESSION_CREATE_INFO;
  EXPECT_EQ(xrCreateSwapchain(app.session, &info, &swapchain), XR_ERROR_VALIDATION_FAILURE);

  // Every swapchain handle is unknown.
  const auto bogus = reinterpret_cast<XrSwapchain>(uintptr_t{0x1234});
  uint32_t index = 0;
  EXPECT_EQ(xrEnumerateSwapchainImages(bogus, 0, &count, nullptr), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(xrAcquireSwapchainImage(bogus, nullptr, &index), XR_ERROR_HANDLE_INVALID);
  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
  wait.timeout = XR_INFINITE_DURATION;
  EXPECT_EQ(xrWaitSwapchainImage(bogus, &wait), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(xrReleaseSwapchainImage(bogus, nullptr), XR_ERROR_HANDLE_INVALID);
  EXPECT_EQ(xrDestroySwapchain(bogus), XR_ERROR_HANDLE_INVALID);
}

TEST(SimHeadless, EndFrameIgnoresLayers) {
  App app;
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  ASSERT_EQ(xrBeginSession(app.session, &begin), XR_SUCCESS);

  // What an app (the CTS among them) submits headless: a projection layer with no swapchain to show.
  XrCompositionLayerProjection projection{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  projection.space = app.local;
  XrCompositionLayerQuad quad{XR_TYPE_COMPOSITION_LAYER_QUAD};
  quad.space = app.local;
  const std::vector<const XrCompositionLayerBaseHeader*> layers{reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection),
                                                                reinterpret_cast<const XrCompositionLayerBaseHeader*>(&quad)};
  const std::vector<const XrCompositionLayerBaseHeader*> with_null{layers[0], nullptr};
  const std::vector<const XrCompositionLayerBaseHeader*> too_many(17, layers[0]);  // maxLayerCount is 16
  XrSessionBeginInfo wrong_type{XR_TYPE_SESSION_BEGIN_INFO};
  const std::vector<const XrCompositionLayerBaseHeader*> not_a_layer{reinterpret_cast<const XrCompositionLayerBaseHeader*>(&wrong_type)};

  XrFrameState frame{XR_TYPE_FRAME_STATE};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  for (const auto* bad : {&with_null, &too_many, &not_a_layer}) {
    ASSERT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(app.session, nullptr), XR_SUCCESS);
    end.displayTime = frame.predictedDisplayTime;
    end.layerCount = static_cast<uint32_t>(bad->size());
    end.layers = bad->data();
    EXPECT_EQ(xrEndFrame(app.session, &end), bad == &too_many ? XR_ERROR_LAYER_LIMIT_EXCEEDED : XR_ERROR_LAYER_INVALID);
    // The frame is still open: end it properly.
    end.layerCount = static_cast<uint32_t>(layers.size());
    end.layers = layers.data();
    ASSERT_EQ(xrEndFrame(app.session, &end), XR_SUCCESS);
  }
  const std::vector<const XrCompositionLayerBaseHeader*> sixteen(16, layers[0]);
  ASSERT_EQ(xrWaitFrame(app.session, nullptr, &frame), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(app.session, nullptr), XR_SUCCESS);
  end.displayTime = frame.predictedDisplayTime;
  end.layerCount = 16;
  end.layers = sixteen.data();
  EXPECT_EQ(xrEndFrame(app.session, &end), XR_SUCCESS);
  EXPECT_EQ(xrEndFrame(app.session, &end), XR_ERROR_CALL_ORDER_INVALID);  // no frame begun
}

TEST(SimHeadless, SystemProperties) {
  App app;
  XrSystemProperties properties{XR_TYPE_SYSTEM_PROPERTIES};
  ASSERT_EQ(xrGetSystemProperties(app.instance, app.system, &properties), XR_SUCCESS);
  EXPECT_GE(properties.graphicsProperties.maxLayerCount, 16u);  // the spec's minimum
  uint32_t count = 0;
  ASSERT_EQ(xrEnumerateViewConfigurationViews(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &count, nullptr),
            XR_SUCCESS);
  std::vector<XrViewConfigurationView> views(count, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
  ASSERT_EQ(xrEnumerateViewConfigurationViews(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, count, &count,
                                              views.data()),
            XR_SUCCESS);
  for (const auto& view : views) {
    EXPECT_GE(properties.graphicsProperties.maxSwapchainImageWidth, view.maxImageRectWidth);
    EXPECT_GE(properties.graphicsProperties.maxSwapchainImageHeight, view.maxImageRectHeight);
  }
  EXPECT_EQ(properties.trackingProperties.positionTracking, XR_TRUE);
}

TEST(SimHeadless, UnsupportedEnumValues) {
  App app;
  XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
  system.formFactor = XR_FORM_FACTOR_MAX_ENUM;
  XrSystemId id = XR_NULL_SYSTEM_ID;
  EXPECT_EQ(xrGetSystem(app.instance, &system, &id), XR_ERROR_FORM_FACTOR_UNSUPPORTED);

  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.poseInReferenceSpace.orientation.w = 1;
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_MAX_ENUM;
  XrSpace created = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(app.session, &space, &created), XR_ERROR_REFERENCE_SPACE_UNSUPPORTED);
  EXPECT_EQ(created, XR_NULL_HANDLE);

  // A view configuration of an extension that is not enabled is not a valid value; mono is valid but unsupported.
  XrViewConfigurationProperties properties{XR_TYPE_VIEW_CONFIGURATION_PROPERTIES};
  EXPECT_EQ(xrGetViewConfigurationProperties(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_QUAD_VARJO, &properties),
            XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(xrGetViewConfigurationProperties(app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO, &properties),
            XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_SECONDARY_MONO_FIRST_PERSON_OBSERVER_MSFT;
  EXPECT_EQ(xrBeginSession(app.session, &begin), XR_ERROR_VALIDATION_FAILURE);
  XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO, nullptr, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_QUAD_VARJO, app.now(), app.local};
  XrViewState state{XR_TYPE_VIEW_STATE};
  uint32_t count = 0;
  EXPECT_EQ(xrLocateViews(app.session, &locate, &state, 0, &count, nullptr), XR_ERROR_VALIDATION_FAILURE);
  locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO;
  EXPECT_EQ(xrLocateViews(app.session, &locate, &state, 0, &count, nullptr), XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
}

}  // namespace
