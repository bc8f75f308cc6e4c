#pragma once
// The live view's network face (civetweb): the page, the frames (WebSocket, MJPEG, single
// JPEG, PNG snapshot), the state and the controls, the time series and the recordings. Each
// viewer's stream is written by a thread of its own that only ever takes the session's newest
// frame, so a slow or stalled viewer loses frames and slows nobody else.
//
// Its doors: a request must name this server in its Host header (the bound address or a
// loopback name: a DNS-rebound name is refused), a request from another site's page (Origin,
// Sec-Fetch-Site) may load the page but not steer, stream or start work, and no CORS header is
// ever sent. Bound beyond loopback, every request also needs the token of the printed URL
// (kept by the page as an HttpOnly, SameSite=Strict cookie).
#include <memory>
#include <string>

#include "live/bind_address.h"
#include "live/live_session.h"

namespace cablefilm {

struct ServerOptions {
  std::string bind = "127.0.0.1";  // the address to listen on
  int port = 8080;                 // 0: any free port
  int max_viewers = 32;            // streams (WebSocket + MJPEG) at once; more get 503
  std::string token;               // empty: none asked (loopback); else every request needs it
};

// 128 bits from /dev/urandom as 32 hex digits; throws Error if it cannot be read.
std::string MakeToken();

// The largest WebSocket message (a control) taken; a frame announcing more closes the
// connection (1009) before any of it is read.
constexpr std::size_t kMaxWsMessageBytes = kMaxControlBytes;

class LiveServer {
 public:
  // Starts listening; throws Error (address in use, bad address).
  LiveServer(LiveSession& session, const ServerOptions& options);
  ~LiveServer();  // closes every connection
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  int port() const;
  std::string url() const;  // http://ADDRESS:PORT/ (with ?token=... when one is needed)

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
