#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace lcmtf::programs {

/// How many single-character edits (insert, delete, replace, swap two neighbours) turn `a`
/// into `b`, counting at most `limit`: anything further is `limit` + 1.
std::size_t editDistance(const std::string& a, const std::string& b, std::size_t limit);

/// Up to `count` names of `known`, the closest to `name` first (ties by name).
std::vector<std::string> closestNames(const std::string& name,
                                      const std::vector<std::string>& known, std::size_t count);

/// " (did you mean 'a'?)" or " (did you mean 'a' or 'b'?)" when names of `known` are close
/// enough to `name` to be what was meant; "" otherwise.
std::string didYouMean(const std::string& name, const std::vector<std::string>& known);

/// The names of `known` for a message: all of them sorted when there are at most `shown`,
/// else the `shown` closest to `name` and how many there are in all.
std::string listOfNames(const std::string& name, const std::vector<std::string>& known,
                        std::size_t shown = 30);

}  // namespace lcmtf::programs
