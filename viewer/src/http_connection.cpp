#include <string>
#include <utility>

#include "web_connections.hpp"

namespace lcmtf::viewer::web {

namespace {

constexpr std::size_t kMaxRequestHeaderBytes = 8 * 1024;
constexpr unsigned kAnswerVersion = 11;  // to a request whose own version could not be read

std::string_view headerValue(const http::request<http::empty_body>& request, http::field field) {
  const auto value = request[field];
  return {value.data(), value.size()};
}

}  // namespace

HttpConnection::HttpConnection(tcp::socket socket, ServerState& state)
    : stream_(std::move(socket)), state_(state) {
  ++state_.open_connections;
}

HttpConnection::~HttpConnection() {
  stopWaiting();
  if (closed_idle_) --state_.closed_idle;
  --state_.open_connections;
}

void HttpConnection::startWaiting() {
  if (!waiting_at_) waiting_at_ = state_.waiting.insert(state_.waiting.end(), this);
}

void HttpConnection::stopWaiting() {
  if (!waiting_at_) return;
  state_.waiting.erase(*waiting_at_);
  waiting_at_.reset();
}

void HttpConnection::closeIdle() {
  stopWaiting();
  closed_idle_ = true;
  ++state_.closed_idle;
  beast::error_code ignored;
  stream_.socket().close(ignored);
}

void HttpConnection::readRequest() {
  startWaiting();
  parser_.emplace();
  parser_->header_limit(kMaxRequestHeaderBytes);
  stream_.expires_after(state_.options.idle_timeout);
  http::async_read_header(stream_, buffer_, *parser_,
                          [self = shared_from_this()](beast::error_code error, std::size_t) {
                            self->onRequestHeader(error);
                          });
}

void HttpConnection::onRequestHeader(beast::error_code error) {
  stopWaiting();
  if (error == http::error::end_of_stream) {
    stream_.socket().shutdown(tcp::socket::shutdown_send, error);
    return;
  }
  if (error == http::error::header_limit) {
    refuse(http::status::request_header_fields_too_large,
           "the request's header is over " + std::to_string(kMaxRequestHeaderBytes) + " bytes",
           kAnswerVersion, false);
    return;
  }
  if (error.category() == beast::error_code(http::error::bad_method).category()) {
    refuse(http::status::bad_request, "not an HTTP request: " + error.message(), kAnswerVersion,
           false);
    return;
  }
  if (error) return;  // a timeout, or the connection failed: no one to answer
  const http::request<http::empty_body>& request = parser_->get();
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    refuse(http::status::method_not_allowed, "only GET and HEAD are served", request.version(),
           false);
    return;
  }
  if (!parser_->is_done()) {
    refuse(http::status::bad_request, "requests with a body are not accepted", request.version(),
           false);
    return;
  }
  answer(request);
}

void HttpConnection::answer(const http::request<http::empty_body>& request) {
  const bool keep_alive = request.keep_alive();
  const std::string_view target(request.target().data(), request.target().size());
  if (const auto why = refuseRequestTarget(target)) {
    refuse(http::status::bad_request, *why, request.version(), false);
    return;
  }
  const std::string_view host = headerValue(request, http::field::host);
  if (request.find(http::field::host) != request.end()) {
    if (const auto why = state_.hosts.refuseHost(host)) {
      refuse(http::status::forbidden, *why, request.version(), false);
      return;
    }
  }
  if (websocket::is_upgrade(request)) {
    const auto why_not_this_page =
        state_.hosts.refuseOrigin(headerValue(request, http::field::origin), host);
    if (target != "/ws") {
      refuse(http::status::not_found, "WebSockets are served at /ws only", request.version(),
             false);
    } else if (why_not_this_page) {
      refuse(http::status::forbidden, *why_not_this_page, request.version(), false);
    } else if (state_.open_pages >= state_.options.max_pages) {
      refuse(http::status::service_unavailable, "too many pages are open", request.version(),
             false);
    } else {
      upgradeToPage();
    }
    return;
  }
  const ServedFile* file = state_.handler.findFile(target);
  if (!file) {
    refuse(http::status::not_found, "no such file is served", request.version(), keep_alive);
    return;
  }
  sendFile(*file, request.method() == http::verb::head, request.version(), keep_alive);
}

void HttpConnection::refuse(http::status status, const std::string& why, unsigned version,
                            bool keep_alive) {
  ++state_.statistics.requests_refused;
  auto response = std::make_shared<http::response<http::string_body>>(status, version);
  response->set(http::field::server, "lcmtf-viewer");
  response->set(http::field::content_type, "text/plain; charset=utf-8");
  if (status == http::status::method_not_allowed) response->set(http::field::allow, "GET, HEAD");
  response->body() = why + "\n";
  response->keep_alive(keep_alive);
  response->prepare_payload();
  write(std::move(response));
}

void HttpConnection::sendFile(const ServedFile& file, bool head_only, unsigned version,
                              bool keep_alive) {
  http::file_body::value_type body;
  beast::error_code error;
  body.open(file.path.c_str(), beast::file_mode::scan, error);
  if (error) {
    refuse(http::status::not_found, "the file can no longer be read", version, keep_alive);
    return;
  }
  ++state_.statistics.files_sent;
  const std::uint64_t size = body.size();
  auto set_headers = [&](auto& response) {
    response.set(http::field::server, "lcmtf-viewer");
    response.set(http::field::content_type, file.content_type);
    response.set(http::field::cache_control, "no-cache");
    response.set("X-Content-Type-Options", "nosniff");
    response.content_length(size);
    response.keep_alive(keep_alive);
  };
  if (head_only) {
    auto response = std::make_shared<http::response<http::empty_body>>(http::status::ok, version);
    set_headers(*response);
    write(std::move(response));
    return;
  }
  auto response = std::make_shared<http::response<http::file_body>>(
      std::piecewise_construct, std::make_tuple(std::move(body)),
      std::make_tuple(http::status::ok, version));
  set_headers(*response);
  write(std::move(response));
}

template <class Response>
void HttpConnection::write(std::shared_ptr<Response> response) {
  stream_.expires_after(state_.options.idle_timeout);
  Response& message = *response;
  http::async_write(stream_, message,
                    [self = shared_from_this(), response = std::move(response)](
                        beast::error_code error, std::size_t) {
                      if (!error && response->keep_alive()) {
                        self->readRequest();
                        return;
                      }
                      self->stream_.socket().shutdown(tcp::socket::shutdown_send, error);
                    });
}

void HttpConnection::upgradeToPage() {
  stream_.expires_never();
  auto page = std::make_shared<PageSocket>(stream_.release_socket(), state_);
  page->accept(parser_->release());
}

}  // namespace lcmtf::viewer::web
