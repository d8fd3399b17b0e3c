#pragma once

#include <stdexcept>
#include <string>

namespace lcmtf {

/// Base of every error a lookup or transform can raise; what() names the frames and times.
class TransformException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A frame that the buffer has never heard of, or a loop in the tree (as tf2 reports it).
class LookupException : public TransformException {
 public:
  using TransformException::TransformException;
};

/// Two frames with no common ancestor at the requested time.
class ConnectivityException : public TransformException {
 public:
  using TransformException::TransformException;
};

/// The requested time lies outside the history of an edge on the path.
class ExtrapolationException : public TransformException {
 public:
  using TransformException::TransformException;
};

/// The requested time is older than the oldest sample of an edge on the path.
class PastExtrapolationException : public ExtrapolationException {
 public:
  using ExtrapolationException::ExtrapolationException;
};

/// The requested time is newer than the newest sample of an edge on the path.
class FutureExtrapolationException : public ExtrapolationException {
 public:
  using ExtrapolationException::ExtrapolationException;
};

/// The requested time falls between two samples of an edge further apart than the buffer's
/// maximum interpolation gap (BufferCore::setMaxInterpolationGap): data was lost or late there.
class InterpolationGapException : public ExtrapolationException {
 public:
  using ExtrapolationException::ExtrapolationException;
};

/// An argument that can never be valid: an empty frame name, NaN, a bad quaternion.
class InvalidArgumentException : public TransformException {
 public:
  using TransformException::TransformException;
};

/// Waiting for a transform ran out of time.
class TimeoutException : public TransformException {
 public:
  using TransformException::TransformException;
};

}  // namespace lcmtf
