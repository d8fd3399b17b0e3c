// Transformable requests: callbacks for when a lookup becomes possible, or never will.
#include <optional>

#include "buffer_core_impl.hpp"

namespace lcmtf {

TransformableRequestHandle BufferCore::addTransformableRequest(TransformableCallback callback,
                                                               const std::string& target,
                                                               const std::string& source,
                                                               TimePoint time) const {
  if (stripLeadingSlash(target).empty() || stripLeadingSlash(source).empty()) {
    throw InvalidArgumentException("addTransformableRequest: frame names must not be empty");
  }
  // Holding requests_mutex_ across the check means no insert can slip between the check and
  // the registration without seeing the request.
  std::lock_guard<std::mutex> guard(impl_->requests_mutex_);
  if (canTransform(target, source, time)) return 0;
  const TransformableRequestHandle handle = impl_->next_request_++;
  impl_->requests_.emplace(handle, TransformableRequest{std::move(callback), target, source, time});
  impl_->has_requests_.store(true, std::memory_order_release);
  return handle;
}

void BufferCore::cancelTransformableRequest(TransformableRequestHandle handle) const {
  std::lock_guard<std::mutex> guard(impl_->requests_mutex_);
  impl_->requests_.erase(handle);
  impl_->has_requests_.store(!impl_->requests_.empty(), std::memory_order_release);
}

std::vector<std::function<void()>> BufferCore::Impl::collectDecidedRequests() {
  std::vector<std::function<void()>> decided;
  std::lock_guard<std::mutex> guard(requests_mutex_);
  SharedLock lock(lock_);
  for (auto request = requests_.begin(); request != requests_.end();) {
    TransformableRequest& r = request->second;
    if (r.target_id == kNoFrame) r.target_id = idOf(stripLeadingSlash(r.target));
    if (r.source_id == kNoFrame) r.source_id = idOf(stripLeadingSlash(r.source));
    std::optional<TransformableResult> result;
    if (r.target_id != kNoFrame && r.source_id != kNoFrame) {
      std::int64_t wanted = toUtime(r.time);
      std::int64_t latest = 0;
      if (r.target_id == r.source_id || !lookup(r.target_id, r.source_id, wanted, nullptr)) {
        result = TransformableResult::kAvailable;
      } else if (wanted != 0 && !latestCommonTime(r.target_id, r.source_id, latest) &&
                 latest != 0 && wanted < detail::saturatingSubtract(latest, cache_time_)) {
        result = TransformableResult::kFailure;
      }
    }
    if (!result) {
      ++request;
      continue;
    }
    decided.push_back(
        [callback = std::move(request->second.callback), handle = request->first,
         target_name = r.target, source_name = r.source, time = r.time,
         outcome = *result] { callback(handle, target_name, source_name, time, outcome); });
    request = requests_.erase(request);
  }
  has_requests_.store(!requests_.empty(), std::memory_order_release);
  return decided;
}

}  // namespace lcmtf
