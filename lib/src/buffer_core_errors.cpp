// Turning a LookupFailure into the message and exception a user sees.
#include "buffer_core_impl.hpp"

namespace lcmtf {

namespace {
std::string atTime(std::int64_t stamp) {
  return stamp == 0 ? std::string("at the latest common time") : "at " + toString(fromUtime(stamp));
}
}  // namespace

std::string BufferCore::Impl::describe(const LookupFailure& failure,
                                       const std::string& what) const {
  using Kind = LookupFailure::Kind;
  switch (failure.kind) {
    case Kind::kNone:
      return {};
    case Kind::kInvalidName:
      return what + ": invalid " + failure.role + " frame name '" + *failure.frame +
             "': frame names must not be empty";
    case Kind::kUnknownFrame:
      return what + ": " + failure.role + " frame '" +
             std::string(stripLeadingSlash(*failure.frame)) + "' does not exist";
    case Kind::kNotConnected:
      return what + ": " + quoted(failure.source) + " and " + quoted(failure.target) +
             " are not connected " + atTime(failure.requested) + ": " + quoted(failure.source) +
             " is in the tree of " + quoted(failure.edge_child) + ", " + quoted(failure.target) +
             " in the tree of " + quoted(failure.edge_parent);
    case Kind::kLoop: {
      std::string loop;
      const std::vector<FrameId> frames =
          findLoop(frames_, failure.loop_start, failure.requested, failure.requested == 0);
      for (FrameId frame : frames) loop += quoted(frame) + " -> ";
      if (!frames.empty()) loop += quoted(frames.front());
      return what + ": the frame tree has a loop " + atTime(failure.requested) + ": " + loop +
             " (each frame's parent in turn)";
    }
    case Kind::kPast:
    case Kind::kFuture: {
      const bool past = failure.kind == Kind::kPast;
      const std::int64_t gap = past ? detail::saturatingSubtract(failure.oldest, failure.requested)
                                    : detail::saturatingSubtract(failure.requested, failure.newest);
      return what + " " + atTime(failure.requested) + " would need extrapolation into the " +
             (past ? "past" : "future") + ": edge " + quoted(failure.edge_parent) + " -> " +
             quoted(failure.edge_child) + " has data from " + toString(fromUtime(failure.oldest)) +
             " to " + toString(fromUtime(failure.newest)) + ", the requested time is " +
             toString(Duration(gap)) + (past ? " before its oldest" : " after its newest") +
             " sample";
    }
    case Kind::kGap:
      return what + " " + atTime(failure.requested) + " falls in a gap in the data: edge " +
             quoted(failure.edge_parent) + " -> " + quoted(failure.edge_child) +
             " has samples at " + toString(fromUtime(failure.oldest)) + " and " +
             toString(fromUtime(failure.newest)) + ", " +
             toString(Duration(detail::saturatingSubtract(failure.newest, failure.oldest))) +
             " apart, more than the maximum interpolation gap of " + toString(Duration(max_gap_));
  }
  return what;
}

void BufferCore::Impl::raise(const LookupFailure& failure, const std::string& what) const {
  using Kind = LookupFailure::Kind;
  const std::string message = describe(failure, what);
  switch (failure.kind) {
    case Kind::kInvalidName:
      throw InvalidArgumentException(message);
    case Kind::kUnknownFrame:
    case Kind::kLoop:
      throw LookupException(message);
    case Kind::kNotConnected:
      throw ConnectivityException(message);
    case Kind::kPast:
      throw PastExtrapolationException(message);
    case Kind::kFuture:
      throw FutureExtrapolationException(message);
    case Kind::kGap:
      throw InterpolationGapException(message);
    case Kind::kNone:
      break;
  }
  throw TransformException(message);
}

}  // namespace lcmtf
