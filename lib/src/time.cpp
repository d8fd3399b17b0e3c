#include "lcmtf/time.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lcmtf {

TimePoint now() { return std::chrono::time_point_cast<Duration>(std::chrono::system_clock::now()); }

double toSeconds(Duration d) { return static_cast<double>(d.count()) * 1e-6; }

double toSeconds(TimePoint t) { return toSeconds(t.time_since_epoch()); }

Duration secondsToDuration(double seconds) {
  return Duration(static_cast<Duration::rep>(std::llround(seconds * 1e6)));
}

TimePoint fromSeconds(double seconds_since_epoch) {
  return TimePoint(secondsToDuration(seconds_since_epoch));
}

namespace {
std::string formatMicroseconds(std::int64_t micros) {
  const char* sign = micros < 0 ? "-" : "";
  const std::uint64_t magnitude =
      micros < 0 ? 0 - static_cast<std::uint64_t>(micros) : static_cast<std::uint64_t>(micros);
  char text[40];
  std::snprintf(text, sizeof text, "%s%" PRIu64 ".%06" PRIu64, sign, magnitude / 1000000,
                magnitude % 1000000);
  return text;
}
}  // namespace

std::string toString(TimePoint t) { return formatMicroseconds(toUtime(t)); }

std::string toString(Duration d) { return formatMicroseconds(d.count()) + " s"; }

}  // namespace lcmtf
