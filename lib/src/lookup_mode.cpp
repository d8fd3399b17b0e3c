#include "lookup_mode.hpp"

namespace lcmtf::detail {

std::atomic<bool> quick_lookups_enabled{true};
std::atomic<bool> cross_check_enabled{true};

void setQuickLookupsEnabled(bool enabled) {
  quick_lookups_enabled.store(enabled, std::memory_order_relaxed);
}

void setCrossCheckEnabled(bool enabled) {
  cross_check_enabled.store(enabled, std::memory_order_relaxed);
}

}  // namespace lcmtf::detail
