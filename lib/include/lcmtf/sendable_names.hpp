#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "lcmtf/transform_stamped.hpp"

namespace lcmtf {

/// Why `name` cannot go on the wire as a frame or sender name, or "" when it can. A name
/// longer than listeners decode (DecodeLimits::max_name_bytes by default) makes every listener
/// refuse the whole batch it is in, and LCM sends a name only up to its first NUL byte.
std::string whyUnsendable(std::string_view name);
/// "<what> '<name>' <whyUnsendable(name)>", the name cut short when long, or "" when it can be
/// sent.
std::string unsendableNameProblem(std::string_view what, std::string_view name);

/// Throws std::invalid_argument, naming the name and what is wrong with it, when a frame name
/// of `transforms` or `authority` cannot be sent (whyUnsendable()). Broadcasters check their
/// batches so, before publishing anything of them.
void requireSendable(const std::vector<TransformStamped>& transforms, const std::string& authority);

}  // namespace lcmtf
