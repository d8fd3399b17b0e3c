#include "lcmtf/nodes/tf_traffic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf/programs/saturating.hpp"
#include "lcmtf/transform_validation.hpp"

namespace lcmtf::nodes {

namespace {

std::string bareName(const std::string& name) { return std::string(canonicalFrameName(name)); }

double secondsBetween(std::int64_t from, std::int64_t to) {
  return static_cast<double>(to - from) * 1e-6;
}

// Events per second between the first and the last of `count` events.
double ratePerSecond(std::size_t count, std::int64_t first, std::int64_t last) {
  if (count < 2 || last <= first) return 0.0;
  return static_cast<double>(count - 1) / secondsBetween(first, last);
}

// receive time minus stamp, in seconds; stamps from the network may be anything.
double delaySeconds(std::int64_t received, std::int64_t stamp) {
  return (static_cast<double>(received) - static_cast<double>(stamp)) * 1e-6;
}

// The oldest stamp a Buffer keeps behind `newest`, without overflowing on hostile stamps.
TimePoint historyStart(TimePoint newest, Duration cache_time) {
  return fromUtime(programs::saturatingSubtract(toUtime(newest), cache_time.count()));
}

struct DelayStatistics {
  std::size_t count = 0;
  double sum = 0.0;
  double max = -HUGE_VAL;

  void add(double delay) {
    ++count;
    sum += delay;
    max = std::max(max, delay);
  }
  double average() const { return count ? sum / static_cast<double>(count) : 0.0; }
  double maximum() const { return count ? max : 0.0; }
};

}  // namespace

TfTraffic::TfTraffic(TrafficLimits limits) : limits_(limits) {}

void TfTraffic::noteProblem(const std::string& kind, const std::string& description) {
  problems_.emplace(kind, description);
}

bool TfTraffic::validate(const transform_t& transform, const std::string& authority) {
  std::string why;
  if (validateTransform(fromMessage(transform), &why) == InsertRejection::kCount) return true;
  ++invalid_;
  noteProblem("invalid", "invalid transforms (first, from '" + authority + "': " + why + ")");
  return false;
}

void TfTraffic::record(const tf_message_t& batch, bool is_static, TimePoint received) {
  ++messages_;
  auto sender = sender_ids_.find(batch.authority);
  if (sender == sender_ids_.end()) {
    if (senders_.size() >= limits_.max_authorities) {
      refused_ += batch.transforms.size();
      noteProblem("authorities", "transforms refused beyond " +
                                     std::to_string(limits_.max_authorities) +
                                     " authorities (first: '" + batch.authority + "')");
      return;
    }
    sender =
        sender_ids_.emplace(batch.authority, static_cast<std::uint32_t>(senders_.size())).first;
    senders_.push_back(Sender{batch.authority, {}, {}, {}});
  }
  const std::int64_t received_utime = toUtime(received);
  Sender& from = senders_[sender->second];
  from.batches_received.push_back(received_utime);
  (is_static ? from.static_sequence : from.dynamic_sequence).observe(batch.sequence);
  for (const transform_t& transform : batch.transforms) {
    if (!validate(transform, batch.authority)) continue;
    const std::string parent = bareName(transform.parent_frame);
    const std::string child = bareName(transform.child_frame);
    auto key = std::make_tuple(child, parent, is_static);
    auto edge = edges_.find(key);
    if (edge == edges_.end()) {
      if (edges_.size() >= limits_.max_edges) {
        ++refused_;
        noteProblem("edges", "transforms refused beyond " + std::to_string(limits_.max_edges) +
                                 " edges (first: '" + parent + "' -> '" + child + "')");
        continue;
      }
      edge = edges_.emplace(std::move(key), Edge{parent, child, is_static, {}}).first;
    }
    std::deque<Arrival>& arrivals = edge->second.arrivals;
    if (arrivals.size() >= limits_.max_arrivals_per_edge) {
      arrivals.pop_front();
      --arrivals_;
    }
    if (arrivals_ >= limits_.max_arrivals) {
      ++refused_;
      noteProblem("arrivals", "transforms refused beyond " + std::to_string(limits_.max_arrivals) +
                                  " held at once (first: '" + parent + "' -> '" + child + "')");
      continue;
    }
    arrivals.push_back(Arrival{received_utime, transform.utime, sender->second});
    ++arrivals_;
  }
}

void TfTraffic::recordMalformed(const std::string& channel, const std::string& error) {
  ++malformed_;
  noteProblem("malformed", "malformed messages (first, on " + channel + ": " + error + ")");
}

void TfTraffic::forgetBefore(TimePoint cutoff) {
  const std::int64_t limit = toUtime(cutoff);
  for (auto& [key, edge] : edges_) {
    while (!edge.arrivals.empty() && edge.arrivals.front().received < limit) {
      edge.arrivals.pop_front();
      --arrivals_;
    }
  }
  for (Sender& sender : senders_) {
    while (!sender.batches_received.empty() && sender.batches_received.front() < limit) {
      sender.batches_received.pop_front();
    }
  }
}

struct TfTraffic::WindowTally {
  struct SenderOfFrame {
    std::set<std::string> parents;
    bool is_static = false;
    bool is_dynamic = false;
    std::size_t transforms = 0;
  };
  std::map<std::uint32_t, DelayStatistics> delays_by_sender;
  std::map<std::uint32_t, std::set<std::string>> frames_by_sender;
  std::map<std::string, std::map<std::uint32_t, SenderOfFrame>> senders_by_child;

  void add(const Edge& edge, const Arrival& arrival) {
    frames_by_sender[arrival.authority].insert(edge.child);
    if (!edge.is_static) {
      delays_by_sender[arrival.authority].add(delaySeconds(arrival.received, arrival.stamp));
    }
    SenderOfFrame& sender = senders_by_child[edge.child][arrival.authority];
    sender.parents.insert(edge.parent);
    (edge.is_static ? sender.is_static : sender.is_dynamic) = true;
    ++sender.transforms;
  }
};

EdgeTraffic TfTraffic::summarizeEdge(const Edge& edge, std::int64_t start, std::int64_t end,
                                     Duration cache_time, WindowTally& tally) const {
  EdgeTraffic summary;
  summary.parent = edge.parent;
  summary.child = edge.child;
  summary.is_static = edge.is_static;
  std::map<std::uint32_t, std::size_t> per_sender;
  DelayStatistics delays;
  std::int64_t first = 0;
  std::int64_t last = 0;
  std::vector<std::int64_t> stamps;
  for (const Arrival& arrival : edge.arrivals) {
    stamps.push_back(arrival.stamp);
    if (arrival.received < start || arrival.received > end) continue;
    if (summary.samples++ == 0) first = arrival.received;
    last = arrival.received;
    ++per_sender[arrival.authority];
    if (!edge.is_static) delays.add(delaySeconds(arrival.received, arrival.stamp));
    tally.add(edge, arrival);
  }
  summary.rate_hz = ratePerSecond(summary.samples, first, last);
  summary.last_received = fromUtime(last);
  summary.average_delay_s = delays.average();
  summary.max_delay_s = delays.maximum();
  std::vector<std::pair<std::size_t, std::uint32_t>> by_count;
  for (const auto& [sender, count] : per_sender) by_count.emplace_back(count, sender);
  std::stable_sort(by_count.begin(), by_count.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [count, sender] : by_count) summary.authorities.push_back(senders_[sender].name);

  std::sort(stamps.begin(), stamps.end());
  stamps.erase(std::unique(stamps.begin(), stamps.end()), stamps.end());
  if (!stamps.empty()) {
    const TimePoint newest = fromUtime(stamps.back());
    const auto oldest_kept = edge.is_static
                                 ? stamps.end() - 1
                                 : std::lower_bound(stamps.begin(), stamps.end(),
                                                    toUtime(historyStart(newest, cache_time)));
    summary.oldest_stamp = fromUtime(*oldest_kept);
    summary.newest_stamp = newest;
    summary.buffered = static_cast<std::size_t>(stamps.end() - oldest_kept);
  }
  return summary;
}

AuthorityTraffic TfTraffic::summarizeSender(std::uint32_t id, std::int64_t start, std::int64_t end,
                                            const WindowTally& tally) const {
  AuthorityTraffic summary;
  summary.authority = senders_[id].name;
  std::int64_t first = 0;
  std::int64_t last = 0;
  for (std::int64_t received : senders_[id].batches_received) {
    if (received < start || received > end) continue;
    if (summary.messages++ == 0) first = received;
    last = received;
  }
  summary.rate_hz = ratePerSecond(summary.messages, first, last);
  summary.sequence = senders_[id].dynamic_sequence.counts();
  summary.sequence += senders_[id].static_sequence.counts();
  if (const auto delays = tally.delays_by_sender.find(id); delays != tally.delays_by_sender.end()) {
    summary.dynamic_samples = delays->second.count;
    summary.average_delay_s = delays->second.average();
    summary.max_delay_s = delays->second.maximum();
  }
  if (const auto frames = tally.frames_by_sender.find(id); frames != tally.frames_by_sender.end()) {
    summary.frames.assign(frames->second.begin(), frames->second.end());
  }
  return summary;
}

std::vector<FrameConflict> TfTraffic::findConflicts(const WindowTally& tally) const {
  std::vector<FrameConflict> conflicts;
  for (const auto& [child, senders] : tally.senders_by_child) {
    if (senders.size() < 2) continue;
    FrameConflict conflict{child, {}};
    std::vector<std::pair<std::uint32_t, const WindowTally::SenderOfFrame*>> heard_most_first;
    for (const auto& [id, sender] : senders) heard_most_first.emplace_back(id, &sender);
    std::stable_sort(
        heard_most_first.begin(), heard_most_first.end(),
        [](const auto& a, const auto& b) { return a.second->transforms > b.second->transforms; });
    for (const auto& [id, sender_of_frame] : heard_most_first) {
      const WindowTally::SenderOfFrame& sender = *sender_of_frame;
      std::string parents;
      for (const std::string& parent : sender.parents) {
        parents += (parents.empty() ? "'" : ", '") + parent + "'";
      }
      const char* kind = sender.is_static && sender.is_dynamic ? "static and dynamic"
                         : sender.is_static                    ? "static"
                                                               : "dynamic";
      conflict.senders.push_back("'" + senders_[id].name + "' (parent " + parents + ", " + kind +
                                 ", " + std::to_string(sender.transforms) + " transforms)");
    }
    conflicts.push_back(std::move(conflict));
  }
  return conflicts;
}

TrafficSummary TfTraffic::summarize(TimePoint window_start, TimePoint window_end,
                                    Duration cache_time) const {
  const std::int64_t start = toUtime(window_start);
  const std::int64_t end = toUtime(window_end);
  TrafficSummary summary;
  summary.window_start = window_start;
  summary.window_end = window_end;
  WindowTally tally;
  for (const auto& [key, edge] : edges_) {
    EdgeTraffic traffic = summarizeEdge(edge, start, end, cache_time, tally);
    if (traffic.samples > 0) summary.edges.push_back(std::move(traffic));
  }
  for (std::uint32_t id = 0; id < senders_.size(); ++id) {
    AuthorityTraffic traffic = summarizeSender(id, start, end, tally);
    if (traffic.messages > 0) summary.authorities.push_back(std::move(traffic));
  }
  summary.conflicts = findConflicts(tally);
  summary.messages = messages_;
  summary.malformed = malformed_;
  summary.invalid_transforms = invalid_;
  summary.refused = refused_;
  for (const auto& [kind, description] : problems_) summary.problems.push_back(description);
  return summary;
}

}  // namespace lcmtf::nodes
