#pragma once
// The live view's network face (civetweb): the page, the frames (WebSocket, MJPEG, single
// JPEG, PNG snapshot), the state and the controls, the time series and the recordings. Each
// viewer's stream is written by a thread of its own that only ever takes the session's newest
// frame, so a slow or stalled viewer loses frames and slows nobody else.
#include <memory>
#include <string>

#include "live/live_session.h"

namespace cablefilm {

struct ServerOptions {
  std::string bind = "127.0.0.1";  // the address to listen on
  int port = 8080;                 // 0: any free port
  int max_viewers = 32;            // streams (WebSocket + MJPEG) at once; more get 503
};

class LiveServer {
 public:
  // Starts listening; throws Error (address in use, bad address).
  LiveServer(LiveSession& session, const ServerOptions& options);
  ~LiveServer();  // closes every connection
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  int port() const;
  std::string url() const;  // http://ADDRESS:PORT/

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
