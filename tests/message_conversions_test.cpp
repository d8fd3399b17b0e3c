#include "lcmtf/message_conversions.hpp"

#include <gtest/gtest.h>

#include "support/sample_messages.hpp"

namespace lcmtf {
namespace {

TEST(MessageConversions, TransformStampedToMessageCopiesEveryField) {
  const TransformStamped stamped{
      fromUtime(1'700'000'000'123'456), "map", "base_link",
      Transform(Eigen::Vector3d(1, -2, 3), Eigen::Quaterniond(0.5, -0.5, 0.5, -0.5))};
  const transform_t message = toMessage(stamped);
  EXPECT_EQ(message.utime, 1'700'000'000'123'456);
  EXPECT_EQ(message.parent_frame, "map");
  EXPECT_EQ(message.child_frame, "base_link");
  EXPECT_EQ(message.translation.x, 1.0);
  EXPECT_EQ(message.translation.y, -2.0);
  EXPECT_EQ(message.translation.z, 3.0);
  EXPECT_EQ(message.rotation.w, 0.5);
  EXPECT_EQ(message.rotation.x, -0.5);
  EXPECT_EQ(message.rotation.y, 0.5);
  EXPECT_EQ(message.rotation.z, -0.5);
}

TEST(MessageConversions, MessageRoundTripsThroughTransformStamped) {
  const transform_t original = lcmtf_test::sampleTransform(3);
  lcmtf_test::expectEqual(toMessage(fromMessage(original)), original);
}

TEST(MessageConversions, AMessageConvertedIntoAUsedTransformStampedReplacesAllOfIt) {
  TransformStamped out = fromMessage(lcmtf_test::sampleTransform(7));
  out.parent_frame += "_and_a_longer_name_than_the_next";
  const transform_t next = lcmtf_test::sampleTransform(2);
  fromMessage(next, out);
  lcmtf_test::expectEqual(toMessage(out), next);
}

TEST(MessageConversions, QuaternionKeepsScalarPartInW) {
  quaternion_t message{};
  message.x = 0.1;
  message.y = 0.2;
  message.z = 0.3;
  message.w = 0.9;
  const Eigen::Quaterniond q = fromMessage(message);
  EXPECT_EQ(q.w(), 0.9);
  EXPECT_EQ(q.x(), 0.1);
  EXPECT_EQ(q.y(), 0.2);
  EXPECT_EQ(q.z(), 0.3);
}

TEST(MessageConversions, MessageToIsometryMapsChildPointsIntoParent) {
  transform_t message = lcmtf_test::sampleTransform(0);
  message.translation = toMessage(Eigen::Vector3d(0, 0, 1));
  message.rotation = toMessage(
      Eigen::Quaterniond(Eigen::AngleAxisd(1.5707963267948966, Eigen::Vector3d::UnitZ())));
  const Eigen::Isometry3d parent_T_child = fromMessage(message).transform.toIsometry();
  EXPECT_TRUE(
      (parent_T_child * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, 1, 1), 1e-12));
}

TEST(MessageConversions, IsometryRoundTripsThroughTransformStampedAndMessage) {
  const Eigen::Isometry3d parent_T_child =
      Eigen::Translation3d(0.5, -1.5, 2.0) *
      Eigen::AngleAxisd(2.2, Eigen::Vector3d(1, -1, 0.5).normalized());
  const TransformStamped stamped =
      toTransformStamped(parent_T_child, fromUtime(42), "base_link", "camera");
  EXPECT_EQ(stamped.parent_frame, "base_link");
  EXPECT_EQ(stamped.child_frame, "camera");
  EXPECT_EQ(toUtime(stamped.stamp), 42);
  EXPECT_TRUE(toIsometry(stamped).isApprox(parent_T_child, 1e-12));

  const transform_t message = toMessage(parent_T_child, fromUtime(42), "base_link", "camera");
  EXPECT_EQ(message.parent_frame, "base_link");
  EXPECT_EQ(message.child_frame, "camera");
  EXPECT_EQ(message.utime, 42);
  EXPECT_TRUE(toIsometry(message).isApprox(parent_T_child, 1e-12));
  const Eigen::Vector3d point(1, 2, 3);
  EXPECT_LE((toIsometry(message) * point - parent_T_child * point).norm(), 1e-12);
}

}  // namespace
}  // namespace lcmtf
