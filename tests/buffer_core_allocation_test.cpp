// A control loop looks up by FrameHandle into a TransformStamped it keeps, so that a lookup in
// a real-time thread never waits on the heap: once the result's strings hold their names and
// the thread has looked up once, such lookups and canTransform by handle allocate nothing,
// whichever way the buffer answers (by the frames' root paths, or by the walk where an edge
// has changed parent). This program counts every allocation made through operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "support/buffer_core_helpers.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void* allocate(std::size_t size, std::size_t alignment = 0) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  if (size == 0) size = 1;
  void* const memory =
      alignment == 0
          ? std::malloc(size)
          : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
  if (!memory) throw std::bad_alloc();
  return memory;
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete(void* memory, std::align_val_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::align_val_t) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t, std::align_val_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t, std::align_val_t) noexcept { std::free(memory); }

namespace lcmtf {
namespace {

using lcmtf_test::kEpoch;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;

constexpr Duration kPeriod = std::chrono::milliseconds(10);
constexpr int kSamples = 200;

// Names longer than a string holds in place, so that a result that allocated would show.
const char* const kMap = "map_of_the_whole_building";
const char* const kOdom = "odometry_frame_of_the_base";
const char* const kBase = "base_link_of_the_mobile_robot";
const char* const kShoulder = "left_arm_shoulder_pan_link";
const char* const kForearm = "left_arm_forearm_roll_link";
const char* const kCamera = "left_forearm_camera_optical_frame";
const char* const kGripper = "left_gripper_palm_link_frame";

// A pose that moves with `x`, as a moving edge's samples do.
Transform moving(double x) {
  return pose(Eigen::Vector3d(x, 0.1, 0.2), 0.01 * x, Eigen::Vector3d::UnitZ());
}

// map -> odom -> base -> shoulder -> forearm -> camera, with a static link and a static camera,
// and a gripper that moves from the shoulder to the forearm halfway through its history when
// `gripper_changes_parent`.
void fill(BufferCore& buffer, bool gripper_changes_parent) {
  putStatic(buffer, kBase, kShoulder, moving(0.3));
  putStatic(buffer, kForearm, kCamera, moving(0.05));
  for (int k = 0; k < kSamples; ++k) {
    const TimePoint t = kEpoch + k * kPeriod;
    const double x = 0.001 * k;
    put(buffer, kMap, kOdom, t, moving(x));
    put(buffer, kOdom, kBase, t + std::chrono::milliseconds(3), moving(2 * x));
    put(buffer, kShoulder, kForearm, t + std::chrono::milliseconds(7), moving(3 * x));
    const char* gripper_parent = gripper_changes_parent && k >= kSamples / 2 ? kForearm : kShoulder;
    put(buffer, gripper_parent, kGripper, t + std::chrono::milliseconds(5), moving(4 * x));
  }
}

struct Query {
  FrameHandle target;
  FrameHandle source;
  TimePoint time;
};

// Pairs of frames at times inside every edge's history, and at the latest time.
std::vector<Query> queries(const BufferCore& buffer) {
  std::vector<FrameHandle> frames;
  for (const char* name : {kMap, kOdom, kBase, kShoulder, kForearm, kCamera, kGripper}) {
    frames.push_back(buffer.findFrame(name));
  }
  std::vector<Query> out;
  for (std::size_t a = 0; a < frames.size(); ++a) {
    for (std::size_t b = 0; b < frames.size(); ++b) {
      if (a == b) continue;
      out.push_back({frames[a], frames[b], kLatestTime});
      for (int k = 2; k < kSamples - 2; k += 37) {
        out.push_back(
            {frames[a], frames[b], kEpoch + k * kPeriod + std::chrono::microseconds(4'321)});
      }
    }
  }
  return out;
}

// Every query once to warm up, then every query again, counting allocations.
long allocationsOfLookups(const BufferCore& buffer, const std::vector<Query>& all) {
  TransformStamped result;
  std::string why;
  for (const Query& q : all) {
    buffer.lookupTransform(q.target, q.source, q.time, result);
    EXPECT_TRUE(buffer.canTransform(q.target, q.source, q.time, &why)) << why;
  }
  allocations = 0;
  counting = true;
  double sum = 0.0;
  for (int round = 0; round < 3; ++round) {
    for (const Query& q : all) {
      buffer.lookupTransform(q.target, q.source, q.time, result);
      sum += result.transform.translation.x();
      sum += buffer.canTransform(q.target, q.source, q.time) ? 1.0 : 0.0;
    }
  }
  counting = false;
  EXPECT_NE(sum, 0.0);
  return allocations.load();
}

TEST(BufferCoreAllocation, CountingSeesAnAllocation) {
  allocations = 0;
  counting = true;
  const std::string long_name(kCamera);
  counting = false;
  EXPECT_EQ(long_name, kCamera);
  EXPECT_GE(allocations.load(), 1);
}

TEST(BufferCoreAllocation, LookupsByHandleIntoAKeptResultAllocateNothingOnceWarm) {
  BufferCore buffer;
  fill(buffer, false);
  const std::vector<Query> all = queries(buffer);
  ASSERT_GT(all.size(), 100u);
  EXPECT_EQ(allocationsOfLookups(buffer, all), 0);
}

TEST(BufferCoreAllocation, LookupsTheWalkAnswersAllocateNothingOnceWarm) {
  BufferCore buffer;
  fill(buffer, true);
  const std::vector<Query> all = queries(buffer);
  EXPECT_EQ(allocationsOfLookups(buffer, all), 0);
}

TEST(BufferCoreAllocation, LookupsByNameAllocateTheResultsNames) {
  BufferCore buffer;
  fill(buffer, false);
  const std::string map = kMap;
  const std::string camera = kCamera;
  buffer.lookupTransform(map, camera, kLatestTime);
  allocations = 0;
  counting = true;
  const TransformStamped result = buffer.lookupTransform(map, camera, kLatestTime);
  counting = false;
  EXPECT_EQ(result.child_frame, kCamera);
  // The result's two names, which a string this long cannot hold in place; nothing else.
  EXPECT_EQ(allocations.load(), 2);
}

}  // namespace
}  // namespace lcmtf
