#include <algorithm>

#include "buffer_core_impl.hpp"

namespace lcmtf {

LookupFailure BufferCore::Impl::commonTimeRange(FrameId target, FrameId source,
                                                std::int64_t& oldest, std::int64_t& newest) const {
  std::vector<PathEdge> source_edges;
  std::vector<PathEdge> target_edges;
  FrameId ancestor = kNoFrame;
  oldest = 0;
  newest = 0;
  if (target == source) return {};
  LookupFailure failure = walk(target, source, 0, source_edges, target_edges, &ancestor);
  if (failure) return failure;
  bool any_dynamic = false;
  for (const auto* edges : {&source_edges, &target_edges}) {
    for (const PathEdge& edge : *edges) {
      if (!edge.isDynamic()) continue;
      const detail::TimeCache& cache = frames_[edge.child].cache;
      oldest = any_dynamic ? std::max(oldest, cache.oldestStamp()) : cache.oldestStamp();
      newest = any_dynamic ? std::min(newest, cache.newestStamp()) : cache.newestStamp();
      any_dynamic = true;
    }
  }
  return {};
}

Velocity BufferCore::lookupVelocity(const std::string& tracking, const std::string& observation,
                                    TimePoint time, Duration averaging_interval) const {
  const std::string what = "velocity of '" + tracking + "' relative to '" + observation + "'";
  if (averaging_interval <= Duration::zero()) {
    throw InvalidArgumentException(what + ": the averaging interval must be positive, not " +
                                   toString(averaging_interval));
  }
  std::int64_t oldest = 0;
  std::int64_t newest = 0;
  {
    SharedLock lock(impl_->lock_);
    FrameId observation_id = kNoFrame;
    FrameId tracking_id = kNoFrame;
    LookupFailure failure = impl_->resolve(observation, "observation", observation_id);
    if (!failure) failure = impl_->resolve(tracking, "tracking", tracking_id);
    if (!failure) failure = impl_->commonTimeRange(observation_id, tracking_id, oldest, newest);
    if (failure) impl_->raise(failure, what);
  }

  Velocity velocity;
  velocity.frame = std::string(stripLeadingSlash(observation));
  const bool all_static = oldest == 0 && newest == 0;
  const std::int64_t centre = time == kLatestTime ? newest : toUtime(time);
  velocity.stamp = fromUtime(centre);
  if (all_static) return velocity;

  const std::int64_t half = averaging_interval.count() / 2;
  const std::int64_t start = std::max(detail::saturatingSubtract(centre, half), oldest);
  const std::int64_t end =
      std::min(detail::saturatingSubtract(centre, half - averaging_interval.count()), newest);
  if (end <= start) {
    throw ExtrapolationException(what + " at " + toString(fromUtime(centre)) +
                                 ": no data around that time; the edges " +
                                 "between them have data from " + toString(fromUtime(oldest)) +
                                 " to " + toString(fromUtime(newest)));
  }
  const Transform before = lookupTransform(observation, tracking, fromUtime(start)).transform;
  const Transform after = lookupTransform(observation, tracking, fromUtime(end)).transform;
  const double seconds = toSeconds(Duration(end - start));
  velocity.linear = (after.translation - before.translation) / seconds;
  Eigen::AngleAxisd turn(after.rotation * before.rotation.conjugate());
  if (turn.angle() > 3.14159265358979323846) turn.angle() -= 2 * 3.14159265358979323846;
  velocity.angular = turn.axis() * (turn.angle() / seconds);
  return velocity;
}

}  // namespace lcmtf
