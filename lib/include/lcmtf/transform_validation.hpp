#pragma once

#include <string>

#include "lcmtf/insert_statistics.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf {

/// The checks setTransform makes on a transform alone: frame names, finite values, a unit
/// rotation. kCount when it may be stored, else the rejection, `reason` saying why.
/// `value` gets the transform to store: its rotation normalized (`normalized` set) when within
/// 1e-3 of unit length.
InsertRejection validateTransform(const TransformStamped& transform, Transform& value,
                                  bool& normalized, std::string& reason);
/// The same for a caller that only asks whether and why not.
InsertRejection validateTransform(const TransformStamped& transform, std::string* reason = nullptr);

}  // namespace lcmtf
