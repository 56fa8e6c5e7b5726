// The shared helpers: the two-call idiom from both sides, rigid transforms, the entry-point guard.
#include "roomsense/xr/guard.h"
#include "roomsense/xr/rigid.h"
#include "roomsense/xr/two_call.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace roomsense::xr {
namespace {

TEST(TwoCall, ServesCountThenItemsAndRefusesShortCapacity) {
  const std::vector<int> items{4, 5, 6};
  std::uint32_t count = 0;
  EXPECT_EQ(two_call<int>(0, &count, nullptr, items), XR_SUCCESS);
  EXPECT_EQ(count, 3u);
  int out[3] = {};
  EXPECT_EQ(two_call<int>(2, &count, out, items), XR_ERROR_SIZE_INSUFFICIENT);
  EXPECT_EQ(two_call<int>(3, &count, out, items), XR_SUCCESS);
  EXPECT_EQ(out[2], 6);
  EXPECT_EQ(two_call<int>(3, nullptr, out, items), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(two_call<int>(3, &count, nullptr, items), XR_ERROR_VALIDATION_FAILURE);
}

TEST(TwoCall, ReadsWhatARuntimeServesAndRefusesAbsurdCounts) {
  const std::vector<int> served{1, 2, 3, 4};
  auto call = [&](std::uint32_t capacity, std::uint32_t* count, int* out) { return two_call(capacity, count, out, served); };
  EXPECT_EQ(read_two_call<int>("serve", call, 100), served);
  EXPECT_THROW(read_two_call<int>("serve", call, 3), std::runtime_error);
  auto failing = [](std::uint32_t, std::uint32_t*, int*) { return XR_ERROR_RUNTIME_FAILURE; };
  try {
    read_two_call<int>("xrGetThingsEXT", failing, 10);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("xrGetThingsEXT failed"), std::string::npos);
  }
}

TEST(Rigid, PoseRoundTripAndInverse) {
  const XrPosef pose{{0.0f, 0.38268343f, 0.0f, 0.92387953f}, {1.0f, 2.0f, -3.0f}};  // 45 degrees about +Y
  EXPECT_TRUE(is_valid_pose(pose));
  EXPECT_TRUE(is_yaw_only(pose));
  const Rigid r = to_rigid(pose);
  const glm::dvec3 p(0.5, -1.0, 2.0);
  const glm::dvec3 back = r.inverse().apply(r.apply(p));
  EXPECT_NEAR(back.x, p.x, 1e-9);
  EXPECT_NEAR(back.z, p.z, 1e-9);
  const XrPosef again = to_pose(r);
  EXPECT_FLOAT_EQ(again.position.z, -3.0f);
  EXPECT_FALSE(is_valid_pose(XrPosef{{0, 0, 0, 2}, {0, 0, 0}}));
  EXPECT_FALSE(is_yaw_only(XrPosef{{0.38268343f, 0, 0, 0.92387953f}, {0, 0, 0}}));
}

TEST(Guard, TurnsExceptionsIntoResultsAndReportsOnce) {
  std::vector<std::string> lines;
  auto report = [&](const std::string& l) { lines.push_back(l); };
  EXPECT_EQ(guarded("f", report, [] { return XR_SUCCESS; }), XR_SUCCESS);
  EXPECT_EQ(guarded("f", report, []() -> XrResult { throw std::runtime_error("boom"); }), XR_ERROR_RUNTIME_FAILURE);
  EXPECT_EQ(guarded("g", report, []() -> XrResult { throw std::bad_alloc(); }), XR_ERROR_OUT_OF_MEMORY);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "f: boom");
}

}  // namespace
}  // namespace roomsense::xr
