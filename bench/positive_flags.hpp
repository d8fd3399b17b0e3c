#pragma once

// Command lines of `--name N` pairs, every N a positive integer, as the benches that take a few
// numbers read them.

#include <cstdlib>
#include <cstring>
#include <functional>
#include <initializer_list>

namespace bench {

/// A flag's name, dashes included, and what takes its value.
struct PositiveFlag {
  const char* name;
  std::function<void(long long)> set;
};

/// What sets `field` to a flag's value.
template <class Field>
std::function<void(long long)> into(Field& field) {
  return [&field](long long value) { field = static_cast<Field>(value); };
}

/// Reads every pair into the flag it names; false for a flag not among `flags`, a flag without
/// a value, or a value that is not a positive integer.
inline bool parsePositiveFlags(int argc, char** argv, std::initializer_list<PositiveFlag> flags) {
  if (argc % 2 != 1) return false;
  for (int i = 1; i + 1 < argc; i += 2) {
    char* end = nullptr;
    const long long value = std::strtoll(argv[i + 1], &end, 10);
    if (value <= 0 || *end != '\0') return false;
    const PositiveFlag* flag = nullptr;
    for (const PositiveFlag& candidate : flags) {
      if (std::strcmp(argv[i], candidate.name) == 0) flag = &candidate;
    }
    if (!flag) return false;
    flag->set(value);
  }
  return true;
}

}  // namespace bench
