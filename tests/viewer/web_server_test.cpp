// WebServer over real TCP: files, refusals, WebSocket messages and the limits on both.
#include "lcmtf_viewer/web_server.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <condition_variable>
#include <fstream>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

namespace lcmtf::viewer {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

// Serves one file; echoes each page message back with its kind; on "flood" sends too much.
class EchoHandler : public WebHandler {
 public:
  explicit EchoHandler(ServedFiles files) : files_(std::move(files)) {}
  const ServedFile* findFile(std::string_view target) override { return files_.find(target); }
  void pageOpened(const std::shared_ptr<PageLink>& page) override {
    pages_.push_back(page);
    page->send(std::make_shared<const std::string>("hello"));
  }
  void pageMessage(PageLink& page, std::string_view message, bool is_text) override {
    if (message == "flood") {
      const auto big = std::make_shared<const std::string>(1 << 20, 'x');
      for (int i = 0; i < 100; ++i) page.send(big);
      return;
    }
    if (message == "bye") {
      page.close(1000, "asked to");
      return;
    }
    page.send(std::make_shared<const std::string>((is_text ? "text:" : "binary:") +
                                                  std::string(message)));
  }
  void pageClosed(PageLink& page) override {
    std::lock_guard<std::mutex> lock(mutex_);
    ++closed_;
    for (auto it = pages_.begin(); it != pages_.end(); ++it) {
      if (it->get() == &page) {
        pages_.erase(it);
        break;
      }
    }
    changed_.notify_all();
  }
  void serverStopping() override { pages_.clear(); }
  bool waitForClosed(int count) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(5), [&] { return closed_ >= count; });
  }

 private:
  ServedFiles files_;
  std::vector<std::shared_ptr<PageLink>> pages_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int closed_ = 0;
};

class WebServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::filesystem::temp_directory_path() /
            ("lcmtf_web_server_" + std::to_string(::getpid()) + ".html");
    std::ofstream(file_) << "<p>page</p>";
    ServedFiles files;
    files.add("/", file_);
    handler_ = std::make_unique<EchoHandler>(std::move(files));
    WebServerOptions options;
    options.port = 0;
    options.max_pages = 3;
    options.max_message_bytes = 1024;
    options.idle_timeout = std::chrono::seconds(2);
    server_ = std::make_unique<WebServer>(options, *handler_);
    server_->start();
  }
  void TearDown() override {
    server_.reset();
    std::filesystem::remove(file_);
  }

  // Sends `request` as is and returns the whole answer (the server closes after it).
  std::string raw(const std::string& request) {
    asio::io_context io;
    tcp::socket socket(io);
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
    asio::write(socket, asio::buffer(request));
    std::string answer;
    boost::system::error_code error;
    char chunk[4096];
    while (!error) {
      const std::size_t n = socket.read_some(asio::buffer(chunk), error);
      answer.append(chunk, n);
    }
    return answer;
  }
  std::string get(const std::string& target) {
    return raw("GET " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n");
  }

  // The answer to a WebSocket upgrade request for `target`, when it is refused.
  std::string upgrade(const std::string& target, const std::string& more_headers = "") {
    return raw("GET " + target +
               " HTTP/1.1\r\nHost: localhost\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
               "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n" +
               more_headers + "\r\n");
  }

  struct Client {
    asio::io_context io;
    websocket::stream<tcp::socket> socket{io};
    std::string read() {
      beast::flat_buffer buffer;
      socket.read(buffer);
      return beast::buffers_to_string(buffer.data());
    }
  };
  std::unique_ptr<Client> connect(const std::string& origin = "") {
    auto client = std::make_unique<Client>();
    client->socket.next_layer().connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
    const std::string host = "127.0.0.1:" + std::to_string(server_->port());
    if (!origin.empty()) {
      client->socket.set_option(websocket::stream_base::decorator(
          [origin](websocket::request_type& request) { request.set("Origin", origin); }));
    }
    client->socket.handshake(host, "/ws");
    return client;
  }

  std::filesystem::path file_;
  std::unique_ptr<EchoHandler> handler_;
  std::unique_ptr<WebServer> server_;
};

TEST_F(WebServerTest, ServesListedFilesWithTypeAndLength) {
  const std::string answer = get("/");
  EXPECT_EQ(answer.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << answer;
  EXPECT_NE(answer.find("Content-Type: text/html; charset=utf-8\r\n"), std::string::npos);
  EXPECT_NE(answer.find("Content-Length: 11\r\n"), std::string::npos);
  EXPECT_NE(answer.find("\r\n\r\n<p>page</p>"), std::string::npos);
  const std::string head = raw("HEAD / HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n");
  EXPECT_NE(head.find("Content-Length: 11\r\n"), std::string::npos);
  EXPECT_EQ(head.find("<p>"), std::string::npos);
  EXPECT_EQ(server_->statistics().files_sent.load(), 2u);
}

TEST_F(WebServerTest, RefusesTraversalUnknownPathsAndOtherMethods) {
  for (const char* target : {"/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd",
                             "/..%2f..%2fetc%2fpasswd", "/index.html%00", "/a\\..\\b"}) {
    const std::string answer = get(target);
    EXPECT_EQ(answer.rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u) << target << "\n" << answer;
    EXPECT_EQ(answer.find("root:"), std::string::npos);
  }
  EXPECT_EQ(get("/etc/passwd").rfind("HTTP/1.1 404 Not Found\r\n", 0), 0u);
  const std::string post = raw(
      "POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 3\r\nConnection: close\r\n\r\nabc");
  EXPECT_EQ(post.rfind("HTTP/1.1 405 Method Not Allowed\r\n", 0), 0u) << post;
  EXPECT_NE(post.find("Allow: GET, HEAD\r\n"), std::string::npos);
  EXPECT_EQ(server_->statistics().requests_refused.load(), 7u);
}

TEST_F(WebServerTest, AnswersWhatIsNotHttpWith400AndAnOversizedHeaderWith431) {
  const std::string garbage = raw("GARBAGE\r\n\r\n");
  EXPECT_EQ(garbage.rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u) << garbage;
  EXPECT_NE(garbage.find("not an HTTP request: "), std::string::npos) << garbage;
  const std::string bad_version = raw("GET / HTTP/9\r\nHost: localhost\r\n\r\n");
  EXPECT_EQ(bad_version.rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u) << bad_version;
  const std::string huge =
      raw("GET / HTTP/1.1\r\nHost: localhost\r\nX-Filler: " + std::string(9000, 'x') + "\r\n\r\n");
  EXPECT_EQ(huge.rfind("HTTP/1.1 431 Request Header Fields Too Large\r\n", 0), 0u) << huge;
  EXPECT_EQ(get("/").rfind("HTTP/1.1 200 OK\r\n", 0), 0u);
  EXPECT_EQ(server_->statistics().requests_refused.load(), 3u);
}

TEST_F(WebServerTest, IdleConnectionsCannotLockThePageOut) {
  server_.reset();
  WebServerOptions options;
  options.port = 0;
  options.max_connections = 3;
  server_ = std::make_unique<WebServer>(options, *handler_);
  server_->start();
  asio::io_context io;
  std::vector<tcp::socket> idle;
  for (int i = 0; i < 3; ++i) {
    idle.emplace_back(io).connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), server_->port()));
    asio::write(idle.back(), asio::buffer(std::string("GET / HT")));  // and never the rest
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string answer = get("/");
  EXPECT_EQ(answer.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << answer;
  EXPECT_EQ(server_->statistics().idle_connections_closed.load(), 1u);
  EXPECT_EQ(server_->statistics().connections_refused.load(), 0u);
  char byte;
  boost::system::error_code error;
  idle[0].read_some(asio::buffer(&byte, 1), error);
  EXPECT_EQ(error, asio::error::eof) << "the connection waiting longest is closed";
  for (int i = 1; i < 3; ++i) {
    idle[i].non_blocking(true);
    idle[i].read_some(asio::buffer(&byte, 1), error);
    EXPECT_EQ(error, asio::error::would_block) << "connection " << i << " is still open";
  }
}

TEST_F(WebServerTest, KeepsAConnectionAliveForSeveralRequests) {
  const std::string answer = raw(
      "GET / HTTP/1.1\r\nHost: localhost\r\n\r\nGET /nothing HTTP/1.1\r\nHost: localhost\r\n\r\n"
      "GET / HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(std::count(answer.begin(), answer.end(), '\n') > 10, true);
  std::size_t oks = 0;
  for (std::size_t at = answer.find("200 OK"); at != std::string::npos;
       at = answer.find("200 OK", at + 1))
    ++oks;
  EXPECT_EQ(oks, 2u);
  EXPECT_NE(answer.find("404 Not Found"), std::string::npos);
}

TEST_F(WebServerTest, PassesWholeMessagesBothWays) {
  auto client = connect();
  EXPECT_EQ(client->read(), "hello");
  client->socket.text(true);
  client->socket.write(asio::buffer(std::string("ping")));
  EXPECT_EQ(client->read(), "text:ping");
  client->socket.binary(true);
  client->socket.write(asio::buffer(std::string("\x01\x02", 2)));
  EXPECT_EQ(client->read(), std::string("binary:\x01\x02", 9));
}

TEST_F(WebServerTest, AMessageOverTheLimitClosesThePageWith1009) {
  auto client = connect();
  client->read();
  client->socket.text(true);
  client->socket.write(asio::buffer(std::string(2000, 'x')));
  beast::flat_buffer buffer;
  beast::error_code error;
  client->socket.read(buffer, error);
  // The server tears the connection down right after its close frame: the client's own close
  // reply may find it gone already.
  EXPECT_TRUE(error == websocket::error::closed || error == asio::error::not_connected) << error;
  EXPECT_EQ(client->socket.reason().code, websocket::close_code::too_big);
  EXPECT_TRUE(handler_->waitForClosed(1));
  EXPECT_EQ(server_->statistics().messages_too_large.load(), 1u);
}

TEST_F(WebServerTest, APageThatDoesNotReadIsClosedInsteadOfQueuingWithoutEnd) {
  auto client = connect();
  client->read();
  client->socket.text(true);
  client->socket.write(asio::buffer(std::string("flood")));
  beast::error_code error;
  std::size_t received = 0;
  while (!error) {
    beast::flat_buffer buffer;
    client->socket.read(buffer, error);
    if (!error) ++received;
  }
  EXPECT_EQ(error, websocket::error::closed);
  EXPECT_EQ(client->socket.reason().code, websocket::close_code::policy_error);
  EXPECT_LT(received, 100u);
}

TEST_F(WebServerTest, MorePagesThanAllowedAreRefusedWith503) {
  auto a = connect();
  auto b = connect();
  auto c = connect();
  EXPECT_EQ(upgrade("/ws").rfind("HTTP/1.1 503 Service Unavailable\r\n", 0), 0u);
  a->socket.close(websocket::close_code::normal);
  EXPECT_TRUE(handler_->waitForClosed(1));
  auto e = connect();  // room again
  EXPECT_EQ(e->read(), "hello");
}

TEST_F(WebServerTest, WebSocketsElsewhereThanWsAreNotFound) {
  EXPECT_EQ(upgrade("/other").rfind("HTTP/1.1 404 Not Found\r\n", 0), 0u);
  EXPECT_EQ(upgrade("/ws/../ws").rfind("HTTP/1.1 400 Bad Request\r\n", 0), 0u);
}

TEST_F(WebServerTest, RequestsNamingAnotherHostAreRefused) {
  const std::string rebound =
      raw("GET / HTTP/1.1\r\nHost: attacker.example:8080\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(rebound.rfind("HTTP/1.1 403 Forbidden\r\n", 0), 0u) << rebound;
  EXPECT_NE(rebound.find("--allow-host attacker.example"), std::string::npos) << rebound;
  EXPECT_EQ(rebound.find("<p>page</p>"), std::string::npos);
  const std::string page =
      raw("GET / HTTP/1.1\r\nHost: 127.0.0.1:1234\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(page.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << page;
}

TEST_F(WebServerTest, OnlyTheViewersOwnPagesMayOpenTheWebSocket) {
  const std::string other = upgrade("/ws", "Origin: http://attacker.example\r\n");
  EXPECT_EQ(other.rfind("HTTP/1.1 403 Forbidden\r\n", 0), 0u) << other;
  EXPECT_NE(other.find("'http://attacker.example' may not open"), std::string::npos) << other;
  EXPECT_EQ(upgrade("/ws", "Origin: http://localhost:1\r\n").rfind("HTTP/1.1 403", 0), 0u)
      << "another port is another origin";
  EXPECT_EQ(upgrade("/ws", "Origin: null\r\n").rfind("HTTP/1.1 403", 0), 0u);
  auto own = connect("http://127.0.0.1:" + std::to_string(server_->port()));
  EXPECT_EQ(own->read(), "hello");
  auto no_origin_so_not_a_browser = connect();
  EXPECT_EQ(no_origin_so_not_a_browser->read(), "hello");
}

TEST(WebServerHosts, AllowedHostsAndOriginsAreAnsweredToo) {
  ServedFiles files;
  class NoPages : public WebHandler {
    const ServedFile* findFile(std::string_view) override { return nullptr; }
    void pageOpened(const std::shared_ptr<PageLink>& page) override { page->close(1000, "ok"); }
    void pageMessage(PageLink&, std::string_view, bool) override {}
    void pageClosed(PageLink&) override {}
    void serverStopping() override {}
  } handler;
  WebServerOptions options;
  options.port = 0;
  options.allowed_hosts = {"robot.lab"};
  options.allowed_origins = {"http://dashboard.lab:3000"};
  WebServer server(options, handler);
  server.start();
  asio::io_context io;
  websocket::stream<tcp::socket> socket(io);
  socket.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  socket.set_option(websocket::stream_base::decorator([](websocket::request_type& request) {
    request.set("Origin", "http://dashboard.lab:3000");
  }));
  beast::error_code error;
  socket.handshake("ROBOT.lab:8080", "/ws", error);
  EXPECT_FALSE(error) << error.message();
}

TEST_F(WebServerTest, TheHandlerClosesAPageWithItsCodeAndReason) {
  auto client = connect();
  client->read();
  client->socket.text(true);
  client->socket.write(asio::buffer(std::string("bye")));
  beast::flat_buffer buffer;
  beast::error_code error;
  client->socket.read(buffer, error);
  EXPECT_EQ(error, websocket::error::closed);
  EXPECT_EQ(client->socket.reason().code, websocket::close_code::normal);
  EXPECT_EQ(client->socket.reason().reason, "asked to");
}

TEST_F(WebServerTest, PeriodicTasksRunOnTheServersThreadUntilStopped) {
  // A second server, so the task can be set before start.
  WebServerOptions options;
  options.port = 0;
  WebServer server(options, *handler_);
  std::promise<void> ran_three_times;
  int runs = 0;
  server.every(std::chrono::milliseconds(5), [&] {
    if (++runs == 3) ran_three_times.set_value();
  });
  server.start();
  EXPECT_EQ(ran_three_times.get_future().wait_for(std::chrono::seconds(5)),
            std::future_status::ready);
  server.stop();
  const int after_stop = runs;
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(runs, after_stop);
}

TEST(WebServerBind, AnAddressThatIsNotOneIsNamed) {
  class Nothing : public WebHandler {
    const ServedFile* findFile(std::string_view) override { return nullptr; }
    void pageOpened(const std::shared_ptr<PageLink>&) override {}
    void pageMessage(PageLink&, std::string_view, bool) override {}
    void pageClosed(PageLink&) override {}
    void serverStopping() override {}
  } nothing;
  WebServerOptions options;
  options.bind_address = "not-an-address";
  try {
    WebServer server(options, nothing);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "--bind: 'not-an-address' is not an IP address");
  }
}

}  // namespace
}  // namespace lcmtf::viewer
