#include "lcmtf_viewer/web_server.hpp"

#include <deque>
#include <stdexcept>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>

#include "web_connections.hpp"

namespace lcmtf::viewer {

using web::tcp;

class WebServer::Impl {
 public:
  Impl(const WebServerOptions& options, WebHandler& handler)
      : state_(handler, options), io_(1), acceptor_(io_) {
    boost::system::error_code error;
    const auto address = boost::asio::ip::make_address(options.bind_address, error);
    if (error) {
      throw std::runtime_error("--bind: '" + options.bind_address + "' is not an IP address");
    }
    const tcp::endpoint endpoint(address, options.port);
    acceptor_.open(endpoint.protocol(), error);
    if (!error) acceptor_.set_option(boost::asio::socket_base::reuse_address(true), error);
    if (!error) acceptor_.bind(endpoint, error);
    if (!error) acceptor_.listen(boost::asio::socket_base::max_listen_connections, error);
    if (error) {
      throw std::runtime_error("cannot listen on " + options.bind_address + ":" +
                               std::to_string(options.port) + ": " + error.message());
    }
  }

  ~Impl() { stop(); }

  std::uint16_t port() const { return acceptor_.local_endpoint().port(); }

  void every(std::chrono::microseconds period, std::function<void()> task) {
    periodic_.push_back(Periodic{boost::asio::steady_timer(io_), period, std::move(task)});
  }

  void start() {
    accept();
    for (Periodic& periodic : periodic_) schedule(periodic);
    thread_ = std::thread([this] { io_.run(); });
  }

  void post(std::function<void()> task) { boost::asio::post(io_, std::move(task)); }

  void stop() {
    if (!thread_.joinable()) return;
    boost::asio::post(io_, [this] {
      boost::system::error_code ignored;
      acceptor_.close(ignored);
      for (Periodic& periodic : periodic_) periodic.timer.cancel();
      state_.handler.serverStopping();
      io_.stop();
    });
    thread_.join();
  }

  const WebServerStatistics& statistics() const { return state_.statistics; }

 private:
  struct Periodic {
    boost::asio::steady_timer timer;
    std::chrono::microseconds period;
    std::function<void()> task;
  };

  // Closes the connection waiting longest for a request when every one is taken.
  bool roomForAnother() {
    const auto full = [this] {
      return state_.open_connections - state_.closed_idle >= state_.options.max_connections;
    };
    if (full() && !state_.waiting.empty()) {
      state_.waiting.front()->closeIdle();
      ++state_.statistics.idle_connections_closed;
    }
    return !full();
  }

  void accept() {
    acceptor_.async_accept(io_, [this](boost::system::error_code error, tcp::socket socket) {
      if (error == boost::asio::error::operation_aborted) return;
      if (!error) {
        if (!roomForAnother()) {
          ++state_.statistics.connections_refused;
        } else {
          // Small messages (a scene after a page's ack) go out at once, not after the page's
          // delayed TCP acknowledgement.
          boost::system::error_code ignored;
          socket.set_option(tcp::no_delay(true), ignored);
          std::make_shared<web::HttpConnection>(std::move(socket), state_)->start();
        }
      }
      accept();
    });
  }

  void schedule(Periodic& periodic) {
    periodic.timer.expires_after(periodic.period);
    periodic.timer.async_wait([this, &periodic](boost::system::error_code error) {
      if (error) return;
      periodic.task();
      schedule(periodic);
    });
  }

  // Outlives io_, whose end destroys the connections still waiting, which touch it.
  web::ServerState state_;
  boost::asio::io_context io_;
  tcp::acceptor acceptor_;
  std::deque<Periodic> periodic_;  // timers must not move once waiting
  std::thread thread_;
};

WebServer::WebServer(const WebServerOptions& options, WebHandler& handler)
    : impl_(std::make_unique<Impl>(options, handler)) {}
WebServer::~WebServer() = default;
std::uint16_t WebServer::port() const { return impl_->port(); }
void WebServer::every(std::chrono::microseconds period, std::function<void()> task) {
  impl_->every(period, std::move(task));
}
void WebServer::start() { impl_->start(); }
void WebServer::post(std::function<void()> task) { impl_->post(std::move(task)); }
void WebServer::stop() { impl_->stop(); }
const WebServerStatistics& WebServer::statistics() const { return impl_->statistics(); }

}  // namespace lcmtf::viewer
