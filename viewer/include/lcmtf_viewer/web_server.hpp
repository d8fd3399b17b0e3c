#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lcmtf_viewer/served_files.hpp"

namespace lcmtf::viewer {

/// One open page's WebSocket, as the handler sees it. Used on the server's thread only.
class PageLink {
 public:
  virtual ~PageLink() = default;
  /// Queues a text message; a page that lets too much queue up is closed (1008).
  virtual void send(std::shared_ptr<const std::string> text) = 0;
  /// Closes the WebSocket with `code` and `reason`; pageClosed follows.
  virtual void close(std::uint16_t code, const std::string& reason) = 0;
};

/// What the server asks of the program. Every call comes on the server's one thread.
class WebHandler {
 public:
  virtual ~WebHandler() = default;
  /// The file to send for a request target already checked by refuseRequestTarget; or null.
  virtual const ServedFile* findFile(std::string_view target) = 0;
  virtual void pageOpened(const std::shared_ptr<PageLink>& page) = 0;
  /// A whole message from the page; `is_text` false for a binary one.
  virtual void pageMessage(PageLink& page, std::string_view message, bool is_text) = 0;
  virtual void pageClosed(PageLink& page) = 0;
  /// The server stops: let go of every PageLink now.
  virtual void serverStopping() = 0;
};

/// Where the server listens and what it allows.
struct WebServerOptions {
  std::string bind_address = "127.0.0.1";
  std::uint16_t port = 8080;  ///< 0: any free port
  /// HTTP connections at once: a new one closes the one waiting longest for a request, or is
  /// closed at once when every one is busy.
  std::size_t max_connections = 256;
  std::size_t max_pages = 64;                 ///< WebSockets at once; more get 503
  std::size_t max_message_bytes = 64 * 1024;  ///< larger page messages close it with 1009
  std::chrono::seconds idle_timeout{30};      ///< an HTTP connection that sends nothing
  std::vector<std::string> allowed_hosts;     ///< see HostPolicy
  std::vector<std::string> allowed_origins;   ///< see HostPolicy
};

/// What the server has done and refused since it started.
struct WebServerStatistics {
  std::atomic<std::uint64_t> files_sent{0};
  std::atomic<std::uint64_t> requests_refused{0};  ///< bad path, method, host, or not found
  std::atomic<std::uint64_t> connections_refused{0};
  std::atomic<std::uint64_t> idle_connections_closed{0};  ///< to make room for new ones
  std::atomic<std::uint64_t> pages_opened{0};
  std::atomic<std::uint64_t> messages_too_large{0};
};

/// An HTTP and WebSocket server on one thread of its own: it serves the files the handler
/// names and passes WebSocket messages at "/ws" to it.
class WebServer {
 public:
  /// Listens at once; std::runtime_error naming the address when it cannot.
  WebServer(const WebServerOptions& options, WebHandler& handler);
  ~WebServer();  ///< stops
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  /// The port listened on (the one chosen when options.port was 0).
  std::uint16_t port() const;
  /// Runs `task` on the server's thread every `period`, from start(); call before start().
  void every(std::chrono::microseconds period, std::function<void()> task);
  /// Starts the server's thread.
  void start();
  /// Runs `task` on the server's thread soon.
  void post(std::function<void()> task);
  /// Stops accepting, lets the handler drop its pages, and joins the thread.
  void stop();
  const WebServerStatistics& statistics() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lcmtf::viewer
