#include "live/http_server.h"

#include <civetweb.h>

#include <atomic>
#include <condition_variable>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "live/page_assets.h"

namespace cablefilm {
namespace {

constexpr char kBoundary[] = "cablefilmframe";
constexpr auto kStateEvery = std::chrono::milliseconds(200);  // state messages on /ws

void SendBody(mg_connection* c, int status, const char* type, const std::string& body,
              const char* extra_headers = "") {
  const char* reason = status == 200 ? "OK" : status == 400 ? "Bad Request"
                     : status == 404 ? "Not Found" : status == 405 ? "Method Not Allowed"
                     : status == 413 ? "Payload Too Large" : "Service Unavailable";
  mg_printf(c,
            "HTTP/1.1 %d %s\r\nContent-Type: %s\r\nContent-Length: %zu\r\n"
            "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n%s"
            "Connection: close\r\n\r\n",
            status, reason, type, body.size(), extra_headers);
  mg_write(c, body.data(), body.size());
}

void SendError(mg_connection* c, int status, const std::string& message) {
  std::string json = "{\"error\": \"";
  for (char ch : message) {  // the messages are ours (ASCII); escape what JSON needs
    if (ch == '"' || ch == '\\') json += '\\';
    if (static_cast<unsigned char>(ch) >= 0x20) json += ch;
  }
  json += "\"}";
  SendBody(c, status, "application/json", json);
}

// A viewer of /ws: its own sender thread takes the newest frame and the state when due.
struct WsViewer {
  mg_connection* conn = nullptr;
  std::thread sender;
  std::atomic<bool> closed{false};
};

}  // namespace

struct LiveServer::Impl {
  LiveSession& session;
  ServerOptions options;
  mg_context* ctx = nullptr;
  int port = 0;
  std::mutex mu;
  std::map<const mg_connection*, std::unique_ptr<WsViewer>> ws_viewers;
  std::atomic<int> streams{0};  // WebSocket and MJPEG viewers

  Impl(LiveSession& s, const ServerOptions& o) : session(s), options(o) {}

  bool TakeStreamSlot() {
    if (streams.fetch_add(1) >= options.max_viewers) {
      --streams;
      return false;
    }
    session.AddViewer(1);
    return true;
  }
  void ReleaseStreamSlot() {
    --streams;
    session.AddViewer(-1);
  }

  // ---- HTTP ----------------------------------------------------------------------------------
  int Handle(mg_connection* c) {
    const mg_request_info* ri = mg_get_request_info(c);
    const std::string uri = ri->local_uri ? ri->local_uri : "";
    const std::string method = ri->request_method ? ri->request_method : "";
    const bool get = method == "GET" || method == "HEAD";
    if (uri == "/control") {
      if (method != "POST") {
        SendError(c, 405, "/control takes POST with a JSON object");
        return 405;
      }
      return HandleControl(c, ri);
    }
    if (!get) {
      SendError(c, 405, uri + " takes GET");
      return 405;
    }
    if (uri == "/state") {
      SendBody(c, 200, "application/json", session.StateJson());
      return 200;
    }
    if (uri == "/frame.jpg") {
      const auto frame = session.NewestFrame();
      SendBody(c, 200, "image/jpeg", std::string(frame->jpeg(), frame->jpeg_size()));
      return 200;
    }
    if (uri == "/snapshot.png") {
      const std::string name = "Content-Disposition: attachment; filename=\"" +
                               session.scene_name() + "-t" + std::to_string(frame_t()) + ".png\"\r\n";
      try {
        SendBody(c, 200, "image/png", session.SnapshotPng(), name.c_str());
      } catch (const std::exception& e) {
        SendError(c, 503, e.what());
        return 503;
      }
      return 200;
    }
    if (uri == "/timeseries.csv") return HandleTimeseries(c);
    if (uri == "/stream.mjpg") return HandleMjpeg(c);
    if (uri.rfind("/recordings/", 0) == 0) {
      const std::string path = session.RecordingPath(uri.substr(std::strlen("/recordings/")));
      if (path.empty()) {
        SendError(c, 404, "no such recording of this session");
        return 404;
      }
      mg_send_mime_file(c, path.c_str(), "video/mp4");
      return 200;
    }
    if (const PageAsset* a = FindPageAsset(uri)) {
      SendBody(c, 200, a->mime_type, std::string(reinterpret_cast<const char*>(a->data), a->size));
      return 200;
    }
    SendError(c, 404, "not found: " + uri.substr(0, 100));
    return 404;
  }

  long frame_t() const {
    const auto f = session.NewestFrame();
    return f ? static_cast<long>(f->t) : 0;
  }

  int HandleControl(mg_connection* c, const mg_request_info* ri) {
    if (ri->content_length > static_cast<long long>(kMaxControlBytes)) {
      SendError(c, 413, "control: expected a JSON object of at most " +
                            std::to_string(kMaxControlBytes) + " bytes");
      return 413;
    }
    std::string body;
    char buf[1024];
    int n;
    while ((n = mg_read(c, buf, sizeof buf)) > 0) {
      body.append(buf, static_cast<std::size_t>(n));
      if (body.size() > kMaxControlBytes) break;  // chunked bodies: the parser says why
    }
    const LiveSession::Reply r = session.Control(body);
    SendBody(c, r.status, "application/json", r.json);
    return r.status;
  }

  int HandleTimeseries(mg_connection* c) {
    const std::string name = session.scene_name() + "-live-timeseries.csv";
    mg_printf(c,
              "HTTP/1.1 200 OK\r\nContent-Type: text/csv\r\nCache-Control: no-store\r\n"
              "Content-Disposition: attachment; filename=\"%s\"\r\nConnection: close\r\n\r\n",
              name.c_str());
    session.ReadTimeseries([&](const char* data, std::size_t size) {
      return mg_write(c, data, size) > 0;
    });
    return 200;
  }

  int HandleMjpeg(mg_connection* c) {
    if (!TakeStreamSlot()) {
      SendError(c, 503, "too many viewers (at most " + std::to_string(options.max_viewers) + ")");
      return 503;
    }
    mg_printf(c,
              "HTTP/1.1 200 OK\r\nContent-Type: multipart/x-mixed-replace; boundary=%s\r\n"
              "Cache-Control: no-store\r\nConnection: close\r\n\r\n--%s\r\n",
              kBoundary, kBoundary);
    std::uint64_t last = 0;
    while (!session.stopped()) {
      const auto frame = session.WaitFrame(last, std::chrono::milliseconds(500));
      if (!frame) continue;
      last = frame->number;
      char head[160];
      const int n = std::snprintf(head, sizeof head,
                                  "Content-Type: image/jpeg\r\nContent-Length: %zu\r\n"
                                  "X-Frame: %llu\r\n\r\n",
                                  frame->jpeg_size(), static_cast<unsigned long long>(frame->number));
      // The next part's boundary goes right after the image: a browser shows a part when it
      // sees the boundary that ends it, so this frame shows now, not when the next one comes.
      const std::string tail = std::string("\r\n--") + kBoundary + "\r\n";
      if (mg_write(c, head, static_cast<std::size_t>(n)) <= 0 ||
          mg_write(c, frame->jpeg(), frame->jpeg_size()) <= 0 ||
          mg_write(c, tail.data(), tail.size()) <= 0)
        break;
    }
    ReleaseStreamSlot();
    return 200;
  }

  // ---- WebSocket -----------------------------------------------------------------------------
  int WsConnect() { return streams >= options.max_viewers ? 1 : 0; }  // 1: refused

  void WsReady(mg_connection* c) {
    if (!TakeStreamSlot()) {  // raced past WsConnect's check: refuse politely
      const char why[] = "\x03\xf5too many viewers";  // close code 1013: try again later
      mg_websocket_write(c, MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE, why, sizeof why - 1);
      return;
    }
    auto viewer = std::make_unique<WsViewer>();
    viewer->conn = c;
    WsViewer* v = viewer.get();
    {
      std::lock_guard<std::mutex> lock(mu);
      ws_viewers[c] = std::move(viewer);
    }
    v->sender = std::thread([this, v] { WsSend(v); });
  }

  void WsSend(WsViewer* v) {
    std::uint64_t last = 0, state_sent = ~0ull;
    auto next_state = std::chrono::steady_clock::now();
    while (!v->closed && !session.stopped()) {
      const auto frame = session.WaitFrame(last, std::chrono::milliseconds(100));
      if (v->closed) break;
      if (frame) {
        last = frame->number;
        if (mg_websocket_write(v->conn, MG_WEBSOCKET_OPCODE_BINARY, frame->message.data(),
                               frame->message.size()) <= 0)
          break;
      }
      const auto now = std::chrono::steady_clock::now();
      const std::uint64_t version = session.state_version();
      if (now >= next_state || version != state_sent) {
        std::string msg = session.StateJson();
        msg.insert(1, "\"type\": \"state\", ");
        if (mg_websocket_write(v->conn, MG_WEBSOCKET_OPCODE_TEXT, msg.data(), msg.size()) <= 0)
          break;
        state_sent = version;
        next_state = now + kStateEvery;
      }
    }
  }

  int WsData(mg_connection* c, int bits, char* data, std::size_t size) {
    const int opcode = bits & 0x0f;
    if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
    if (opcode != MG_WEBSOCKET_OPCODE_TEXT) return 1;  // pings are answered by civetweb
    const LiveSession::Reply r = session.Control(std::string(data, size));
    std::string msg = r.status == 200
                          ? "{\"type\": \"reply\", \"ok\": true, \"state\": " + r.json + "}"
                          : "{\"type\": \"reply\", \"ok\": false, " + r.json.substr(1);
    mg_websocket_write(c, MG_WEBSOCKET_OPCODE_TEXT, msg.data(), msg.size());
    return 1;
  }

  void WsClose(const mg_connection* c) {
    std::unique_ptr<WsViewer> viewer;
    {
      std::lock_guard<std::mutex> lock(mu);
      auto it = ws_viewers.find(c);
      if (it != ws_viewers.end()) {
        viewer = std::move(it->second);
        ws_viewers.erase(it);
      }
    }
    if (!viewer) return;  // refused in WsReady: holds no slot
    // The connection is still valid here (civetweb frees it after this returns): the sender
    // must be done with it first. A blocked write ends with the socket's timeout.
    viewer->closed = true;
    if (viewer->sender.joinable()) viewer->sender.join();
    ReleaseStreamSlot();
  }
};

namespace {

int OnRequest(mg_connection* c, void* impl) { return static_cast<LiveServer::Impl*>(impl)->Handle(c); }
int OnWsConnect(const mg_connection*, void* impl) {
  return static_cast<LiveServer::Impl*>(impl)->WsConnect();
}
void OnWsReady(mg_connection* c, void* impl) { static_cast<LiveServer::Impl*>(impl)->WsReady(c); }
int OnWsData(mg_connection* c, int bits, char* data, std::size_t size, void* impl) {
  return static_cast<LiveServer::Impl*>(impl)->WsData(c, bits, data, size);
}
void OnWsClose(const mg_connection* c, void* impl) {
  static_cast<LiveServer::Impl*>(impl)->WsClose(c);
}
int OnLog(const mg_connection*, const char*) { return 1; }  // quiet: errors reach the viewer

}  // namespace

LiveServer::LiveServer(LiveSession& session, const ServerOptions& options)
    : impl_(std::make_unique<Impl>(session, options)) {
  if (options.port < 0 || options.port > 65535)
    throw Error("live: --port must be 0..65535, got " + std::to_string(options.port));
  if (options.bind.empty() || options.bind.find_first_of(":/ ,") != std::string::npos)
    throw Error("live: --bind expects an IPv4 address such as 127.0.0.1, got \"" + options.bind + "\"");
  mg_init_library(0);
  const std::string ports = options.bind + ":" + std::to_string(options.port);
  const std::string threads = std::to_string(options.max_viewers + 16);
  // Nagle's algorithm would hold each frame's tail for ~25 ms: off. Socket operations time
  // out after 10 s, which bounds a write to a stalled viewer; WebSocket pings keep idle
  // viewers and detect dead ones.
  const char* opts[] = {"listening_ports", ports.c_str(), "num_threads", threads.c_str(),
                        "tcp_nodelay", "1", "request_timeout_ms", "10000",
                        "websocket_timeout_ms", "10000", "enable_websocket_ping_pong", "yes",
                        "enable_keep_alive", "no", nullptr};
  mg_callbacks callbacks{};
  callbacks.log_message = OnLog;
  impl_->ctx = mg_start(&callbacks, impl_.get(), opts);
  if (!impl_->ctx)
    throw Error("live: cannot listen on " + ports + " (in use, or not an address of this machine)");
  mg_set_websocket_handler(impl_->ctx, "/ws$", OnWsConnect, OnWsReady, OnWsData, OnWsClose,
                           impl_.get());
  mg_set_request_handler(impl_->ctx, "/", OnRequest, impl_.get());
  mg_server_port p[4]{};
  if (mg_get_server_ports(impl_->ctx, 4, p) < 1) {
    mg_stop(impl_->ctx);
    throw Error("live: the server did not report its port");
  }
  impl_->port = p[0].port;
}

LiveServer::~LiveServer() {
  if (impl_->ctx) mg_stop(impl_->ctx);
}

int LiveServer::port() const { return impl_->port; }

std::string LiveServer::url() const {
  return "http://" + impl_->options.bind + ":" + std::to_string(impl_->port) + "/";
}

}  // namespace cablefilm
