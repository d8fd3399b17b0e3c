#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/child_process.hpp"

namespace lcmtf_test {

/// Thrown where this machine cannot make network namespaces joined by veth pairs.
class NamespacesUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Three network namespaces of this process's own in a line, sender -- relay -- receiver,
/// joined by veth pairs; the sender and the receiver route multicast onto their one interface.
/// All three are removed when it goes out of scope, and so are those a killed run left behind.
class NamespaceChain {
 public:
  /// Throws NamespacesUnavailable, after removing what it made, where a step fails.
  NamespaceChain();
  NamespaceChain(const NamespaceChain&) = delete;
  NamespaceChain& operator=(const NamespaceChain&) = delete;

  const std::string& sender() const { return sender_; }
  const std::string& relay() const { return relay_; }
  const std::string& receiver() const { return receiver_; }
  /// The relay's two interfaces, by the namespace at their other end.
  static constexpr const char* kRelayToSender = "to-sender";
  static constexpr const char* kRelayToReceiver = "to-receiver";

  /// Starts `program` inside the namespace `name`; killed when the pointer goes.
  std::unique_ptr<ChildProcess> start(const std::string& name, const std::string& program,
                                      const std::vector<std::string>& arguments) const;

 private:
  // Deletes the namespaces it lists, also when the chain's constructor throws half way.
  struct OwnedNamespaces {
    OwnedNamespaces() = default;
    OwnedNamespaces(const OwnedNamespaces&) = delete;
    OwnedNamespaces& operator=(const OwnedNamespaces&) = delete;
    ~OwnedNamespaces();
    std::string ip;
    std::vector<std::string> names;
  };
  void create(const std::string& name);
  void ip(const std::vector<std::string>& arguments) const;

  OwnedNamespaces owned_;
  std::string sender_;
  std::string relay_;
  std::string receiver_;
};

}  // namespace lcmtf_test
