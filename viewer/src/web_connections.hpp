// The connections of WebServer. Boost.Beast is the HTTP and WebSocket library: it is in
// Debian, kept by Boost, parses and frames with limits we set (header size, message size,
// timeouts), and runs every connection on one Asio thread, so the handler needs no locks.
// civetweb, the other candidate, sets no bound on a WebSocket frame's size and gives each
// connection a thread.
#pragma once

#include <cstddef>
#include <deque>
#include <list>
#include <memory>
#include <optional>
#include <string>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "lcmtf_viewer/host_policy.hpp"
#include "lcmtf_viewer/web_server.hpp"

namespace lcmtf::viewer::web {

class HttpConnection;

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = boost::asio::ip::tcp;

/// What every connection shares with the server; touched on the server's thread only.
struct ServerState {
  ServerState(WebHandler& server_handler, const WebServerOptions& server_options)
      : handler(server_handler),
        options(server_options),
        hosts(options.allowed_hosts, options.allowed_origins) {}

  WebHandler& handler;
  WebServerOptions options;
  HostPolicy hosts;
  WebServerStatistics statistics;
  std::size_t open_connections = 0;
  std::size_t open_pages = 0;
  /// Connections waiting for a request, the one waiting longest first: when all are taken,
  /// it makes room for a new one, so that idle connections cannot lock the page out.
  std::list<HttpConnection*> waiting;
  std::size_t closed_idle = 0;  ///< of open_connections: closed to make room, not yet gone
};

/// One HTTP connection: GET and HEAD of listed files, or an upgrade to a page's WebSocket.
class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  HttpConnection(tcp::socket socket, ServerState& state);
  ~HttpConnection();
  void start() { readRequest(); }
  /// Closes it while it waits for a request, to make room for a new connection.
  void closeIdle();

 private:
  void startWaiting();
  void stopWaiting();
  void readRequest();
  void onRequestHeader(beast::error_code error);
  void answer(const http::request<http::empty_body>& request);
  void refuse(http::status status, const std::string& why, unsigned version, bool keep_alive);
  void sendFile(const ServedFile& file, bool head_only, unsigned version, bool keep_alive);
  void upgradeToPage();
  template <class Response>
  void write(std::shared_ptr<Response> response);

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::empty_body>> parser_;
  ServerState& state_;
  std::optional<std::list<HttpConnection*>::iterator> waiting_at_;
  bool closed_idle_ = false;
};

/// One open page's WebSocket: reads whole messages, writes queued ones one at a time.
class PageSocket : public PageLink, public std::enable_shared_from_this<PageSocket> {
 public:
  PageSocket(tcp::socket socket, ServerState& state);
  ~PageSocket() override;
  void accept(http::request<http::empty_body> request);
  void send(std::shared_ptr<const std::string> text) override;
  void close(std::uint16_t code, const std::string& reason) override;

 private:
  void read();
  void onRead(beast::error_code error);
  void writeNext();

  websocket::stream<beast::tcp_stream> socket_;
  beast::flat_buffer buffer_;
  std::deque<std::shared_ptr<const std::string>> outbox_;
  std::size_t outbox_bytes_ = 0;
  bool open_ = false;
  bool closing_ = false;
  ServerState& state_;
};

}  // namespace lcmtf::viewer::web
