// How much of a thread's stack each kind of lookup takes, since a real-time thread often runs on
// a small stack of its own. Each lookup runs on a new thread whose stack was painted beforehand:
// its own bytes are those from where the thread called it down to the deepest one overwritten.
#include <gtest/gtest.h>
#include <pthread.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/exceptions.hpp"
#include "support/test_scale.hpp"

namespace lcmtf {
namespace {

// What the README promises a real-time thread's stack must leave a lookup, in an optimized build;
// unoptimized and sanitized builds take several times more.
constexpr std::size_t kLookupStackBound = 32 * 1024;
// canTransform asks for no value, so it keeps no room for samples: the README gives 3.3 KiB.
constexpr std::size_t kCanTransformStackBound = 8 * 1024;
constexpr std::size_t kSlowBuildFactor = lcmtf_test::kWorkDivisor > 1 ? 4 : 1;
constexpr std::size_t kBuildBound = kLookupStackBound * kSlowBuildFactor;
constexpr std::size_t kThreadStack = 1024 * 1024;
constexpr unsigned char kPaint = 0xA5;
constexpr int kChain = 100;  // frames f0 .. f99, each below the one before
constexpr std::int64_t kFirstStamp = 1'000'000;
constexpr std::int64_t kPeriod = 10'000;
constexpr int kSamples = 100;

std::string frame(int index) { return "f" + std::to_string(index); }

struct Work {
  std::function<void()> run;
  const unsigned char* entry = nullptr;  // the thread's stack where it called `run`
};

void* runWork(void* work) {
  Work& w = *static_cast<Work*>(work);
  w.entry = static_cast<const unsigned char*>(__builtin_frame_address(0));
  w.run();
  return nullptr;
}

struct FreeAligned {
  void operator()(unsigned char* bytes) const { std::free(bytes); }
};

// The bytes of a painted stack below where `run` was called that running it overwrote.
std::size_t stackTakenBy(std::function<void()> run) {
  const std::unique_ptr<unsigned char, FreeAligned> stack(
      static_cast<unsigned char*>(std::aligned_alloc(4096, kThreadStack)));
  if (!stack) throw std::bad_alloc();
  std::memset(stack.get(), kPaint, kThreadStack);
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstack(&attributes, stack.get(), kThreadStack);
  Work work{std::move(run)};
  pthread_t thread;
  const int created = pthread_create(&thread, &attributes, runWork, &work);
  pthread_attr_destroy(&attributes);
  if (created != 0) throw std::runtime_error("pthread_create failed");
  pthread_join(thread, nullptr);
  std::size_t untouched = 0;  // the stack grows down, from the end of the block
  while (untouched < kThreadStack && stack.get()[untouched] == kPaint) ++untouched;
  const unsigned char* deepest = stack.get() + untouched;
  return work.entry > deepest ? static_cast<std::size_t>(work.entry - deepest) : 0;
}

class LookupStack : public ::testing::Test {
 protected:
  void SetUp() override {
    std::vector<TransformStamped> transforms;
    for (int k = 0; k < kSamples; ++k) {
      for (int child = 1; child < kChain; ++child) {
        const double t = 0.01 * k + child;
        transforms.push_back(TransformStamped{
            fromUtime(kFirstStamp + k * kPeriod), frame(child - 1), frame(child),
            Transform(Eigen::Vector3d(t, 0.5, 0.25),
                      Eigen::Quaterniond(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ())))});
      }
    }
    ASSERT_EQ(buffer_.setTransforms(transforms, "test"), transforms.size());
  }

  void expectWithinBound(const char* what, const std::function<void()>& lookup,
                         std::size_t bound = kLookupStackBound) {
    const std::size_t taken = stackTakenBy(lookup);
    std::cout << what << ": " << taken << " bytes of stack\n";
    EXPECT_LE(taken, bound * kSlowBuildFactor) << what;
  }

  BufferCore buffer_{std::chrono::seconds(10)};
};

const TimePoint kBetweenSamples = fromUtime(kFirstStamp + 40 * kPeriod + 3'333);
const TimePoint kEarlier = fromUtime(kFirstStamp + 20 * kPeriod + 7'777);

TEST_F(LookupStack, EveryKindOfLookupKeepsWithinTheBound) {
  expectWithinBound("lookup 40 edges at a time between samples",
                    [this] { buffer_.lookupTransform(frame(10), frame(50), kBetweenSamples); });
  expectWithinBound("lookup at the latest common time",
                    [this] { buffer_.lookupTransform(frame(10), frame(50), kLatestTime); });
  expectWithinBound("lookup by handle into a kept result", [this] {
    TransformStamped result;
    buffer_.lookupTransform(buffer_.findFrame(frame(50)), buffer_.findFrame(frame(10)),
                            kBetweenSamples, result);
  });
  expectWithinBound("time-travel lookup", [this] {
    buffer_.lookupTransform(frame(60), kBetweenSamples, frame(50), kEarlier, frame(0));
  });
  expectWithinBound(
      "canTransform",
      [this] { EXPECT_TRUE(buffer_.canTransform(frame(10), frame(50), kBetweenSamples)); },
      kCanTransformStackBound);
  expectWithinBound("lookup along 99 edges", [this] {
    buffer_.lookupTransform(frame(0), frame(kChain - 1), kBetweenSamples);
  });
  expectWithinBound("lookup that fails", [this] {
    EXPECT_THROW(buffer_.lookupTransform(frame(0), frame(50), fromUtime(kFirstStamp - 1)),
                 ExtrapolationException);
  });
}

// The measurement sees what work takes: more than the bound is caught.
TEST(LookupStackMeasure, MeasuresWhatTheWorkTakes) {
  const std::size_t taken = stackTakenBy([] {
    volatile unsigned char scratch[2 * kBuildBound];
    for (std::size_t i = 0; i < sizeof scratch; i += 512) scratch[i] = 0;
  });
  EXPECT_GT(taken, 2 * kBuildBound);
  EXPECT_LT(taken, 2 * kBuildBound + 16 * 1024);
}

}  // namespace
}  // namespace lcmtf
