#include "lcmtf/programs/closest_names.hpp"

#include <algorithm>
#include <tuple>

namespace lcmtf::programs {

namespace {

// Names typed by people are short; longer ones cost no more than this many characters each.
constexpr std::size_t kLongestCompared = 256;
constexpr std::size_t kMostSuggested = 3;

// Whether one is part of the other ("gripper" of "r_gripper_tool_frame").
bool contains(const std::string& a, const std::string& b) {
  return b.size() >= 3 && a.size() >= 3 &&
         (a.find(b) != std::string::npos || b.find(a) != std::string::npos);
}

// Rank of `candidate` as what `name` meant: fewer edits first, then names that contain it.
std::tuple<std::size_t, bool, std::string> rank(const std::string& name,
                                                const std::string& candidate) {
  return {editDistance(name, candidate, kLongestCompared), !contains(name, candidate), candidate};
}

}  // namespace

std::size_t editDistance(const std::string& a_in, const std::string& b_in, std::size_t limit) {
  const std::string a = a_in.substr(0, kLongestCompared);
  const std::string b = b_in.substr(0, kLongestCompared);
  const std::size_t n = a.size(), m = b.size();
  if ((n > m ? n - m : m - n) > limit) return limit + 1;
  // Three rows of the optimal-string-alignment table: two back for a swap of neighbours.
  std::vector<std::size_t> before(m + 1), previous(m + 1), current(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    current[0] = i;
    std::size_t row_least = current[0];
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t replace = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
      row_least = std::min(row_least, current[j]);
    }
    if (row_least > limit) return limit + 1;
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return std::min(previous[m], limit + 1);
}

std::vector<std::string> closestNames(const std::string& name,
                                      const std::vector<std::string>& known, std::size_t count) {
  std::vector<std::tuple<std::size_t, bool, std::string>> ranked;
  ranked.reserve(known.size());
  for (const std::string& candidate : known) ranked.push_back(rank(name, candidate));
  count = std::min(count, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(count),
                    ranked.end());
  std::vector<std::string> closest;
  for (std::size_t i = 0; i < count; ++i) closest.push_back(std::get<2>(ranked[i]));
  return closest;
}

std::string didYouMean(const std::string& name, const std::vector<std::string>& known) {
  // A typo is a few edits away; of several names, only the fewest edits away are meant.
  std::size_t close_enough = std::max<std::size_t>(1, name.size() / 4);
  std::vector<std::string> meant;
  for (const std::string& candidate : closestNames(name, known, kMostSuggested)) {
    if (candidate == name) continue;
    const std::size_t edits = editDistance(name, candidate, close_enough);
    if (edits > close_enough && !contains(name, candidate)) continue;
    if (edits <= close_enough) close_enough = edits;
    meant.push_back("'" + candidate + "'");
  }
  if (meant.empty()) return "";
  std::string text = " (did you mean " + meant[0];
  for (std::size_t i = 1; i < meant.size(); ++i) {
    text += (i + 1 == meant.size() ? " or " : ", ") + meant[i];
  }
  return text + "?)";
}

std::string listOfNames(const std::string& name, const std::vector<std::string>& known,
                        std::size_t shown) {
  std::vector<std::string> names = known;
  if (names.size() <= shown) {
    std::sort(names.begin(), names.end());
  } else {
    names = closestNames(name, known, shown);
  }
  std::string list;
  for (const std::string& each : names) list += (list.empty() ? "" : ", ") + each;
  if (known.size() > shown) {
    list +=
        ", ... (the " + std::to_string(shown) + " closest of " + std::to_string(known.size()) + ")";
  }
  return list;
}

}  // namespace lcmtf::programs
