#pragma once

#include <functional>
#include <string>

namespace lcmtf_test {

/// Runs `work` to its end on a thread of its own inside the network namespace `name` (made by
/// `ip netns add`): the sockets it opens and the threads it starts live there, the rest of the
/// process stays where it is. Rethrows what `work` throws; std::runtime_error if it cannot enter.
void runInNamespace(const std::string& name, const std::function<void()>& work);

}  // namespace lcmtf_test
