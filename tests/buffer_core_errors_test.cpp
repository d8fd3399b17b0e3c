// BufferCore errors: which exception each failure raises, what its message says, and
// canTransform reporting the same without throwing.
#include "lcmtf/buffer_core.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;
using ::testing::AllOf;
using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::Not;

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

static_assert(std::is_base_of_v<std::runtime_error, TransformException>);
static_assert(std::is_base_of_v<TransformException, LookupException>);
static_assert(std::is_base_of_v<TransformException, ConnectivityException>);
static_assert(std::is_base_of_v<TransformException, ExtrapolationException>);
static_assert(std::is_base_of_v<ExtrapolationException, PastExtrapolationException>);
static_assert(std::is_base_of_v<ExtrapolationException, FutureExtrapolationException>);
static_assert(std::is_base_of_v<TransformException, InvalidArgumentException>);
static_assert(std::is_base_of_v<TransformException, TimeoutException>);

// The message of the exception `call` throws, failing the test unless it is an `Expected`.
template <class Expected>
std::string messageOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Expected& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw the wrong type: " << error.what();
    return {};
  }
  ADD_FAILURE() << "did not throw";
  return {};
}

// world -> base -> arm (dynamic 1 s to 3 s) -> hand (static); map -> dock.
class BufferCoreErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    putStatic(buffer_, "world", "base", pose({0, 0, 0.1}, 0, kZ));
    for (int i = 1; i <= 3; ++i) put(buffer_, "base", "arm", at(i), pose({0.1 * i, 0, 0}, 0, kZ));
    putStatic(buffer_, "arm", "hand", pose({0.3, 0, 0}, 0, kZ));
    put(buffer_, "map", "dock", at(2), pose({5, 5, 0}, 0, kZ));
  }
  BufferCore buffer_;
};

TEST_F(BufferCoreErrors, UnknownSourceFrameRaisesLookupExceptionNamingIt) {
  const std::string message =
      messageOf<LookupException>([&] { buffer_.lookupTransform("world", "ghost", at(2)); });
  EXPECT_THAT(message, HasSubstr("source frame 'ghost' does not exist"));
}

TEST_F(BufferCoreErrors, UnknownTargetFrameRaisesLookupExceptionNamingIt) {
  const std::string message =
      messageOf<LookupException>([&] { buffer_.lookupTransform("/phantom", "hand", at(2)); });
  EXPECT_THAT(message, HasSubstr("target frame 'phantom' does not exist"));
}

TEST_F(BufferCoreErrors, EveryQueryOfAnUnknownFrameRaisesLookupException) {
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.getLatestCommonTime("ghost", "arm"); }),
              HasSubstr("'ghost' does not exist"));
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.getFrameChain("arm", "ghost"); }),
              HasSubstr("'ghost' does not exist"));
  EXPECT_THAT(messageOf<LookupException>([&] {
                buffer_.lookupVelocity("ghost", "world", at(2), std::chrono::milliseconds(100));
              }),
              HasSubstr("'ghost' does not exist"));
  EXPECT_THAT(messageOf<LookupException>(
                  [&] { buffer_.lookupTransform("hand", at(2), "arm", at(2), "ghost"); }),
              HasSubstr("'ghost' does not exist"));
  EXPECT_THAT(messageOf<LookupException>(
                  [&] { buffer_.lookupTransform("hand", at(2), "ghost", at(2), "world"); }),
              HasSubstr("'ghost' does not exist"));
}

TEST_F(BufferCoreErrors, DisconnectedTreesRaiseConnectivityExceptionNamingBothFramesAndRoots) {
  const std::string message =
      messageOf<ConnectivityException>([&] { buffer_.lookupTransform("hand", "dock", at(2)); });
  EXPECT_THAT(message, HasSubstr("'dock' and 'hand' are not connected at " + toString(at(2))));
  EXPECT_THAT(message, HasSubstr("'dock' is in the tree of 'map'"));
  EXPECT_THAT(message, HasSubstr("'hand' in the tree of 'world'"));
}

TEST_F(BufferCoreErrors, DisconnectedTreesAtTheLatestTimeSayLatestAndNameTheRoots) {
  const std::string message =
      messageOf<ConnectivityException>([&] { buffer_.lookupTransform("map", "arm", kLatestTime); });
  EXPECT_THAT(message, HasSubstr("'arm' and 'map' are not connected at the latest common time"));
  EXPECT_THAT(message, HasSubstr("'arm' is in the tree of 'world'"));
  EXPECT_THAT(message, HasSubstr("'map' in the tree of 'map'"));
  EXPECT_THROW(buffer_.getLatestCommonTime("dock", "hand"), ConnectivityException);
  EXPECT_THROW(buffer_.getFrameChain("dock", "hand", at(2)), ConnectivityException);
}

TEST_F(BufferCoreErrors, FrameWithoutAnyEdgeIsNotConnectedToAnything) {
  buffer_.resolveFrame("lonely");
  EXPECT_THAT(
      messageOf<ConnectivityException>([&] { buffer_.lookupTransform("world", "lonely", at(2)); }),
      HasSubstr("'lonely' is in the tree of 'lonely', 'world' in the tree of 'world'"));
}

TEST_F(BufferCoreErrors, TimeBeforeTheHistoryRaisesPastExtrapolationNamingEdgeTimeAndRange) {
  const std::string message = messageOf<PastExtrapolationException>(
      [&] { buffer_.lookupTransform("world", "hand", at(0.5)); });
  EXPECT_THAT(message, HasSubstr("lookup of 'hand' in 'world' at " + toString(at(0.5))));
  EXPECT_THAT(message, HasSubstr("extrapolation into the past"));
  EXPECT_THAT(message, HasSubstr("edge 'base' -> 'arm' has data from " + toString(at(1)) + " to " +
                                 toString(at(3))));
  EXPECT_THAT(message, HasSubstr("0.500000 s before its oldest sample"));
  EXPECT_THROW(buffer_.lookupTransform("world", "hand", at(0.5)), ExtrapolationException);
  EXPECT_THROW(buffer_.lookupTransform("world", "hand", at(0.5)), TransformException);
}

TEST_F(BufferCoreErrors, TimeAfterTheHistoryRaisesFutureExtrapolationNamingEdgeTimeAndRange) {
  const std::string message = messageOf<FutureExtrapolationException>(
      [&] { buffer_.lookupTransform("hand", "base", at(3) + Duration(250)); });
  EXPECT_THAT(message,
              HasSubstr("lookup of 'base' in 'hand' at " + toString(at(3) + Duration(250))));
  EXPECT_THAT(message, HasSubstr("extrapolation into the future"));
  EXPECT_THAT(message, HasSubstr("edge 'base' -> 'arm' has data from " + toString(at(1)) + " to " +
                                 toString(at(3))));
  EXPECT_THAT(message, HasSubstr("0.000250 s after its newest sample"));
  EXPECT_THAT(message, Not(HasSubstr("past")));
}

TEST(BufferCoreExtrapolation, MessageNamesTheEdgeThatLacksDataNotItsNeighbours) {
  BufferCore buffer;
  put(buffer, "odom", "base", at(0), pose({0, 0, 0}, 0, kZ));
  put(buffer, "odom", "base", at(10), pose({1, 0, 0}, 0, kZ));
  put(buffer, "base", "head", at(4), pose({0, 0, 1}, 0, kZ));
  put(buffer, "base", "head", at(5), pose({0, 0, 1}, 0, kZ));
  putStatic(buffer, "head", "camera", pose({0, 0, 0.1}, 0, kZ));
  const std::string message = messageOf<FutureExtrapolationException>(
      [&] { buffer.lookupTransform("odom", "camera", at(6)); });
  EXPECT_THAT(message, HasSubstr("edge 'base' -> 'head' has data from " + toString(at(4)) + " to " +
                                 toString(at(5))));
  EXPECT_THAT(message, Not(HasSubstr("'odom' ->")));
  EXPECT_THAT(messageOf<PastExtrapolationException>(
                  [&] { buffer.lookupTransform("camera", "odom", at(3)); }),
              HasSubstr("edge 'base' -> 'head'"));
}

// A loop made by parent changes: at t = 2 a's parent becomes c, whose parent is b, whose parent
// is a. Until then world -> a -> b -> c is a chain.
class TreeWithALoop : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const double t : {1.0, 2.0}) {
      put(buffer_, "a", "b", at(t), pose({1, 0, 0}, 0, kZ));
      put(buffer_, "b", "c", at(t), pose({1, 0, 0}, 0, kZ));
      put(buffer_, "c", "d", at(t), pose({0, 1, 0}, 0, kZ));
    }
    put(buffer_, "world", "a", at(1), pose({0, 0, 1}, 0, kZ));
    put(buffer_, "c", "a", at(2), pose({1, 0, 0}, 0, kZ));
  }
  static ::testing::Matcher<const std::string&> listsTheLoop() {
    // Each frame followed by its parent, starting anywhere on the loop.
    return AllOf(HasSubstr("loop"),
                 AnyOf(HasSubstr("'a' -> 'c' -> 'b' -> 'a'"), HasSubstr("'c' -> 'b' -> 'a' -> 'c'"),
                       HasSubstr("'b' -> 'a' -> 'c' -> 'b'")),
                 Not(HasSubstr("'world' ->")), Not(HasSubstr("'d' ->")));
  }
  BufferCore buffer_;
};

TEST_F(TreeWithALoop, LookupThroughTheLoopRaisesLookupExceptionListingItsFrames) {
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.lookupTransform("world", "c", at(2)); }),
              listsTheLoop());
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.lookupTransform("c", "world", at(2)); }),
              listsTheLoop());
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.lookupTransform("world", "d", at(2)); }),
              listsTheLoop());
  EXPECT_THAT(
      messageOf<LookupException>([&] { buffer_.lookupTransform("world", "d", kLatestTime); }),
      listsTheLoop());
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.getLatestCommonTime("d", "world"); }),
              listsTheLoop());
}

TEST_F(TreeWithALoop, CanTransformThroughTheLoopSaysWhyNot) {
  std::string why;
  EXPECT_FALSE(buffer_.canTransform("world", "d", at(2), &why));
  EXPECT_THAT(why, listsTheLoop());
}

TEST_F(TreeWithALoop, BeforeTheParentChangeTheChainStillWorks) {
  const Eigen::Vector3d world_d(2, 1, 1);
  EXPECT_LE((buffer_.lookupTransform("world", "d", at(1)).transform.translation - world_d).norm(),
            1e-12);
  // Between the samples a keeps its older parent.
  EXPECT_LE((buffer_.lookupTransform("world", "d", at(1.5)).transform.translation - world_d).norm(),
            1e-12);
}

TEST_F(BufferCoreErrors, DisconnectedTreesStayNotConnectedWhereAnEdgeAlsoLacksData) {
  // arm has data from 1 s to 3 s only; it is in world's tree all the same.
  EXPECT_THAT(
      messageOf<ConnectivityException>([&] { buffer_.lookupTransform("dock", "hand", at(5)); }),
      HasSubstr("'hand' is in the tree of 'world', 'dock' in the tree of 'map'"));
  EXPECT_THROW(buffer_.lookupTransform("hand", "dock", at(5)), ConnectivityException);
}

// A loop that only an edge without data closes: c's parent is b, b's is a, and a's parent is
// c, but only from t = 4 on; d hangs off a. b and c have data from 1 s to 5 s.
class LoopClosedLater : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const double t : {1.0, 5.0}) {
      put(buffer_, "a", "b", at(t), pose({1, 0, 0}, 0, kZ));
      put(buffer_, "b", "c", at(t), pose({0, 1, 0}, 0, kZ));
    }
    putStatic(buffer_, "a", "d", pose({0, 0, 1}, 0, kZ));
    for (const double t : {4.0, 5.0}) put(buffer_, "c", "a", at(t), pose({0, 0, 2}, 0, kZ));
  }
  BufferCore buffer_;
};

TEST_F(LoopClosedLater, BeforeTheLoopClosesFramesBelowItsOpenEdgeConnect) {
  // c climbs to a, whose edge has no data at 2 s; d meets it there.
  EXPECT_LE(
      (buffer_.lookupTransform("d", "c", at(2)).transform.translation - Eigen::Vector3d(1, 1, -1))
          .norm(),
      1e-12);
  EXPECT_LE(
      (buffer_.lookupTransform("c", "d", at(2)).transform.translation - Eigen::Vector3d(-1, -1, 1))
          .norm(),
      1e-12);
  EXPECT_TRUE(buffer_.canTransform("d", "c", at(2)));
}

TEST_F(LoopClosedLater, OnceTheLoopIsClosedLookupsThroughItRaiseLookupException) {
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.lookupTransform("d", "c", at(4.5)); }),
              HasSubstr("'c' -> 'b' -> 'a' -> 'c'"));
}

TEST_F(LoopClosedLater, BeyondTheOpenEdgeTheMissingDataIsTheError) {
  // Climbing on from a would only go round the loop that a's nearest sample closes.
  buffer_.resolveFrame("elsewhere");
  EXPECT_THAT(messageOf<PastExtrapolationException>(
                  [&] { buffer_.lookupTransform("d", "elsewhere", at(2)); }),
              HasSubstr("edge 'c' -> 'a'"));
  EXPECT_THAT(messageOf<PastExtrapolationException>(
                  [&] { buffer_.lookupTransform("elsewhere", "d", at(2)); }),
              HasSubstr("edge 'c' -> 'a'"));
}

// A loop that only the older sample of a re-parented edge closes: b hangs from a at 1 s and
// from z at 3 s, a from b at 1 s and 3 s; s and u are fixed to a. Between 1 s and 3 s b keeps
// its older parent, a, so a and b are each other's parent; from 3 s on there is no loop.
class LoopClosedByAnOlderSample : public ::testing::Test {
 protected:
  void SetUp() override {
    put(buffer_, "b", "a", at(1), pose({1, 0, 0}, 0, kZ));
    put(buffer_, "b", "a", at(3), pose({1, 0, 0}, 0, kZ));
    put(buffer_, "a", "b", at(1), pose({0, 1, 0}, 0, kZ));
    put(buffer_, "z", "b", at(3), pose({0, 0, 1}, 0, kZ));
    putStatic(buffer_, "a", "s", pose({0, 0, 5}, 0, kZ));
    putStatic(buffer_, "a", "u", pose({0, 6, 0}, 0, kZ));
  }
  BufferCore buffer_;
};

TEST_F(LoopClosedByAnOlderSample, LookupWhileTheLoopExistsRaisesLookupException) {
  EXPECT_THAT(messageOf<LookupException>([&] { buffer_.lookupTransform("s", "u", at(2)); }),
              AllOf(HasSubstr("loop"),
                    AnyOf(HasSubstr("'a' -> 'b' -> 'a'"), HasSubstr("'b' -> 'a' -> 'b'"))));
  EXPECT_FALSE(buffer_.canTransform("s", "u", at(2)));
  EXPECT_THROW(buffer_.lookupTransform("s", at(3), "u", at(2), "z"), LookupException);
  EXPECT_NO_THROW(buffer_.lookupTransform("s", at(3), "u", at(2), "a"));
}

TEST_F(LoopClosedByAnOlderSample, OnceTheLoopIsGoneTheSameLookupAnswers) {
  EXPECT_LE(
      (buffer_.lookupTransform("s", "u", at(3)).transform.translation - Eigen::Vector3d(0, 6, -5))
          .norm(),
      1e-12);
  EXPECT_EQ(buffer_.lookupTransform("s", "u", kLatestTime).stamp, TimePoint{});
  EXPECT_TRUE(buffer_.canTransform("s", "u", at(3)));
}

TEST_F(BufferCoreErrors, EmptyFrameNamesRaiseInvalidArgumentException) {
  const auto invalid = [](const std::function<void()>& call) {
    return messageOf<InvalidArgumentException>(call);
  };
  EXPECT_THAT(invalid([&] { buffer_.lookupTransform("", "arm", at(2)); }),
              HasSubstr("invalid target frame name ''"));
  EXPECT_THAT(invalid([&] { buffer_.lookupTransform("arm", "", at(2)); }),
              HasSubstr("invalid source frame name ''"));
  EXPECT_THAT(invalid([&] { buffer_.lookupTransform("/", "arm", at(2)); }),
              HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.lookupTransform("", "", at(2)); }),
              HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.lookupTransform("hand", at(2), "arm", at(2), ""); }),
              HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.getLatestCommonTime("arm", ""); }),
              HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.getFrameChain("", "arm"); }), HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.resolveFrame(""); }), HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.resolveFrame("/"); }), HasSubstr("must not be empty"));
  EXPECT_THAT(
      invalid([&] { buffer_.lookupVelocity("", "world", at(2), std::chrono::milliseconds(100)); }),
      HasSubstr("must not be empty"));
  EXPECT_THAT(invalid([&] { buffer_.addTransformableRequest([](auto&&...) {}, "", "arm", at(2)); }),
              HasSubstr("must not be empty"));
  EXPECT_FALSE(buffer_.findFrame(""));
  EXPECT_FALSE(buffer_.frameExists(""));
}

TEST_F(BufferCoreErrors, NullOrForeignFrameHandlesRaiseInvalidArgumentException) {
  const FrameHandle arm = buffer_.findFrame("arm");
  EXPECT_THROW(buffer_.lookupTransform(FrameHandle{}, arm, at(2)), InvalidArgumentException);
  EXPECT_THROW(buffer_.lookupTransform(arm, FrameHandle{9999}, at(2)), InvalidArgumentException);
  std::string why;
  EXPECT_FALSE(buffer_.canTransform(arm, FrameHandle{}, at(2), &why));
  EXPECT_THAT(why, HasSubstr("frame handle"));
}

TEST_F(BufferCoreErrors, NonPositiveVelocityIntervalRaisesInvalidArgumentException) {
  EXPECT_THAT(messageOf<InvalidArgumentException>(
                  [&] { buffer_.lookupVelocity("arm", "world", at(2), Duration(0)); }),
              HasSubstr("averaging interval must be positive"));
  EXPECT_THROW(buffer_.lookupVelocity("arm", "world", at(2), Duration(-5)),
               InvalidArgumentException);
}

// Each failing query once as a lookup (its message) and once as canTransform (its `why`).
struct FailingQuery {
  std::string target;
  std::string source;
  TimePoint time;
};

TEST_F(BufferCoreErrors, CanTransformNeverThrowsAndSaysWhyWithTheLookupsMessage) {
  putStatic(buffer_, "loop_a", "loop_b", pose({0, 0, 0}, 0, kZ));
  putStatic(buffer_, "loop_b", "loop_a", pose({0, 0, 0}, 0, kZ));
  const std::vector<FailingQuery> queries{
      {"world", "ghost", at(2)},  {"ghost", "world", kLatestTime}, {"", "arm", at(2)},
      {"arm", "/", at(2)},        {"hand", "dock", at(2)},         {"dock", "hand", kLatestTime},
      {"world", "hand", at(0.5)}, {"hand", "world", at(4)},        {"world", "loop_a", at(2)},
  };
  for (const FailingQuery& query : queries) {
    std::string message;
    try {
      buffer_.lookupTransform(query.target, query.source, query.time);
      ADD_FAILURE() << "lookup did not throw for '" << query.source << "' in '" << query.target
                    << "'";
    } catch (const TransformException& error) {
      message = error.what();
    }
    std::string why;
    bool can = true;
    EXPECT_NO_THROW(can = buffer_.canTransform(query.target, query.source, query.time, &why));
    EXPECT_FALSE(can);
    EXPECT_EQ(why, message);
    EXPECT_NO_THROW(can = buffer_.canTransform(query.target, query.source, query.time));
    EXPECT_FALSE(can);
  }
}

TEST_F(BufferCoreErrors, TimeTravelCanTransformNeverThrowsAndSaysWhyWithTheLookupsMessage) {
  const std::vector<std::vector<std::string>> frames{
      {"hand", "arm", "ghost"}, {"hand", "ghost", "world"}, {"dock", "arm", "world"},
      {"hand", "arm", ""},      {"hand", "dock", "map"},
  };
  for (const TimePoint target_time : {at(2), at(5)}) {
    for (const auto& names : frames) {
      std::string message;
      try {
        buffer_.lookupTransform(names[0], target_time, names[1], at(2.5), names[2]);
        ADD_FAILURE() << "lookup did not throw";
      } catch (const TransformException& error) {
        message = error.what();
      }
      std::string why;
      bool can = true;
      EXPECT_NO_THROW(
          can = buffer_.canTransform(names[0], target_time, names[1], at(2.5), names[2], &why));
      EXPECT_FALSE(can);
      EXPECT_EQ(why, message);
    }
  }
  // Good data at the source time, none at the target time.
  std::string why;
  EXPECT_FALSE(buffer_.canTransform("hand", at(5), "arm", at(2.5), "world", &why));
  EXPECT_THAT(why, HasSubstr("future"));
  EXPECT_TRUE(buffer_.canTransform("hand", at(3), "arm", at(1), "world", &why));
}

TEST_F(BufferCoreErrors, CanTransformSucceedsWhereTheLookupSucceeds) {
  std::string why;
  EXPECT_TRUE(buffer_.canTransform("world", "hand", at(2), &why));
  EXPECT_TRUE(buffer_.canTransform("world", "hand", kLatestTime));
  EXPECT_TRUE(buffer_.canTransform("dock", "map", at(2)));
  EXPECT_TRUE(buffer_.canTransform("ghost", "ghost", at(2)));  // as tf2: a frame in itself
  EXPECT_NO_THROW(buffer_.lookupTransform("world", "hand", at(2)));
}

TEST_F(BufferCoreErrors, AFrameInItselfIsTheIdentityWhetherOrNotItIsKnownButNoNameIsNoFrame) {
  for (const auto& [target, source] :
       {std::pair<std::string, std::string>{"hand", "/hand"}, {"/ghost", "ghost"}}) {
    EXPECT_TRUE(buffer_.canTransform(target, source, at(2))) << target << " " << source;
    const TransformStamped t = buffer_.lookupTransform(target, source, at(2));
    EXPECT_TRUE(t.transform.isApprox(Transform::identity(), 0.0)) << target << " " << source;
    EXPECT_EQ(t.parent_frame, t.child_frame);
  }
  std::string why;
  EXPECT_FALSE(buffer_.canTransform("/", "", at(2), &why));
  EXPECT_THAT(why, HasSubstr("invalid"));
  EXPECT_FALSE(buffer_.canTransform("ghost", "spectre", at(2), &why));
  EXPECT_THAT(why, HasSubstr("ghost"));
}

}  // namespace
}  // namespace lcmtf
