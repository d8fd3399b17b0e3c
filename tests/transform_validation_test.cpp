#include "lcmtf/transform_validation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "lcmtf/buffer_core.hpp"

namespace lcmtf {
namespace {

using testing::HasSubstr;

TransformStamped edge(const std::string& parent, const std::string& child,
                      const Eigen::Quaterniond& rotation = Eigen::Quaterniond::Identity()) {
  return {fromUtime(1'700'000'000'000'000), parent, child,
          Transform(Eigen::Vector3d(1, 2, 3), rotation)};
}

TEST(ValidateTransform, SaysWhatTheBufferWouldRefuseAndWhy) {
  std::string why;
  EXPECT_EQ(validateTransform(edge("/", "base"), &why), InsertRejection::kEmptyFrameName);
  EXPECT_THAT(why, HasSubstr("empty parent frame name"));
  EXPECT_EQ(validateTransform(edge("base", "/base"), &why), InsertRejection::kSelfParented);
  EXPECT_THAT(why, HasSubstr("frame 'base' cannot be its own parent"));
  TransformStamped nan = edge("odom", "base");
  nan.transform.translation.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validateTransform(nan, &why), InsertRejection::kNonFinite);
  EXPECT_EQ(validateTransform(edge("odom", "base", Eigen::Quaterniond(0, 0, 0, 0)), &why),
            InsertRejection::kBadQuaternion);
  EXPECT_EQ(validateTransform(edge("odom", "base", Eigen::Quaterniond(1.1, 0, 0, 0)), &why),
            InsertRejection::kBadQuaternion);
  EXPECT_THAT(why, HasSubstr("quaternion of norm 1.1"));
  EXPECT_EQ(validateTransform(edge("/odom", "base")), InsertRejection::kCount);
}

TEST(ValidateTransform, EveryCoordinateThatIsNotFiniteIsRefusedAndHugeOnesAreNot) {
  const double kNotFinite[] = {std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN()};
  for (int coordinate = 0; coordinate < 7; ++coordinate) {
    for (const double bad : kNotFinite) {
      TransformStamped transform = edge("odom", "base");
      double& value = coordinate < 3 ? transform.transform.translation[coordinate]
                                     : transform.transform.rotation.coeffs()[coordinate - 3];
      value = bad;
      EXPECT_EQ(validateTransform(transform), InsertRejection::kNonFinite)
          << "coordinate " << coordinate << " = " << bad;
    }
  }
  TransformStamped huge = edge("odom", "base");
  huge.transform.translation = {std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max()};
  EXPECT_EQ(validateTransform(huge), InsertRejection::kCount);
}

TEST(ValidateTransform, NearlyUnitRotationsAreNormalized) {
  Transform value;
  bool normalized = false;
  std::string why;
  EXPECT_EQ(validateTransform(edge("odom", "base", Eigen::Quaterniond(1.0005, 0, 0, 0)), value,
                              normalized, why),
            InsertRejection::kCount);
  EXPECT_TRUE(normalized);
  EXPECT_DOUBLE_EQ(value.rotation.w(), 1.0);
}

TEST(ValidateTransform, AgreesWithWhatTheBufferStores) {
  BufferCore buffer;
  for (const TransformStamped& transform :
       {edge("", "base"), edge("a", "a"), edge("odom", "base", Eigen::Quaterniond(2, 0, 0, 0)),
        edge("odom", "base")}) {
    const bool valid = validateTransform(transform) == InsertRejection::kCount;
    EXPECT_EQ(buffer.setTransform(transform, "test"), valid)
        << transform.parent_frame << " -> " << transform.child_frame;
  }
}

}  // namespace
}  // namespace lcmtf
