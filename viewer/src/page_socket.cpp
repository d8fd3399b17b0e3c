#include <string_view>
#include <utility>

#include "web_connections.hpp"

namespace lcmtf::viewer::web {

namespace {

// A page that has not read this much of what was sent to it is not keeping up.
constexpr std::size_t kMaxQueuedMessages = 64;
constexpr std::size_t kMaxQueuedBytes = 16 * 1024 * 1024;

}  // namespace

PageSocket::PageSocket(tcp::socket socket, ServerState& state)
    : socket_(std::move(socket)), state_(state) {
  ++state_.open_pages;
}

PageSocket::~PageSocket() { --state_.open_pages; }

void PageSocket::accept(http::request<http::empty_body> request) {
  socket_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  socket_.set_option(websocket::stream_base::decorator([](websocket::response_type& response) {
    response.set(http::field::server, "lcmtf-viewer");
  }));
  socket_.read_message_max(state_.options.max_message_bytes);
  socket_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
    if (error) return;
    self->open_ = true;
    ++self->state_.statistics.pages_opened;
    self->state_.handler.pageOpened(self);
    self->read();
  });
}

void PageSocket::read() {
  socket_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, std::size_t) {
    self->onRead(error);
  });
}

void PageSocket::onRead(beast::error_code error) {
  if (error) {
    if (error == websocket::error::message_too_big) ++state_.statistics.messages_too_large;
    if (open_) {
      open_ = false;
      state_.handler.pageClosed(*this);
    }
    return;
  }
  const auto data = buffer_.data();
  const std::string_view message(static_cast<const char*>(data.data()), data.size());
  state_.handler.pageMessage(*this, message, socket_.got_text());
  buffer_.consume(buffer_.size());
  read();  // also while closing: the page's close frame ends the read
}

void PageSocket::send(std::shared_ptr<const std::string> text) {
  if (!open_ || closing_) return;
  if (outbox_.size() >= kMaxQueuedMessages || outbox_bytes_ + text->size() > kMaxQueuedBytes) {
    close(static_cast<std::uint16_t>(websocket::close_code::policy_error),
          "the page does not read what it is sent");
    return;
  }
  outbox_bytes_ += text->size();
  outbox_.push_back(std::move(text));
  if (outbox_.size() == 1) writeNext();
}

void PageSocket::writeNext() {
  socket_.text(true);
  socket_.async_write(boost::asio::buffer(*outbox_.front()),
                      [self = shared_from_this()](beast::error_code error, std::size_t) {
                        if (error) return;  // the read fails too, and ends the page
                        self->outbox_bytes_ -= self->outbox_.front()->size();
                        self->outbox_.pop_front();
                        if (!self->outbox_.empty() && !self->closing_) self->writeNext();
                      });
}

void PageSocket::close(std::uint16_t code, const std::string& reason) {
  if (!open_ || closing_) return;
  closing_ = true;
  socket_.async_close(websocket::close_reason(static_cast<websocket::close_code>(code), reason),
                      [self = shared_from_this()](beast::error_code) {});
}

}  // namespace lcmtf::viewer::web
