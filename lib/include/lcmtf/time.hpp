#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace lcmtf {

/// Microseconds: the resolution of LCM's utime, so the wire and the API agree exactly.
using Duration = std::chrono::microseconds;
/// Microseconds since the Unix epoch on the system clock. TimePoint{} means "latest available".
using TimePoint = std::chrono::time_point<std::chrono::system_clock, Duration>;

/// The zero time point, which lookups read as "the latest time with data".
inline constexpr TimePoint kLatestTime{};

/// A TimePoint from an LCM utime (microseconds since the epoch), and back.
constexpr TimePoint fromUtime(std::int64_t utime) { return TimePoint(Duration(utime)); }
constexpr std::int64_t toUtime(TimePoint t) { return t.time_since_epoch().count(); }

/// The system clock now, truncated to microseconds.
TimePoint now();

/// Seconds as a double, for printing and arithmetic; fromSeconds rounds to the nearest microsecond.
double toSeconds(Duration d);
double toSeconds(TimePoint t);
Duration secondsToDuration(double seconds);
TimePoint fromSeconds(double seconds_since_epoch);

/// Seconds with microsecond digits ("1700000000.000250"), the form every error message uses.
std::string toString(TimePoint t);
/// A duration in seconds with microsecond digits and a unit ("0.250000 s").
std::string toString(Duration d);

}  // namespace lcmtf
