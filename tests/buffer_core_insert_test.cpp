// BufferCore::setTransform: what is stored, what is refused, and what is counted.
#include "lcmtf/buffer_core.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::axisAngle;
using lcmtf_test::identical;
using lcmtf_test::isometry;
using lcmtf_test::kEpoch;
using lcmtf_test::near;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;
using lcmtf_test::stamped;
using ::testing::HasSubstr;

constexpr double kTolerance = 1e-12;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

std::uint64_t rejected(const BufferCore& buffer, InsertRejection kind) {
  return buffer.statistics().rejectedCount(kind);
}

// Everything a user can observe of a buffer, to show that a refused insert changed nothing.
struct Snapshot {
  std::vector<std::string> names;
  std::string yaml;
  std::string dot;
  std::vector<std::string> lookups;

  explicit Snapshot(const BufferCore& buffer)
      : names(buffer.getAllFrameNames()),
        yaml(buffer.allFramesAsYaml()),
        dot(buffer.allFramesAsDot()) {
    for (const TimePoint t : {kLatestTime, at(0.5), at(1), at(2.5), at(3), at(4), at(-8)}) {
      for (const char* target : {"world", "laser"}) {
        std::string why;
        if (!buffer.canTransform(target, "base", t, &why)) {
          lookups.push_back("cannot: " + why);
          continue;
        }
        const TransformStamped result = buffer.lookupTransform(target, "base", t);
        std::ostringstream text;
        text.precision(17);
        text << toString(result.stamp) << ' ' << result.transform.translation.transpose() << ' '
             << result.transform.rotation.coeffs().transpose();
        lookups.push_back(text.str());
      }
    }
  }
  bool operator==(const Snapshot& other) const {
    return names == other.names && yaml == other.yaml && dot == other.dot &&
           lookups == other.lookups;
  }
};

std::ostream& operator<<(std::ostream& out, const Snapshot& snapshot) {
  out << "frames:";
  for (const std::string& name : snapshot.names) out << ' ' << name;
  out << "\n" << snapshot.yaml;
  for (const std::string& lookup : snapshot.lookups) out << lookup << '\n';
  return out;
}

Transform withTranslation(double x, double y, double z) {
  return Transform(Eigen::Vector3d(x, y, z), axisAngle(0.3, kZ));
}
Transform withRotation(double x, double y, double z, double w) {
  return Transform(Eigen::Vector3d(1, 0, 0), Eigen::Quaterniond(w, x, y, z));
}
Transform scaledRotation(double scale) {
  Eigen::Quaterniond q = axisAngle(0.8, Eigen::Vector3d(1, 2, 3));
  q.coeffs() *= scale;
  return Transform(Eigen::Vector3d(1, 0, 0), q);
}

struct BadInput {
  std::string name;
  TransformStamped transform;
  bool is_static;
  InsertRejection kind;
  std::string reason;
};

std::ostream& operator<<(std::ostream& out, const BadInput& input) { return out << input.name; }

// world -> base (dynamic, 1 s to 3 s), base -> laser (static).
class BadInputToSetTransform : public ::testing::TestWithParam<BadInput> {
 protected:
  void SetUp() override {
    buffer_.setErrorReporter([this](const std::string& message) { reports_.push_back(message); });
    for (int i = 1; i <= 3; ++i) put(buffer_, "world", "base", at(i), pose({1.0 * i, 0, 0}, 0, kZ));
    putStatic(buffer_, "base", "laser", pose({0.2, 0, 0.1}, 0.5, kZ));
  }
  BufferCore buffer_;
  std::vector<std::string> reports_;
};

TEST_P(BadInputToSetTransform, IsRefusedWithAReasonCountedByKindAndChangesNothing) {
  const BadInput& input = GetParam();
  const Snapshot before(buffer_);
  const InsertStatistics statistics_before = buffer_.statistics();

  std::string error;
  EXPECT_FALSE(buffer_.setTransform(input.transform, "bad_publisher", input.is_static, &error));
  EXPECT_THAT(error, HasSubstr(input.reason));

  const InsertStatistics statistics = buffer_.statistics();
  for (std::size_t kind = 0; kind < statistics.rejected.size(); ++kind) {
    EXPECT_EQ(statistics.rejected[kind], kind == static_cast<std::size_t>(input.kind) ? 1u : 0u)
        << describe(static_cast<InsertRejection>(kind));
  }
  EXPECT_EQ(statistics.inserted, statistics_before.inserted);
  EXPECT_EQ(statistics.replaced, statistics_before.replaced);
  EXPECT_EQ(statistics.normalized, statistics_before.normalized);
  EXPECT_EQ(statistics.authority_conflicts, statistics_before.authority_conflicts);

  const Snapshot after(buffer_);
  EXPECT_EQ(after, before);
  EXPECT_FALSE(buffer_.frameExists("ghost"));
  ASSERT_EQ(reports_.size(), 1u);
  EXPECT_THAT(reports_[0], HasSubstr(input.reason));
}

std::vector<BadInput> badInputs() {
  const TimePoint next = at(4);  // would extend world -> base if it were stored
  const Transform good = pose({4, 0, 0}, 0, kZ);
  const auto edge = [&](const Transform& value) { return stamped("world", "base", next, value); };
  using R = InsertRejection;
  return {
      {"NaNInTranslationX", edge(withTranslation(kNaN, 0, 0)), false, R::kNonFinite, "NaN"},
      {"NaNInTranslationY", edge(withTranslation(0, kNaN, 0)), false, R::kNonFinite, "NaN"},
      {"InfinityInTranslationZ", edge(withTranslation(0, 0, kInf)), false, R::kNonFinite,
       "infinite"},
      {"MinusInfinityInTranslation", edge(withTranslation(-kInf, 0, 0)), false, R::kNonFinite,
       "infinite"},
      {"NaNInRotationW", edge(withRotation(0, 0, 0, kNaN)), false, R::kNonFinite, "NaN"},
      {"NaNInRotationY", edge(withRotation(0, kNaN, 0, 1)), false, R::kNonFinite, "NaN"},
      {"InfinityInRotationX", edge(withRotation(kInf, 0, 0, 1)), false, R::kNonFinite, "infinite"},
      {"NaNInStaticTransform", edge(withTranslation(kNaN, 0, 0)), true, R::kNonFinite, "NaN"},
      {"NaNForANewChildFrame", stamped("world", "ghost", next, withTranslation(kNaN, 1, 1)), false,
       R::kNonFinite, "NaN"},
      {"QuaternionNormTooLarge", edge(scaledRotation(1.0011)), false, R::kBadQuaternion,
       "quaternion of norm 1.0011"},
      {"QuaternionNormTooSmall", edge(scaledRotation(0.9989)), false, R::kBadQuaternion,
       "quaternion of norm 0.9989"},
      {"QuaternionNormTwo", edge(scaledRotation(2.0)), false, R::kBadQuaternion,
       "quaternion of norm 2"},
      {"ZeroQuaternion", edge(withRotation(0, 0, 0, 0)), false, R::kBadQuaternion,
       "quaternion of norm 0"},
      {"ZeroQuaternionForANewChildFrame", stamped("world", "ghost", next, withRotation(0, 0, 0, 0)),
       true, R::kBadQuaternion, "quaternion"},
      {"EmptyParent", stamped("", "base", next, good), false, R::kEmptyFrameName,
       "empty parent frame name"},
      {"EmptyChild", stamped("world", "", next, good), false, R::kEmptyFrameName,
       "empty child frame name"},
      {"SlashOnlyChild", stamped("world", "/", next, good), false, R::kEmptyFrameName,
       "empty child frame name"},
      {"EmptyParentOfNewChild", stamped("", "ghost", next, good), true, R::kEmptyFrameName,
       "empty parent frame name"},
      {"SelfParented", stamped("base", "base", next, good), false, R::kSelfParented,
       "'base' cannot be its own parent"},
      {"SelfParentedAfterStrippingSlash", stamped("/ghost", "ghost", next, good), false,
       R::kSelfParented, "'ghost' cannot be its own parent"},
      {"SelfParentedStatic", stamped("laser", "/laser", next, good), true, R::kSelfParented,
       "own parent"},
      {"OlderThanHistory",
       stamped("world", "base", at(3) - std::chrono::seconds(10) - Duration(1), good), false,
       R::kOlderThanHistory, "older than the history kept"},
      {"OlderThanHistoryUnderANewParent",
       stamped("ghost", "base", at(3) - std::chrono::seconds(10) - Duration(1), good), false,
       R::kOlderThanHistory, "older than the history kept"},
  };
}

INSTANTIATE_TEST_SUITE_P(BufferCoreInsert, BadInputToSetTransform, ::testing::ValuesIn(badInputs()),
                         [](const ::testing::TestParamInfo<BadInput>& param_info) {
                           return param_info.param.name;
                         });

TEST(BufferCoreInsert, RefusalWithoutAnErrorStringIsStillCounted) {
  BufferCore buffer;
  buffer.setErrorReporter(nullptr);
  EXPECT_FALSE(buffer.setTransform(stamped("world", "base", at(1), withTranslation(kNaN, 0, 0)),
                                   "test", false));
  EXPECT_EQ(rejected(buffer, InsertRejection::kNonFinite), 1u);
  EXPECT_FALSE(buffer.frameExists("base"));
}

TEST(BufferCoreInsert, RejectionsAccumulatePerKind) {
  BufferCore buffer;
  buffer.setErrorReporter(nullptr);
  put(buffer, "world", "base", at(20), pose({0, 0, 0}, 0, kZ));
  const Transform good = pose({0, 0, 0}, 0, kZ);
  for (int i = 0; i < 3; ++i) {
    EXPECT_FALSE(
        buffer.setTransform(stamped("world", "base", at(21), withTranslation(kNaN, 0, 0)), "test"));
  }
  for (int i = 0; i < 2; ++i) {
    EXPECT_FALSE(buffer.setTransform(stamped("world", "", at(21), good), "test"));
  }
  EXPECT_FALSE(buffer.setTransform(stamped("a", "a", at(21), good), "test"));
  for (int i = 0; i < 4; ++i) {
    EXPECT_FALSE(
        buffer.setTransform(stamped("world", "base", at(21), scaledRotation(1.1)), "test"));
  }
  for (int i = 0; i < 5; ++i) {
    EXPECT_FALSE(buffer.setTransform(stamped("world", "base", at(i), good), "test"));
  }
  const InsertStatistics statistics = buffer.statistics();
  EXPECT_EQ(statistics.rejectedCount(InsertRejection::kNonFinite), 3u);
  EXPECT_EQ(statistics.rejectedCount(InsertRejection::kEmptyFrameName), 2u);
  EXPECT_EQ(statistics.rejectedCount(InsertRejection::kSelfParented), 1u);
  EXPECT_EQ(statistics.rejectedCount(InsertRejection::kBadQuaternion), 4u);
  EXPECT_EQ(statistics.rejectedCount(InsertRejection::kOlderThanHistory), 5u);
  EXPECT_EQ(statistics.rejectedTotal(), 15u);
  EXPECT_EQ(statistics.inserted, 1u);
}

TEST(BufferCoreInsert, ErrorReporterIsCalledOncePerKindOfRejection) {
  BufferCore buffer;
  std::vector<std::string> reports;
  buffer.setErrorReporter([&](const std::string& message) { reports.push_back(message); });
  put(buffer, "world", "base", at(20), pose({0, 0, 0}, 0, kZ));
  const Transform good = pose({0, 0, 0}, 0, kZ);
  for (int round = 0; round < 3; ++round) {
    buffer.setTransform(stamped("world", "base", at(21), withTranslation(kInf, 0, 0)), "test");
    buffer.setTransform(stamped("world", "base", at(21), scaledRotation(0.5)), "test");
    buffer.setTransform(stamped("", "base", at(21), good), "test");
    buffer.setTransform(stamped("base", "base", at(21), good), "test");
    buffer.setTransform(stamped("world", "base", at(1), good), "test");
    put(buffer, "world", "base", at(22 + round), good);  // accepted inserts report nothing
  }
  ASSERT_EQ(reports.size(), 5u);
  EXPECT_THAT(reports[0], HasSubstr("infinite"));
  EXPECT_THAT(reports[1], HasSubstr("quaternion of norm 0.5"));
  EXPECT_THAT(reports[2], HasSubstr("empty parent frame name"));
  EXPECT_THAT(reports[3], HasSubstr("own parent"));
  EXPECT_THAT(reports[4], HasSubstr("older than the history kept"));
  EXPECT_EQ(buffer.statistics().rejectedTotal(), 15u);
}

TEST(BufferCoreInsert, SlightlyDenormalizedQuaternionIsNormalizedAndCounted) {
  BufferCore buffer;
  const Eigen::Quaterniond unit = axisAngle(0.8, Eigen::Vector3d(1, 2, 3));
  std::string error;
  EXPECT_TRUE(buffer.setTransform(stamped("world", "a", at(1), scaledRotation(1.0009)), "test",
                                  false, &error))
      << error;
  EXPECT_TRUE(buffer.setTransform(stamped("world", "b", at(1), scaledRotation(0.9991)), "test",
                                  false, &error))
      << error;
  EXPECT_TRUE(buffer.setTransform(stamped("world", "c", at(1), scaledRotation(1.0009)), "test",
                                  true, &error))
      << error;
  EXPECT_EQ(buffer.statistics().normalized, 3u);
  EXPECT_EQ(buffer.statistics().inserted, 3u);
  EXPECT_EQ(buffer.statistics().rejectedTotal(), 0u);
  for (const char* child : {"a", "b", "c"}) {
    const Eigen::Quaterniond stored =
        buffer.lookupTransform("world", child, at(1)).transform.rotation;
    EXPECT_NEAR(stored.norm(), 1.0, 1e-15) << child;
    EXPECT_LE((stored.coeffs() - unit.coeffs()).cwiseAbs().maxCoeff(), 1e-15) << child;
  }
}

TEST(BufferCoreInsert, UnitQuaternionsWithOnlyRoundingErrorAreStoredAsGivenAndNotCounted) {
  // About a quarter of unit quaternions computed in double precision have a norm a few ulps
  // away from 1; they are not denormalized input.
  BufferCore buffer;
  std::srand(3);
  std::vector<Eigen::Quaterniond> rotations;
  for (int i = 0; i < 200; ++i) {
    rotations.push_back(Eigen::Quaterniond::UnitRandom());
    put(buffer, "world", "robot", at(0.01 * i),
        Transform(Eigen::Vector3d(i, 0, 0), rotations.back()));
  }
  EXPECT_EQ(buffer.statistics().normalized, 0u);
  for (int i = 0; i < 200; ++i) {
    EXPECT_TRUE(
        identical(buffer.lookupTransform("world", "robot", at(0.01 * i)).transform,
                  Transform(Eigen::Vector3d(i, 0, 0), rotations[static_cast<std::size_t>(i)])));
  }
}

TEST(BufferCoreInsert, OneLeadingSlashIsStrippedFromInsertedNames) {
  BufferCore buffer;
  put(buffer, "/world", "/base", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(2), pose({2, 0, 0}, 0, kZ));
  put(buffer, "//odd", "base_link", at(2), pose({0, 0, 0}, 0, kZ));
  EXPECT_THAT(buffer.getAllFrameNames(),
              ::testing::UnorderedElementsAre("world", "base", "/odd", "base_link"));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("'base':\n  parent: 'world'\n"));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 2\n"));
  EXPECT_TRUE(buffer.frameExists("//odd"));
  EXPECT_FALSE(buffer.frameExists("/odd"));
  EXPECT_EQ(buffer.statistics().replaced, 0u);
}

TEST(BufferCoreInsert, HistoryKeepsExactlyCacheTimeBehindTheNewestSample) {
  BufferCore buffer(std::chrono::seconds(1));
  for (int i = 0; i <= 20; ++i)
    put(buffer, "world", "robot", at(0.1 * i), pose({0.1 * i, 0, 0}, 0, kZ));
  // Newest 2.0: 1.0 is exactly one cache time behind and stays, 0.9 is gone.
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 11\n"));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("oldest_transform: " + toString(at(1)) + "\n"));
  EXPECT_TRUE(buffer.canTransform("world", "robot", at(1)));
  EXPECT_THROW(buffer.lookupTransform("world", "robot", at(1) - Duration(1)),
               PastExtrapolationException);
  EXPECT_LE((buffer.lookupTransform("world", "robot", at(1)).transform.translation -
             Eigen::Vector3d(1, 0, 0))
                .norm(),
            kTolerance);
}

TEST(BufferCoreInsert, SampleExactlyCacheTimeOlderThanTheNewestIsAcceptedAndOneOlderIsRefused) {
  BufferCore buffer(std::chrono::seconds(1));
  std::vector<std::string> reports;
  buffer.setErrorReporter([&](const std::string& message) { reports.push_back(message); });
  put(buffer, "world", "robot", at(1.5), pose({1.5, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2), pose({2, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(1), pose({1, 0, 0}, 0, kZ));  // the boundary is inclusive
  EXPECT_TRUE(
      identical(buffer.lookupTransform("world", "robot", at(1)).transform, pose({1, 0, 0}, 0, kZ)));

  std::string error;
  EXPECT_FALSE(
      buffer.setTransform(stamped("world", "robot", at(1) - Duration(1), pose({0, 0, 0}, 0, kZ)),
                          "test", false, &error));
  EXPECT_EQ(rejected(buffer, InsertRejection::kOlderThanHistory), 1u);
  EXPECT_EQ(error, "'world' -> 'robot' at " + toString(at(1) - Duration(1)) +
                       " is older than the history kept: the newest sample is at " +
                       toString(at(2)) + " and the cache time is 1.000000 s");
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_THAT(reports[0], HasSubstr(error));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 3\n"));
  EXPECT_EQ(buffer.statistics().inserted, 3u);
}

TEST(BufferCoreInsert, NewerSamplePrunesSamplesThatFallOutOfTheWindow) {
  BufferCore buffer(std::chrono::seconds(1));
  put(buffer, "world", "robot", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(1.5), pose({1.5, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2), pose({2, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2) + Duration(1), pose({2, 0, 0}, 0, kZ));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 3\n"));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("oldest_transform: " + toString(at(1.5)) + "\n"));
  EXPECT_THROW(buffer.lookupTransform("world", "robot", at(1)), PastExtrapolationException);
  EXPECT_THROW(buffer.lookupTransform("world", "robot", at(1.25)), PastExtrapolationException);
  // The window moved by a microsecond: a sample at its new edge is still accepted.
  put(buffer, "world", "robot", at(1) + Duration(1), pose({1, 0, 0}, 0, kZ));
  EXPECT_TRUE(buffer.canTransform("world", "robot", at(1.25)));
}

TEST(BufferCoreInsert, DefaultCacheTimeIsTenSecondsPerEdge) {
  BufferCore buffer;
  EXPECT_EQ(buffer.cacheTime(), std::chrono::seconds(10));
  put(buffer, "world", "slow", at(0), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "fast", at(0), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "fast", at(10), pose({10, 0, 0}, 0, kZ));
  EXPECT_TRUE(buffer.canTransform("world", "fast", at(0)));
  put(buffer, "world", "fast", at(10) + Duration(1), pose({10, 0, 0}, 0, kZ));
  EXPECT_FALSE(buffer.canTransform("world", "fast", at(0)));
  EXPECT_FALSE(buffer.canTransform("world", "fast", at(0) + Duration(1)));
  EXPECT_TRUE(buffer.canTransform("world", "fast", at(10)));
  // Another edge's history is its own: the slow edge keeps its only sample.
  EXPECT_TRUE(buffer.canTransform("world", "slow", at(0)));
}

TEST(BufferCoreInsert, OutOfOrderInsertsLandInTimeOrder) {
  BufferCore buffer;
  std::vector<int> order(21);
  for (int i = 0; i <= 20; ++i) order[static_cast<std::size_t>(i)] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(11));
  const auto value = [](double t) {
    return Transform(Eigen::Vector3d(t, t * t, 0), Eigen::Quaterniond::Identity());
  };
  for (const int i : order) put(buffer, "world", "robot", at(0.5 * i), value(0.5 * i));
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 21\n"));
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.5 * i;
    EXPECT_TRUE(identical(buffer.lookupTransform("world", "robot", at(t)).transform, value(t)))
        << "t " << t;
    if (i == 20) continue;
    // A quarter of the way to the next sample: mixes this sample and the next only.
    const Eigen::Vector3d expected =
        0.75 * value(t).translation + 0.25 * value(t + 0.5).translation;
    EXPECT_LE(
        (buffer.lookupTransform("world", "robot", at(t + 0.125)).transform.translation - expected)
            .norm(),
        kTolerance)
        << "t " << t;
  }
  EXPECT_EQ(buffer.statistics().replaced, 0u);
  EXPECT_EQ(buffer.statistics().inserted, 21u);
}

// One edge's history under random traffic, checked against a sorted map that follows the rules:
// newest sample sets a window of cache_time (inclusive), older samples are refused, a repeated
// stamp replaces, anything else lands in time order. The stream wraps the history's storage
// many times, with irregular spacing and late samples.
TEST(BufferCoreInsert, RandomTrafficMatchesAReferenceHistory) {
  constexpr std::int64_t kCache = 1'000'000;
  BufferCore buffer{Duration(kCache)};
  buffer.setErrorReporter(nullptr);
  std::map<std::int64_t, double> model;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  std::int64_t clock = 0;
  std::uint64_t refused = 0;
  std::uint64_t replaced = 0;

  const auto check = [&](int queries) {
    const std::int64_t oldest = model.begin()->first;
    const std::int64_t newest = model.rbegin()->first;
    const std::string yaml = buffer.allFramesAsYaml();
    EXPECT_THAT(yaml, HasSubstr("samples: " + std::to_string(model.size()) + "\n"));
    EXPECT_THAT(yaml, HasSubstr("oldest_transform: " + toString(kEpoch + Duration(oldest))));
    EXPECT_THAT(yaml, HasSubstr("most_recent_transform: " + toString(kEpoch + Duration(newest))));
    std::uniform_int_distribution<std::int64_t> when(oldest - 100'000, newest + 100'000);
    for (int i = 0; i < queries; ++i) {
      const std::int64_t t = when(random);
      const bool inside = t >= oldest && t <= newest;
      ASSERT_EQ(buffer.canTransform("world", "robot", kEpoch + Duration(t)), inside) << t;
      if (!inside) continue;
      const auto after = model.lower_bound(t);
      double expected = after->second;
      if (after->first != t) {
        const auto before = std::prev(after);
        const double ratio = static_cast<double>(t - before->first) /
                             static_cast<double>(after->first - before->first);
        expected = before->second + ratio * (after->second - before->second);
      }
      ASSERT_NEAR(
          buffer.lookupTransform("world", "robot", kEpoch + Duration(t)).transform.translation.x(),
          expected, kTolerance)
          << t;
    }
    for (const auto& [stamp, x] : model) {
      ASSERT_EQ(buffer.lookupTransform("world", "robot", kEpoch + Duration(stamp))
                    .transform.translation.x(),
                x)
          << stamp;
    }
  };

  for (int i = 1; i <= 4000; ++i) {
    clock += std::uniform_int_distribution<std::int64_t>(1, 20'000)(random);
    std::int64_t stamp = clock;
    const int kind = std::uniform_int_distribution<int>(0, 9)(random);
    if (kind == 0 && !model.empty()) {  // late, sometimes too late
      stamp =
          model.rbegin()->first - std::uniform_int_distribution<std::int64_t>(0, 1'200'000)(random);
    } else if (kind == 1 && !model.empty()) {  // a repeat of a stored stamp
      const auto index = std::uniform_int_distribution<std::size_t>(0, model.size() - 1)(random);
      stamp = std::next(model.begin(), static_cast<std::ptrdiff_t>(index))->first;
    }
    const double x = value(random);
    const bool accept = model.empty() || stamp >= model.rbegin()->first - kCache;
    ASSERT_EQ(buffer.setTransform(stamped("world", "robot", kEpoch + Duration(stamp),
                                          Transform({x, 0, 0}, Eigen::Quaterniond::Identity())),
                                  "test"),
              accept)
        << "insert " << i << " at " << stamp;
    if (!accept) {
      ++refused;
      continue;
    }
    replaced += model.count(stamp);
    model[stamp] = x;
    model.erase(model.begin(), model.lower_bound(model.rbegin()->first - kCache));
    if (i % 200 == 0) check(50);
  }
  check(2000);
  EXPECT_GT(refused, 0u);
  EXPECT_GT(replaced, 0u);
  EXPECT_EQ(buffer.statistics().rejectedCount(InsertRejection::kOlderThanHistory), refused);
  EXPECT_EQ(buffer.statistics().replaced, replaced);
}

TEST(BufferCoreInsert, RepeatedStampReplacesTheSampleSilently) {
  BufferCore buffer;
  std::vector<std::string> reports;
  buffer.setErrorReporter([&](const std::string& message) { reports.push_back(message); });
  put(buffer, "world", "robot", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2), pose({2, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(1), pose({5, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2), pose({6, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(2), pose({7, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.statistics().replaced, 3u);
  EXPECT_EQ(buffer.statistics().rejectedTotal(), 0u);
  EXPECT_TRUE(reports.empty());
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("samples: 2\n"));
  EXPECT_TRUE(
      identical(buffer.lookupTransform("world", "robot", at(1)).transform, pose({5, 0, 0}, 0, kZ)));
  EXPECT_LE((buffer.lookupTransform("world", "robot", at(1.5)).transform.translation -
             Eigen::Vector3d(6, 0, 0))
                .norm(),
            kTolerance);
}

TEST(BufferCoreInsert, StaticEdgesSurviveClearAndDynamicHistoryDoesNot) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({1, 2, 3}, 0.4, kZ));
  put(buffer, "base", "arm", at(5), pose({0, 0, 1}, 0, kZ));
  put(buffer, "base", "arm", at(6), pose({0, 0, 2}, 0, kZ));
  const InsertStatistics statistics = buffer.statistics();

  buffer.clear();
  EXPECT_TRUE(near(buffer.lookupTransform("world", "base", at(100)).transform,
                   isometry({1, 2, 3}, 0.4, kZ), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "base", kLatestTime).transform,
                   isometry({1, 2, 3}, 0.4, kZ), kTolerance));
  EXPECT_FALSE(buffer.canTransform("base", "arm", at(5)));
  EXPECT_FALSE(buffer.canTransform("base", "arm", kLatestTime));
  EXPECT_THROW(buffer.lookupTransform("base", "arm", at(5)), ConnectivityException);
  EXPECT_THAT(buffer.getAllFrameNames(), ::testing::UnorderedElementsAre("world", "base", "arm"));
  EXPECT_EQ(buffer.statistics().inserted, statistics.inserted);
  EXPECT_THAT(buffer.allFramesAsYaml(), ::testing::Not(HasSubstr("'arm':")));

  // With the history gone, older data is welcome again.
  put(buffer, "base", "arm", at(1), pose({0, 0, 3}, 0, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(1)).transform,
                   isometry({1, 2, 3}, 0.4, kZ) * isometry({0, 0, 3}, 0, kZ), kTolerance));
}

TEST(BufferCoreInsert, RedeclaringAnEdgeStaticReplacesItsDynamicHistory) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(2), pose({2, 0, 0}, 0, kZ));
  putStatic(buffer, "world", "base", pose({0, 7, 0}, 0.2, kZ));
  for (const TimePoint t : {at(0), at(1), at(1.5), at(50), kLatestTime}) {
    const TransformStamped result = buffer.lookupTransform("world", "base", t);
    EXPECT_TRUE(near(result.transform, isometry({0, 7, 0}, 0.2, kZ), kTolerance));
    EXPECT_EQ(result.stamp, t);
  }
  EXPECT_EQ(buffer.getLatestCommonTime("world", "base"), TimePoint{});
  EXPECT_THAT(buffer.allFramesAsYaml(), HasSubstr("  static: true\n  rate: 0.000\n  samples: 1\n"));
  buffer.clear();
  EXPECT_TRUE(buffer.canTransform("world", "base", at(3)));
}

TEST(BufferCoreInsert, RedeclaringAStaticEdgeReplacesItsValueAndMayChangeItsParent) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({1, 0, 0}, 0, kZ));
  putStatic(buffer, "world", "base", pose({2, 0, 0}, 0, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "base", at(1)).transform,
                   isometry({2, 0, 0}, 0, kZ), kTolerance));
  putStatic(buffer, "world", "map", pose({0, 5, 0}, 0, kZ));
  putStatic(buffer, "map", "base", pose({3, 0, 0}, 0, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "base", at(1)).transform,
                   isometry({3, 5, 0}, 0, kZ), kTolerance));
  std::string parent;
  ASSERT_TRUE(buffer.getParent("base", at(1), parent));
  EXPECT_EQ(parent, "map");
}

TEST(BufferCoreInsert, AuthorityConflictsAreCountedAndShownInTheYamlDump) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({0, 0, 0}, 0, kZ), false, "alice");
  put(buffer, "world", "base", at(2), pose({0, 0, 0}, 0, kZ), false, "alice");
  put(buffer, "world", "arm", at(2), pose({0, 0, 0}, 0, kZ), false, "bob");
  EXPECT_EQ(buffer.statistics().authority_conflicts, 0u);
  put(buffer, "world", "base", at(3), pose({0, 0, 0}, 0, kZ), false, "bob");
  EXPECT_EQ(buffer.statistics().authority_conflicts, 1u);
  put(buffer, "world", "base", at(4), pose({0, 0, 0}, 0, kZ), false, "bob");
  EXPECT_EQ(buffer.statistics().authority_conflicts, 1u);
  put(buffer, "world", "base", at(5), pose({0, 0, 0}, 0, kZ), false, "alice");
  EXPECT_EQ(buffer.statistics().authority_conflicts, 2u);

  const std::string yaml = buffer.allFramesAsYaml();
  EXPECT_THAT(yaml, HasSubstr("'base':\n  parent: 'world'\n  authority: 'alice'\n"));
  EXPECT_THAT(yaml, HasSubstr("'arm':\n  parent: 'world'\n  authority: 'bob'\n"));
  const std::size_t base_entry = yaml.find("'base':");
  const std::size_t arm_entry = yaml.find("'arm':");
  ASSERT_NE(base_entry, std::string::npos);
  ASSERT_NE(arm_entry, std::string::npos);
  const std::string base_text = yaml.substr(base_entry, arm_entry - base_entry);
  EXPECT_THAT(base_text, HasSubstr("authority_conflicts: 2\n"));
  EXPECT_THAT(yaml.substr(arm_entry), HasSubstr("authority_conflicts: 0\n"));
}

// The buffer guesses each insert's child from the order of the inserts before: the edges of one
// cycle, then the same edges reordered, interleaved with another publisher's, with new frames
// among them, and under names that differ from the guess in a single byte anywhere.
TEST(BufferCoreInsert, EachSampleLandsOnItsOwnEdgeWhateverTheOrderOfInserts) {
  BufferCore buffer;
  std::vector<std::string> children;
  const std::string longest = "an_even_longer_joint_name_that_takes_more_than_forty_bytes_";
  for (const std::string stem : {"j", "joint_", "a_rather_longer_joint_name_", longest.c_str()}) {
    for (const char last : {'1', '2', '3'}) children.push_back(stem + last);
    children.push_back("x" + stem.substr(1) + "1");
  }
  std::map<std::string, double> newest;
  std::mt19937_64 random(11);
  std::vector<std::string> order = children;
  for (int round = 1; round <= 40; ++round) {
    if (round > 10) std::shuffle(order.begin(), order.end(), random);
    if (round == 20) order.insert(order.begin() + 3, "joint_4");
    for (std::size_t i = 0; i < order.size(); ++i) {
      const double x = round * 100.0 + static_cast<double>(i);
      put(buffer, "base", order[i], at(round), pose({x, 0, 0}, 0, kZ));
      newest[order[i]] = x;
      if (round % 3 == 0) {
        put(buffer, "map", "other_publisher_" + std::to_string(i % 2), at(round),
            pose({0, 0, 0}, 0, kZ));
      }
    }
    for (const auto& [child, x] : newest) {
      ASSERT_EQ(buffer.lookupTransform("base", child, at(round)).transform.translation.x(), x)
          << child << " in round " << round;
    }
  }
  EXPECT_EQ(buffer.getAllFrameNames().size(), children.size() + 5);
}

TEST(BufferCoreInsert, InsertedCountsEveryStoredSampleStaticOnesIncluded) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  putStatic(buffer, "base", "laser", pose({0, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.statistics().inserted, 3u);
  buffer.clear();
  EXPECT_EQ(buffer.statistics().inserted, 3u);
}

TEST(BufferCoreBatchInsert, StoresTheGoodTransformsAndCountsTheBadOnes) {
  BufferCore buffer;
  buffer.setErrorReporter(nullptr);
  std::vector<TransformStamped> batch{
      stamped("map", "odom", at(1), pose(Eigen::Vector3d(1, 0, 0), 0.0, Eigen::Vector3d::UnitZ())),
      stamped("odom", "base", at(1), pose(Eigen::Vector3d(0, 2, 0), 0.0, Eigen::Vector3d::UnitZ())),
      stamped("base", "base", at(1), pose(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::UnitZ())),
      stamped("base", "camera", at(1),
              pose(Eigen::Vector3d(0, 0, 3), 0.0, Eigen::Vector3d::UnitZ()))};
  batch[3].transform.translation.x() = std::numeric_limits<double>::quiet_NaN();
  std::string error;
  EXPECT_EQ(buffer.setTransforms(batch, "batcher", false, &error), 2u);
  EXPECT_THAT(error, HasSubstr("'base' cannot be its own parent"));
  EXPECT_EQ(buffer.statistics().inserted, 2u);
  EXPECT_EQ(buffer.statistics().rejectedCount(InsertRejection::kSelfParented), 1u);
  EXPECT_EQ(buffer.statistics().rejectedCount(InsertRejection::kNonFinite), 1u);
  EXPECT_FALSE(buffer.frameExists("camera"));
  EXPECT_TRUE(buffer.lookupTransform("map", "base", at(1))
                  .transform.isApprox(pose(Eigen::Vector3d(1, 2, 0), 0.0, Eigen::Vector3d::UnitZ()),
                                      1e-12));
}

// Rotations a little off unit length are normalized in a batch as one by one, each stored with
// its own value whatever the transforms refused or normalized before it.
TEST(BufferCoreBatchInsert, StoresEachTransformWithItsOwnValueAmongNormalizedAndRefusedOnes) {
  BufferCore buffer;
  buffer.setErrorReporter(nullptr);
  const Eigen::Quaterniond unit = axisAngle(0.8, Eigen::Vector3d(1, 2, 3));
  std::vector<TransformStamped> batch{stamped("world", "a", at(1), withTranslation(1, 0, 0)),
                                      stamped("world", "b", at(1), scaledRotation(1.0009)),
                                      stamped("world", "c", at(1), scaledRotation(0.5)),
                                      stamped("world", "d", at(1), scaledRotation(0.9991)),
                                      stamped("world", "e", at(1), withTranslation(0, 5, 0)),
                                      stamped("world", "f", at(1), scaledRotation(1.0005))};
  batch[1].transform.translation = Eigen::Vector3d(2, 0, 0);
  batch[3].transform.translation = Eigen::Vector3d(4, 0, 0);
  batch[5].transform.translation = Eigen::Vector3d(6, 0, 0);
  EXPECT_EQ(buffer.setTransforms(batch, "batcher"), 5u);
  EXPECT_EQ(buffer.statistics().normalized, 3u);
  EXPECT_EQ(buffer.statistics().rejectedCount(InsertRejection::kBadQuaternion), 1u);
  EXPECT_FALSE(buffer.frameExists("c"));
  for (const auto& [child, translation] :
       {std::pair{"a", Eigen::Vector3d(1, 0, 0)}, {"e", Eigen::Vector3d(0, 5, 0)}}) {
    const Transform stored = buffer.lookupTransform("world", child, at(1)).transform;
    EXPECT_EQ(stored.translation, translation) << child;
    EXPECT_EQ(stored.rotation.coeffs(), axisAngle(0.3, kZ).coeffs()) << child;
  }
  for (const auto& [child, x] : {std::pair{"b", 2.0}, {"d", 4.0}, {"f", 6.0}}) {
    const Transform stored = buffer.lookupTransform("world", child, at(1)).transform;
    EXPECT_EQ(stored.translation, Eigen::Vector3d(x, 0, 0)) << child;
    EXPECT_LE((stored.rotation.coeffs() - unit.coeffs()).cwiseAbs().maxCoeff(), 1e-15) << child;
  }
}

TEST(BufferCoreBatchInsert, TakesTheCountGivenFromAnArray) {
  BufferCore buffer;
  const TransformStamped batch[] = {
      stamped("map", "odom", at(1), pose(Eigen::Vector3d(1, 0, 0), 0.0, Eigen::Vector3d::UnitZ())),
      stamped("odom", "base", at(1), pose(Eigen::Vector3d(0, 2, 0), 0.0, Eigen::Vector3d::UnitZ())),
      stamped("base", "camera", at(1),
              pose(Eigen::Vector3d(0, 0, 3), 0.0, Eigen::Vector3d::UnitZ()))};
  EXPECT_EQ(buffer.setTransforms(batch, 0, "batcher"), 0u);
  EXPECT_EQ(buffer.frameCount(), 0u);
  EXPECT_EQ(buffer.setTransforms(batch, 2, "batcher"), 2u);
  EXPECT_EQ(buffer.statistics().inserted, 2u);
  EXPECT_TRUE(buffer.frameExists("base"));
  EXPECT_FALSE(buffer.frameExists("camera"));
}

TEST(BufferCoreBatchInsert, DecidesPendingRequestsOnceTheWholeBatchIsIn) {
  BufferCore buffer;
  int calls = 0;
  bool transformable_when_called = false;
  buffer.addTransformableRequest(
      [&](TransformableRequestHandle, const std::string&, const std::string&, TimePoint,
          TransformableResult result) {
        ++calls;
        transformable_when_called =
            result == TransformableResult::kAvailable && buffer.canTransform("map", "base", at(1));
      },
      "map", "base", at(1));
  EXPECT_EQ(
      buffer.setTransforms({stamped("map", "odom", at(1),
                                    pose(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::UnitZ())),
                            stamped("odom", "base", at(1),
                                    pose(Eigen::Vector3d::Zero(), 0.0, Eigen::Vector3d::UnitZ()))},
                           "batcher"),
      2u);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(transformable_when_called);
}

}  // namespace
}  // namespace lcmtf
