// lcmtf's BufferCore gives ROS tf2's answers. Random forests of frames (static and dynamic
// edges, edges that change parent once or twice, loops over part of the history, samples
// inserted out of order, late samples at and just past the edge of the history kept, histories
// long enough to be pruned, bad samples) are given to both libraries alike; then the same
// lookups, latest-time lookups, time-travel lookups, canTransform and parent questions go to
// both, and every answer must agree: the same value and stamp, or the same kind of error.
// Built where ROS tf2 is installed; the test command installs it.
//
// Left out on purpose, where lcmtf is specified to differ (README, "Where lcmtf differs from
// tf2"): a repeated stamp (tf2 keeps the first sample, lcmtf the newer one), names with a
// leading '/' (tf2 refuses them, lcmtf strips the slash), rotations slightly off unit length
// (tf2 refuses them, lcmtf normalizes those within 1e-3) and error messages. Two differences
// are allowed in the answers. Where the frames' trees do not meet, lcmtf reports them not
// connected even when an edge on the way also lacks data at the time asked, as it knows that
// edge's parent from its nearest sample; tf2 stops at such an edge and reports the missing
// data. And a name seen only in samples refused as too old is unknown to lcmtf, whose refusals
// change nothing; tf2 has added it to its frames by then.
#include <console_bridge/console.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>

#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/exceptions.hpp"
#include "support/test_scale.hpp"

namespace lcmtf {
namespace {

constexpr std::int64_t kSecond = 1'000'000;
constexpr std::int64_t kStart = 1'000 * kSecond;
constexpr std::int64_t kCacheTime = 10 * kSecond;

ros::Time rosTime(std::int64_t utime) {
  return ros::Time(static_cast<std::uint32_t>(utime / kSecond),
                   static_cast<std::uint32_t>(utime % kSecond * 1000));
}

std::int64_t utimeOf(const ros::Time& time) {
  return static_cast<std::int64_t>(time.sec) * kSecond + time.nsec / 1000;
}

// What a lookup gave: a value and its stamp, or the kind of error.
struct Outcome {
  enum Kind { kValue, kLookup, kConnectivity, kExtrapolation, kInvalidArgument, kOther };
  Kind kind = kOther;
  std::int64_t stamp = 0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  std::string message;

  std::string describe() const {
    static const char* const kNames[] = {"value",         "LookupException", "Connectivity",
                                         "Extrapolation", "InvalidArgument", "other error"};
    std::ostringstream text;
    text << kNames[kind];
    if (kind == kValue) {
      text << " at " << stamp << ": t [" << translation.transpose() << "] q ["
           << rotation.coeffs().transpose() << "]";
    } else {
      text << ": " << message;
    }
    return text.str();
  }
};

bool agree(const Outcome& ours, const Outcome& theirs) {
  const Outcome& a = ours;
  const Outcome& b = theirs;
  if (a.kind == Outcome::kConnectivity && b.kind == Outcome::kExtrapolation) return true;
  if (a.kind != b.kind) return false;
  if (a.kind != Outcome::kValue) return true;
  const double scale = 1.0 + a.translation.norm();
  return a.stamp == b.stamp && (a.translation - b.translation).norm() < 1e-9 * scale &&
         std::abs(a.rotation.dot(b.rotation)) > 1.0 - 1e-12;
}

template <class Lookup>
Outcome oursOf(Lookup lookup) {
  Outcome outcome;
  try {
    const TransformStamped result = lookup();
    outcome.kind = Outcome::kValue;
    outcome.stamp = toUtime(result.stamp);
    outcome.translation = result.transform.translation;
    outcome.rotation = result.transform.rotation;
  } catch (const LookupException& e) {
    outcome = {Outcome::kLookup, 0, {}, {}, e.what()};
  } catch (const ConnectivityException& e) {
    outcome = {Outcome::kConnectivity, 0, {}, {}, e.what()};
  } catch (const ExtrapolationException& e) {
    outcome = {Outcome::kExtrapolation, 0, {}, {}, e.what()};
  } catch (const InvalidArgumentException& e) {
    outcome = {Outcome::kInvalidArgument, 0, {}, {}, e.what()};
  } catch (const std::exception& e) {
    outcome = {Outcome::kOther, 0, {}, {}, e.what()};
  }
  return outcome;
}

template <class Lookup>
Outcome theirsOf(Lookup lookup) {
  Outcome outcome;
  try {
    const geometry_msgs::TransformStamped result = lookup();
    const auto& t = result.transform.translation;
    const auto& r = result.transform.rotation;
    outcome.kind = Outcome::kValue;
    outcome.stamp = utimeOf(result.header.stamp);
    outcome.translation = Eigen::Vector3d(t.x, t.y, t.z);
    outcome.rotation = Eigen::Quaterniond(r.w, r.x, r.y, r.z);
  } catch (const tf2::LookupException& e) {
    outcome = {Outcome::kLookup, 0, {}, {}, e.what()};
  } catch (const tf2::ConnectivityException& e) {
    outcome = {Outcome::kConnectivity, 0, {}, {}, e.what()};
  } catch (const tf2::ExtrapolationException& e) {
    outcome = {Outcome::kExtrapolation, 0, {}, {}, e.what()};
  } catch (const tf2::InvalidArgumentException& e) {
    outcome = {Outcome::kInvalidArgument, 0, {}, {}, e.what()};
  } catch (const std::exception& e) {
    outcome = {Outcome::kOther, 0, {}, {}, e.what()};
  }
  return outcome;
}

// One sample of an edge, as both libraries are given it.
struct Sample {
  std::string parent;
  std::string child;
  std::int64_t stamp = 0;
  Eigen::Vector3d translation;
  Eigen::Quaterniond rotation;
  bool is_static = false;
  std::int64_t arrival = 0;  // when it is given to the buffers, roughly
};

// A random forest: frame i's parent is a frame before it, so no loops form even as edges
// change parent, unless `loops` lets an edge's later parent be any other frame. Some frames
// have no edge and root trees of their own.
class RandomForest {
 public:
  RandomForest(unsigned seed, int frame_count, std::int64_t history,
               const std::string& prefix = "frame_", bool loops = false)
      : random_(seed), history_(history), loops_(loops) {
    for (int i = 0; i < frame_count; ++i) names_.push_back(prefix + std::to_string(i));
    for (int child = 1; child < frame_count; ++child) plan(child);
    std::shuffle(samples_.begin(), samples_.end(), random_);
    // Mostly in time order, as they arrive from a network, with some shuffled.
    std::stable_sort(samples_.begin(), samples_.end(), [](const Sample& a, const Sample& b) {
      return a.arrival / (kSecond / 2) < b.arrival / (kSecond / 2);
    });
    names_.push_back("unknown_frame");
  }

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<Sample>& samples() const { return samples_; }
  std::int64_t end() const { return kStart + history_; }

  // Now and then a name no sample has, or one only a refused sample has.
  std::string randomFrame() {
    const int pick = uniform(0, static_cast<int>(names_.size()) + 1);
    if (pick >= static_cast<int>(names_.size())) {
      return "refused_only_" + std::to_string(uniform(1, static_cast<int>(names_.size())));
    }
    return names_[static_cast<std::size_t>(pick)];
  }
  // The latest time a fifth of the time.
  std::int64_t randomTime() {
    const int pick = uniform(0, 9);
    if (pick <= 1) return 0;
    if (pick == 2 && !samples_.empty()) {
      return samples_[static_cast<std::size_t>(uniform(0, static_cast<int>(samples_.size()) - 1))]
          .stamp;
    }
    return kStart - kSecond / 2 +
           std::uniform_int_distribution<std::int64_t>(0, history_ + kSecond)(random_);
  }

 private:
  int uniform(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }
  double real(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random_);
  }
  Eigen::Quaterniond randomRotation() {
    Eigen::Quaterniond q(real(-1, 1), real(-1, 1), real(-1, 1), real(-1, 1));
    return q.normalized();
  }
  std::string randomParentOf(int child) {
    return names_[static_cast<std::size_t>(uniform(0, child - 1))];
  }

  void plan(int child) {
    const int kind = uniform(0, 9);
    if (kind == 0) return;  // a root of its own
    std::string parent = randomParentOf(child);
    if (kind <= 3) {
      samples_.push_back({parent, names_[static_cast<std::size_t>(child)], 0,
                          Eigen::Vector3d(real(-2, 2), real(-2, 2), real(-2, 2)), randomRotation(),
                          true});
      return;
    }
    if (kind == 4 && uniform(0, 3) == 0) {
      // A sender without a clock: one dynamic sample stamped 0, which sets no bound on the
      // latest common time.
      samples_.push_back({parent, names_[static_cast<std::size_t>(child)], 0,
                          Eigen::Vector3d(real(-2, 2), real(-2, 2), real(-2, 2)), randomRotation(),
                          false, 0});
      return;
    }
    // A dynamic edge: samples at its own rate over part or all of the history, turning by up to
    // a quarter turn between samples, and in some edges changing parent once, or twice and
    // back (with `loops`, a loop may then exist over the middle part of the history only).
    const std::int64_t period = kSecond / uniform(2, 50);
    const std::int64_t first = kStart + (uniform(0, 3) == 0 ? uniform(0, 10) * history_ / 20 : 0);
    const std::int64_t last = end() - (uniform(0, 3) == 0 ? uniform(0, 10) * history_ / 20 : 0);
    const int changes = uniform(0, 5);
    const std::int64_t reparent_at = changes >= 4 ? first + (last - first) / 3 : last + 1;
    const std::int64_t return_at = changes == 5 ? first + 2 * (last - first) / 3 : last + 1;
    std::string later_parent = randomParentOf(child);
    if (loops_) {
      const int other = uniform(0, static_cast<int>(names_.size()) - 2);
      later_parent = names_[static_cast<std::size_t>(other >= child ? other + 1 : other)];
    }
    auto parentAt = [&](std::int64_t stamp) {
      return stamp >= reparent_at && stamp < return_at ? later_parent : parent;
    };
    const std::string& name = names_[static_cast<std::size_t>(child)];
    Eigen::Vector3d translation(real(-2, 2), real(-2, 2), real(-2, 2));
    Eigen::Quaterniond rotation = randomRotation();
    std::int64_t newest = 0;
    std::set<std::int64_t> stamps;
    for (std::int64_t stamp = first + uniform(0, 1000); stamp <= last;
         stamp += period + uniform(-1000, 1000)) {
      translation += Eigen::Vector3d(real(-0.1, 0.1), real(-0.1, 0.1), real(-0.1, 0.1));
      rotation = (rotation * Eigen::Quaterniond(Eigen::AngleAxisd(
                                 real(-1.5, 1.5), randomRotation().vec().normalized())))
                     .normalized();
      // A few arrive late, some so late that their time has left the history kept.
      const std::int64_t delay = uniform(0, 50) == 0 ? uniform(1, 12) * kSecond : 0;
      samples_.push_back(
          {parentAt(stamp), name, stamp, translation, rotation, false, stamp + delay});
      newest = stamp;
      stamps.insert(stamp);
    }
    if (stamps.empty() || uniform(0, 2) != 0) return;
    // Once every sample above has arrived: one exactly at the oldest time the history keeps,
    // which both must take, and one a microsecond older, which both must refuse. Its parent is
    // a name no other sample has, some of the time.
    const std::int64_t boundary = newest - kCacheTime;
    const std::int64_t arrival = newest + 13 * kSecond;
    if (stamps.count(boundary) == 0) {
      samples_.push_back(
          {parentAt(boundary), name, boundary, translation, rotation, false, arrival});
    }
    const std::string refused_parent =
        uniform(0, 1) == 0 ? "refused_only_" + std::to_string(child) : parentAt(boundary - 1);
    if (stamps.count(boundary - 1) == 0) {
      samples_.push_back(
          {refused_parent, name, boundary - 1, translation, rotation, false, arrival});
    }
  }

  std::mt19937 random_;
  std::int64_t history_;
  bool loops_;
  std::vector<std::string> names_;
  std::vector<Sample> samples_;
};

class Tf2AgreementTest : public ::testing::TestWithParam<unsigned> {
 protected:
  static void SetUpTestSuite() {
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  }

  // Samples too old for the history are meant to be refused; both libraries are kept quiet.
  void SetUp() override {
    ours_.setErrorReporter([](const std::string&) {});
  }

  void insertAll(const RandomForest& forest) {
    for (const Sample& sample : forest.samples()) {
      insert(sample);
      if (HasFailure()) return;
    }
  }

  // Whether lcmtf took the sample, which tf2 must have done alike.
  bool insert(const Sample& sample) {
    TransformStamped ours{fromUtime(sample.stamp), sample.parent, sample.child,
                          Transform(sample.translation, sample.rotation)};
    geometry_msgs::TransformStamped theirs;
    theirs.header.stamp = rosTime(sample.stamp);
    theirs.header.frame_id = sample.parent;
    theirs.child_frame_id = sample.child;
    theirs.transform.translation.x = sample.translation.x();
    theirs.transform.translation.y = sample.translation.y();
    theirs.transform.translation.z = sample.translation.z();
    theirs.transform.rotation.x = sample.rotation.x();
    theirs.transform.rotation.y = sample.rotation.y();
    theirs.transform.rotation.z = sample.rotation.z();
    theirs.transform.rotation.w = sample.rotation.w();
    const bool ours_took = ours_.setTransform(ours, "test", sample.is_static);
    const bool theirs_took = theirs_.setTransform(theirs, "test", sample.is_static);
    EXPECT_EQ(ours_took, theirs_took)
        << sample.child << " -> " << sample.parent << " at " << sample.stamp;
    if (!ours_took) {
      for (const std::string* name : {&sample.parent, &sample.child}) {
        if (!ours_.frameExists(*name) && theirs_._frameExists(*name)) refused_only_.insert(*name);
      }
    }
    return ours_took;
  }

  // Whether a question names a frame that only refused samples have named: lcmtf does not know
  // it, and tf2 knows it with no edge (unless the question is of a frame in itself).
  bool namesRefusedOnly(std::initializer_list<const std::string*> frames) const {
    for (const std::string* frame : frames) {
      if (refused_only_.count(*frame) != 0) return true;
    }
    return false;
  }
  void expectRefusedOnlyUnknown(const std::string& question, const Outcome& ours,
                                const Outcome& theirs) {
    ++questions_;
    EXPECT_EQ(ours.kind, Outcome::kLookup) << question << "\n  lcmtf: " << ours.describe();
    EXPECT_NE(theirs.kind, Outcome::kValue) << question << "\n  tf2:   " << theirs.describe();
  }

  void expectAgreement(const std::string& question, const Outcome& ours, const Outcome& theirs) {
    ++questions_;
    if (ours.kind == Outcome::kValue) ++answered_;
    EXPECT_TRUE(agree(ours, theirs))
        << question << "\n  lcmtf: " << ours.describe() << "\n  tf2:   " << theirs.describe();
  }

  void askLookup(const std::string& target, const std::string& source, std::int64_t time) {
    const std::string question =
        "lookup of " + source + " in " + target + " at " + std::to_string(time);
    const Outcome ours =
        oursOf([&] { return ours_.lookupTransform(target, source, fromUtime(time)); });
    const Outcome theirs =
        theirsOf([&] { return theirs_.lookupTransform(target, source, rosTime(time)); });
    const bool ours_can = ours_.canTransform(target, source, fromUtime(time));
    const bool theirs_can = theirs_.canTransform(target, source, rosTime(time));
    if (target != source && namesRefusedOnly({&target, &source})) {
      expectRefusedOnlyUnknown(question, ours, theirs);
      EXPECT_FALSE(ours_can || theirs_can) << "canTransform for the " << question;
      return;
    }
    expectAgreement(question, ours, theirs);
    EXPECT_EQ(ours_can, theirs_can) << "canTransform for the " << question;
  }

  void askTimeTravel(const std::string& target, std::int64_t target_time, const std::string& source,
                     std::int64_t source_time, const std::string& fixed) {
    const std::string question = "time-travel lookup of " + source + " at " +
                                 std::to_string(source_time) + " in " + target + " at " +
                                 std::to_string(target_time) + " through " + fixed;
    const Outcome ours = oursOf([&] {
      return ours_.lookupTransform(target, fromUtime(target_time), source, fromUtime(source_time),
                                   fixed);
    });
    const Outcome theirs = theirsOf([&] {
      return theirs_.lookupTransform(target, rosTime(target_time), source, rosTime(source_time),
                                     fixed);
    });
    const bool ours_can =
        ours_.canTransform(target, fromUtime(target_time), source, fromUtime(source_time), fixed);
    const bool theirs_can =
        theirs_.canTransform(target, rosTime(target_time), source, rosTime(source_time), fixed);
    if (namesRefusedOnly({&target, &source, &fixed})) {
      // Each frame is looked up, even where the two halves are of a frame in itself.
      expectRefusedOnlyUnknown(question, ours, theirs);
      EXPECT_FALSE(ours_can) << "canTransform for the " << question;
      return;
    }
    expectAgreement(question, ours, theirs);
    EXPECT_EQ(ours_can, theirs_can) << "canTransform for the " << question;
  }

  void askAboutFrame(const std::string& frame, std::int64_t time) {
    EXPECT_EQ(ours_.frameExists(frame), theirs_._frameExists(frame) && !namesRefusedOnly({&frame}))
        << frame;
    std::string ours_parent;
    std::string theirs_parent;
    const bool ours_has = ours_.getParent(frame, fromUtime(time), ours_parent);
    const bool theirs_has = theirs_._getParent(frame, rosTime(time), theirs_parent);
    EXPECT_EQ(ours_has, theirs_has) << "parent of " << frame << " at " << time;
    if (ours_has && theirs_has) {
      EXPECT_EQ(ours_parent, theirs_parent) << frame << " at " << time;
    }
  }

  void askMany(RandomForest& forest, int count) {
    for (int i = 0; i < count && !HasFailure(); ++i) {
      askAboutFrame(forest.randomFrame(), forest.randomTime());
      askLookup(forest.randomFrame(), forest.randomFrame(), forest.randomTime());
      askTimeTravel(forest.randomFrame(), forest.randomTime(), forest.randomFrame(),
                    forest.randomTime(), forest.randomFrame());
    }
  }

  BufferCore ours_{std::chrono::seconds(10)};
  tf2::BufferCore theirs_{ros::Duration(10.0)};
  int questions_ = 0;
  int answered_ = 0;
  std::set<std::string> refused_only_;
};

TEST_P(Tf2AgreementTest, EveryAnswerMatchesTf2InARandomForest) {
  RandomForest forest(GetParam(), 16, 3 * kSecond);
  insertAll(forest);
  askMany(forest, 2000);
  // Enough questions have answers for the agreement to mean something.
  EXPECT_GT(answered_, questions_ / 20);
}

TEST_P(Tf2AgreementTest, EveryAnswerMatchesTf2AfterHistoryIsPruned) {
  RandomForest forest(GetParam() + 1000, 12, 25 * kSecond);
  insertAll(forest);
  askMany(forest, 1000);
  EXPECT_GT(answered_, questions_ / 20);
}

TEST_P(Tf2AgreementTest, EveryAnswerMatchesTf2AfterClear) {
  RandomForest before(GetParam() + 2000, 12, 3 * kSecond);
  insertAll(before);
  ours_.clear();
  theirs_.clear();
  // Static edges outlive clear() in both; the cleared frames stay known, with no data.
  RandomForest after(GetParam() + 3000, 12, 3 * kSecond, "later_");
  insertAll(after);
  askMany(after, 1000);
  askMany(before, 500);
  EXPECT_GT(answered_, questions_ / 20);
}

// A sample both libraries must refuse, made from a good one.
Sample flawed(Sample sample, int flaw) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (flaw % 6) {
    case 0:
      sample.parent = sample.child;
      break;
    case 1:
      sample.parent.clear();
      break;
    case 2:
      sample.child.clear();
      break;
    case 3:
      sample.translation.y() = nan;
      break;
    case 4:
      sample.rotation.coeffs() << 0, std::numeric_limits<double>::infinity(), 0, 1;
      break;
    default:
      sample.rotation.coeffs().setZero();
      break;
  }
  return sample;
}

TEST_P(Tf2AgreementTest, BadSamplesAreRefusedByBothAndChangeNoAnswer) {
  RandomForest forest(GetParam() + 5000, 12, 3 * kSecond);
  int flaw = 0;
  for (const Sample& sample : forest.samples()) {
    insert(sample);
    EXPECT_FALSE(insert(flawed(sample, flaw++)));
    if (HasFailure()) return;
  }
  askMany(forest, 500);
}

TEST_P(Tf2AgreementTest, EveryAnswerMatchesTf2WhenEdgesCloseLoops) {
  RandomForest forest(GetParam() + 4000, 12, 3 * kSecond, "frame_", true);
  insertAll(forest);
  askMany(forest, 1000);
  EXPECT_GT(answered_, questions_ / 20);
}

// Five kinds of forest for each seed: 500 forests in an optimized build.
INSTANTIATE_TEST_SUITE_P(
    Seeds, Tf2AgreementTest,
    ::testing::Range(1u, 1u + static_cast<unsigned>(lcmtf_test::scaledCount(100))));

}  // namespace
}  // namespace lcmtf
