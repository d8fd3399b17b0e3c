// Readers, writers, clear() and transformable requests at once. Run under ThreadSanitizer in
// CI; here it also checks that every answer a reader gets is a valid transform.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "support/test_scale.hpp"

namespace lcmtf {
namespace {

constexpr std::int64_t kStepMicros = 1000;

TransformStamped moving(const std::string& parent, const std::string& child, std::int64_t utime) {
  const double t = static_cast<double>(utime) * 1e-6;
  return TransformStamped{
      fromUtime(utime), parent, child,
      Transform(Eigen::Vector3d(std::cos(t), std::sin(t), 0.1 * t),
                Eigen::Quaterniond(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ())))};
}

TEST(BufferCoreConcurrency, ReadersWritersClearAndRequestsRunTogether) {
  BufferCore buffer(std::chrono::milliseconds(200));
  buffer.setErrorReporter(nullptr);
  buffer.setTransform(TransformStamped{TimePoint{}, "map", "odom",
                                       Transform(Eigen::Vector3d(1, 0, 0), {1, 0, 0, 0})},
                      "static", true);
  buffer.setTransform(TransformStamped{TimePoint{}, "base", "camera",
                                       Transform(Eigen::Vector3d(0, 0, 1), {1, 0, 0, 0})},
                      "static", true);

  const int samples_per_writer = lcmtf_test::scaledCount(4000);
  std::atomic<std::int64_t> newest{kStepMicros};
  std::atomic<bool> writing{true};
  std::atomic<std::uint64_t> answered{0};
  std::atomic<std::uint64_t> refused{0};
  std::atomic<std::uint64_t> bad_answers{0};

  std::vector<std::thread> threads;
  const std::vector<std::pair<std::string, std::string>> writer_edges{{"odom", "base"},
                                                                      {"base", "arm"}};
  for (const auto& [parent, child] : writer_edges) {
    threads.emplace_back([&buffer, &newest, samples_per_writer, parent = parent, child = child] {
      for (int i = 1; i <= samples_per_writer; ++i) {
        const std::int64_t utime = i * kStepMicros;
        buffer.setTransform(moving(parent, child, utime), "writer_" + child);
        std::int64_t seen = newest.load();
        while (seen < utime && !newest.compare_exchange_weak(seen, utime)) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      }
    });
  }
  for (int reader = 0; reader < 2; ++reader) {
    threads.emplace_back([&, reader] {
      std::uint64_t state = 88172645463325252ull + static_cast<std::uint64_t>(reader);
      while (writing.load()) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        const std::int64_t when = newest.load() - static_cast<std::int64_t>(state % 150'000);
        const TimePoint time = (state & 7) == 0 ? kLatestTime : fromUtime(when);
        try {
          const TransformStamped t = buffer.lookupTransform("map", "camera", time);
          const bool valid = std::abs(t.transform.rotation.norm() - 1.0) < 1e-9 &&
                             t.transform.translation.allFinite() && t.parent_frame == "map" &&
                             t.child_frame == "camera";
          (valid ? answered : bad_answers).fetch_add(1);
        } catch (const TransformException&) {
          refused.fetch_add(1);
        }
        std::string why;
        buffer.canTransform("arm", "camera", time, &why);
      }
    });
  }
  threads.emplace_back([&] {
    while (writing.load()) {
      buffer.clear();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      buffer.allFramesAsYaml();
      buffer.getAllFrameNames();
    }
  });

  std::mutex fired_mutex;
  std::multiset<TransformableRequestHandle> fired;
  std::set<TransformableRequestHandle> cancelled;
  threads.emplace_back([&] {
    while (writing.load()) {
      const TimePoint ahead = fromUtime(newest.load() + 5 * kStepMicros);
      const TransformableRequestHandle handle = buffer.addTransformableRequest(
          [&](TransformableRequestHandle h, const std::string&, const std::string&, TimePoint,
              TransformableResult) {
            std::lock_guard<std::mutex> guard(fired_mutex);
            fired.insert(h);
          },
          "map", "arm", ahead);
      if (handle != 0 && handle % 3 == 0) {
        buffer.cancelTransformableRequest(handle);
        std::lock_guard<std::mutex> guard(fired_mutex);
        cancelled.insert(handle);
      }
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  });

  threads[0].join();
  threads[1].join();
  writing.store(false);
  for (std::size_t i = 2; i < threads.size(); ++i) threads[i].join();

  const std::int64_t after_all = (samples_per_writer + 1) * kStepMicros;
  for (const auto& [parent, child] : writer_edges) {
    ASSERT_TRUE(buffer.setTransform(moving(parent, child, after_all), "writer_" + child));
  }
  EXPECT_EQ(toUtime(buffer.lookupTransform("map", "camera", kLatestTime).stamp), after_all);

  EXPECT_EQ(bad_answers.load(), 0u);
  EXPECT_GT(answered.load(), 0u);
  std::lock_guard<std::mutex> guard(fired_mutex);
  EXPECT_FALSE(fired.empty());
  for (TransformableRequestHandle handle : fired) {
    EXPECT_EQ(fired.count(handle), 1u) << "request " << handle << " fired twice";
  }
}

// Writers with no pause between inserts contend for their turns, so that many of them pass
// through the kernel, with a reader waiting on each of them now and then.
TEST(BufferCoreConcurrency, WritersContendingForTheirTurnsLoseNoSample) {
  BufferCore buffer(std::chrono::seconds(100));
  const int samples_per_writer = lcmtf_test::scaledCount(20000, 500);
  constexpr int kWriters = 4;
  std::atomic<bool> writing{true};
  std::atomic<std::uint64_t> bad_answers{0};
  std::vector<std::thread> writers;
  for (int writer = 0; writer < kWriters; ++writer) {
    writers.emplace_back([&buffer, samples_per_writer, writer] {
      const std::string child = "arm_" + std::to_string(writer);
      for (int i = 1; i <= samples_per_writer; ++i) {
        buffer.setTransform(moving("base", child, i * kStepMicros), "writer_" + child);
      }
    });
  }
  std::thread reader([&] {
    std::int64_t utime = kStepMicros;
    while (writing.load()) {
      try {
        const TransformStamped t = buffer.lookupTransform("arm_0", "arm_1", fromUtime(utime));
        const bool valid = std::abs(t.transform.rotation.norm() - 1.0) < 1e-9 &&
                           t.transform.translation.allFinite();
        if (!valid) bad_answers.fetch_add(1);
      } catch (const TransformException&) {
      }
      utime = utime % (samples_per_writer * kStepMicros) + kStepMicros;
    }
  });
  for (std::thread& writer : writers) writer.join();
  writing.store(false);
  reader.join();

  EXPECT_EQ(buffer.statistics().inserted,
            static_cast<std::uint64_t>(kWriters) * static_cast<std::uint64_t>(samples_per_writer));
  for (int writer = 0; writer < kWriters; ++writer) {
    const std::string child = "arm_" + std::to_string(writer);
    EXPECT_EQ(toUtime(buffer.lookupTransform("base", child, kLatestTime).stamp),
              samples_per_writer * kStepMicros)
        << child;
  }
  EXPECT_EQ(bad_answers.load(), 0u);
}

}  // namespace
}  // namespace lcmtf
