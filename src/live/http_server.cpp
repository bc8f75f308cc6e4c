#include "live/http_server.h"

#include <arpa/inet.h>
#include <civetweb.h>
#include <dirent.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "core/error.h"
#include "live/content_disposition.h"
#include "live/page_assets.h"

namespace cablefilm {
namespace {

using Clock = std::chrono::steady_clock;

constexpr char kBoundary[] = "cablefilmframe";
constexpr char kTokenCookie[] = "cablefilm_token";
constexpr auto kStateEvery = std::chrono::milliseconds(200);  // state messages on /ws
// A viewer's socket that takes no bytes for this long is dropped: a stalled viewer holds a
// worker and a stream slot no longer.
constexpr auto kWriteTimeout = std::chrono::seconds(10);
constexpr auto kWsPingEvery = std::chrono::seconds(10);
// A WebSocket from which nothing (not even the pong to our ping) came for this long is closed.
constexpr auto kWsIdle = std::chrono::seconds(30);
// Workers beyond the streams: plain requests (the page, /state, controls) always find one
// free however many viewers stream, and idle connections need this many to block them, each
// for at most the header timeout below.
constexpr int kSpareWorkers = 64;
// Request headers must arrive within this (browsers and scripts send them at once); an idle
// or trickling connection gives its worker back after it. civetweb also bounds each write of
// a plain response (and of an MJPEG part) by it.
constexpr char kRequestTimeoutMs[] = "3000";

bool Equal(const char* a, const char* b) { return a && b && mg_strcasecmp(a, b) == 0; }

std::string Lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

bool IsHead(const mg_connection* c) {
  return std::strcmp(mg_get_request_info(c)->request_method, "HEAD") == 0;
}

const char* Reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 413: return "Payload Too Large";
    case 421: return "Misdirected Request";
    case 426: return "Upgrade Required";
    case 500: return "Internal Server Error";
    default: return "Service Unavailable";
  }
}

// The whole response; a HEAD request gets the same headers without the body.
void SendBody(mg_connection* c, int status, const char* type, const std::string& body,
              const std::string& extra_headers = "") {
  mg_printf(c,
            "HTTP/1.1 %d %s\r\nContent-Type: %s\r\nContent-Length: %zu\r\n"
            "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n%s"
            "Connection: close\r\n\r\n",
            status, Reason(status), type, body.size(), extra_headers.c_str());
  if (!IsHead(c)) mg_write(c, body.data(), body.size());
}

std::string JsonString(const std::string& message) {
  std::string json = "\"";
  for (char ch : message) {  // the messages are ours (ASCII); escape what JSON needs
    if (ch == '"' || ch == '\\') json += '\\';
    if (static_cast<unsigned char>(ch) >= 0x20) json += ch;
  }
  return json + "\"";
}

int SendError(mg_connection* c, int status, const std::string& message,
              const std::string& extra_headers = "") {
  SendBody(c, status, "application/json", "{\"error\": " + JsonString(message) + "}",
           extra_headers);
  return status;
}

// ---- SHA-1 and base64, for the WebSocket handshake's Sec-WebSocket-Accept (RFC 6455) --------
std::string Sha1(const std::string& text) {
  std::uint32_t h[5] = {0x67452301, 0xEFCDAB89, 0x98BADCFE, 0x10325476, 0xC3D2E1F0};
  std::string m = text;
  const std::uint64_t bits = static_cast<std::uint64_t>(text.size()) * 8;
  m += '\x80';
  while (m.size() % 64 != 56) m += '\0';
  for (int i = 7; i >= 0; --i) m += static_cast<char>((bits >> (8 * i)) & 0xff);
  auto rol = [](std::uint32_t x, int n) { return (x << n) | (x >> (32 - n)); };
  for (std::size_t off = 0; off < m.size(); off += 64) {
    std::uint32_t w[80];
    for (int i = 0; i < 16; ++i)
      w[i] = static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i])) << 24 |
             static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 1])) << 16 |
             static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 2])) << 8 |
             static_cast<std::uint32_t>(static_cast<unsigned char>(m[off + 4 * i + 3]));
    for (int i = 16; i < 80; ++i) w[i] = rol(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
    std::uint32_t a = h[0], b = h[1], cc = h[2], d = h[3], e = h[4];
    for (int i = 0; i < 80; ++i) {
      std::uint32_t f, k;
      if (i < 20) f = (b & cc) | (~b & d), k = 0x5A827999;
      else if (i < 40) f = b ^ cc ^ d, k = 0x6ED9EBA1;
      else if (i < 60) f = (b & cc) | (b & d) | (cc & d), k = 0x8F1BBCDC;
      else f = b ^ cc ^ d, k = 0xCA62C1D6;
      const std::uint32_t t = rol(a, 5) + f + e + k + w[i];
      e = d, d = cc, cc = rol(b, 30), b = a, a = t;
    }
    h[0] += a, h[1] += b, h[2] += cc, h[3] += d, h[4] += e;
  }
  std::string out;
  for (std::uint32_t v : h)
    for (int i = 3; i >= 0; --i) out += static_cast<char>((v >> (8 * i)) & 0xff);
  return out;
}

std::string Base64(const std::string& bytes) {
  static const char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

// ---- Sockets ----------------------------------------------------------------------------------
// Reads and drops what the peer has sent so far (a megabyte at most a call); false once it has
// hung up or the socket failed.
bool DropInput(int fd) {
  char buf[16384];
  for (int i = 0; i < 64; ++i) {
    const ssize_t n = ::recv(fd, buf, sizeof buf, MSG_DONTWAIT);
    if (n > 0) continue;
    return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR);
  }
  return true;
}

// Sends all of `data` before `deadline`; false if the peer is gone or takes nothing meanwhile.
// With `drain`, what the peer sends meanwhile is read and dropped: a peer blocked sending reads
// nothing, so it could otherwise never take what is sent to it.
bool SendAll(int fd, const char* data, std::size_t size, Clock::time_point deadline,
             bool drain = false) {
  while (size > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, static_cast<short>(POLLOUT | (drain ? POLLIN : 0)), 0};
    const int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (r < 0 && errno != EINTR) return false;
    if (r <= 0) continue;
    if (drain && (p.revents & POLLIN) && !DropInput(fd)) drain = false;  // hung up: send only
    if (!(p.revents & (POLLOUT | POLLERR | POLLHUP))) continue;
    const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The socket of the connection civetweb is serving `ri` on: the one whose peer and local port
// are the request's (a TCP connection is unique by its two ends). -1 if none.
int FindSocket(const mg_request_info* ri) {
  in_addr want{};
  if (inet_pton(AF_INET, ri->remote_addr, &want) != 1) return -1;
  DIR* dir = opendir("/proc/self/fd");
  if (!dir) return -1;
  int found = -1;
  while (dirent* e = readdir(dir)) {
    char* end = nullptr;
    const long fd = std::strtol(e->d_name, &end, 10);
    if (end == e->d_name || *end != '\0') continue;
    sockaddr_in peer{}, local{};
    socklen_t n = sizeof peer, m = sizeof local;
    if (getpeername(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&peer), &n) != 0 ||
        peer.sin_family != AF_INET || peer.sin_addr.s_addr != want.s_addr ||
        ntohs(peer.sin_port) != ri->remote_port)
      continue;
    if (getsockname(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&local), &m) == 0 &&
        ntohs(local.sin_port) == ri->server_port) {
      found = static_cast<int>(fd);
      break;
    }
  }
  closedir(dir);
  return found;
}

// ---- WebSocket framing (RFC 6455), server side -----------------------------------------------
enum : int { kWsContinuation = 0, kWsText = 1, kWsBinary = 2, kWsClose = 8, kWsPing = 9, kWsPong = 10 };

struct WsViewer {
  int fd = -1;
  std::timed_mutex write_mu;  // one frame at a time on the socket: the sender's and the reader's
  // No frame begins once a close is under way (`closing`), and none at all once the close is
  // sent, a write failed (a frame cut short leaves nothing after it readable) or the reader is
  // done (`closed`, which also stops the sender).
  std::atomic<bool> closing{false}, closed{false};

  bool Write(int opcode, const char* data, std::size_t size) {
    std::lock_guard<std::timed_mutex> lock(write_mu);
    if (closing || closed) return false;
    return WriteLocked(opcode, data, size, false);
  }
  bool Write(int opcode, const std::string& s) { return Write(opcode, s.data(), s.size()); }

  // The close frame, whole and last (RFC 6455 5.5.1): after the frame the sender may be
  // writing, never within it, and with no frame after it. What the peer sends meanwhile is read
  // and dropped: a peer still sending (a refused 1 GiB message) may read nothing until its send
  // is taken, and the frame being written to it could not end.
  void Close(int code, const std::string& reason) {
    closing = true;
    std::unique_lock<std::timed_mutex> lock(write_mu, std::defer_lock);
    const auto deadline = Clock::now() + kWriteTimeout + std::chrono::seconds(1);
    bool peer_sends = true;
    while (!lock.try_lock_for(std::chrono::milliseconds(10))) {
      if (Clock::now() >= deadline) {  // not reached: the sender's writes have a deadline
        closed = true;
        return;
      }
      if (peer_sends) peer_sends = DropInput(fd);
    }
    if (!closed) {
      std::string payload{static_cast<char>(code >> 8), static_cast<char>(code & 0xff)};
      payload += reason.substr(0, 120);
      WriteLocked(kWsClose, payload.data(), payload.size(), true);
    }
    closed = true;
  }

 private:
  bool WriteLocked(int opcode, const char* data, std::size_t size, bool drain) {
    char head[10];
    std::size_t n = 2;
    head[0] = static_cast<char>(0x80 | opcode);
    if (size < 126) {
      head[1] = static_cast<char>(size);
    } else if (size <= 0xffff) {
      head[1] = 126;
      head[2] = static_cast<char>(size >> 8);
      head[3] = static_cast<char>(size & 0xff);
      n = 4;
    } else {
      head[1] = 127;
      for (int i = 0; i < 8; ++i) head[2 + i] = static_cast<char>((std::uint64_t{size} >> (56 - 8 * i)) & 0xff);
      n = 10;
    }
    const auto deadline = Clock::now() + kWriteTimeout;
    if (!SendAll(fd, head, n, deadline, drain) || !SendAll(fd, data, size, deadline, drain)) {
      closed = true;
      return false;
    }
    return true;
  }
};

// Reads frames from what arrived: each one whole (a control message, a ping) is handed to
// `on_frame`. A frame or message announcing more than kMaxWsMessageBytes, an unmasked frame
// and the like are protocol errors returned as a close code before their payload is read, so
// the buffer never holds more than one header and one control message.
class WsParser {
 public:
  struct Frame {
    int opcode;
    std::string payload;
  };
  // 0 and the frames taken out of `in`, or a close code (1002 protocol, 1009 too big).
  int Take(std::string& in, std::vector<Frame>& out) {
    while (in.size() >= 2) {
      const auto b0 = static_cast<unsigned char>(in[0]), b1 = static_cast<unsigned char>(in[1]);
      const bool fin = b0 & 0x80, masked = b1 & 0x80;
      const int opcode = b0 & 0x0f;
      if ((b0 & 0x70) || !masked) return 1002;  // no extensions; clients must mask
      std::size_t head = 2;
      std::uint64_t len = b1 & 0x7f;
      if (len == 126) head += 2;
      if (len == 127) head += 8;
      if (in.size() < head) return 0;
      if (len == 126) len = static_cast<unsigned char>(in[2]) << 8 | static_cast<unsigned char>(in[3]);
      if (len == 127) {
        len = 0;
        for (int i = 0; i < 8; ++i) len = len << 8 | static_cast<unsigned char>(in[2 + i]);
      }
      if (opcode >= 8) {
        if (opcode > kWsPong || !fin || len > 125) return 1002;
      } else {
        if (opcode > kWsBinary) return 1002;
        if ((opcode == kWsContinuation) != (message_opcode_ != 0)) return 1002;
        if (len > kMaxWsMessageBytes - message_.size()) return 1009;  // before reading it
      }
      head += 4;
      if (in.size() < head + len) return 0;
      std::string payload = in.substr(head, len);
      for (std::size_t i = 0; i < payload.size(); ++i) payload[i] ^= in[head - 4 + i % 4];
      in.erase(0, head + len);
      if (opcode >= 8) {
        out.push_back({opcode, std::move(payload)});
        continue;
      }
      if (opcode != kWsContinuation) message_opcode_ = opcode;
      message_ += payload;
      if (fin) {
        out.push_back({message_opcode_, std::move(message_)});
        message_.clear();
        message_opcode_ = 0;
      }
    }
    return 0;
  }

 private:
  int message_opcode_ = 0;  // of a fragmented message under way
  std::string message_;
};

// ---- The doors ----------------------------------------------------------------------------------
// The host of a Host header or an Origin's authority, lower case, without the port; empty if
// malformed (a port that is not a number, an unclosed bracket).
std::string HostName(const std::string& authority) {
  std::string host = authority, port;
  if (!host.empty() && host[0] == '[') {
    const std::size_t close = host.find(']');
    if (close == std::string::npos) return "";
    port = host.substr(close + 1);
    host = host.substr(0, close + 1);
    if (!port.empty() && port[0] != ':') return "";
    if (!port.empty()) port.erase(0, 1);
  } else if (const std::size_t colon = host.rfind(':'); colon != std::string::npos) {
    port = host.substr(colon + 1);
    host = host.substr(0, colon);
  }
  if (port.size() > 5 ||
      !std::all_of(port.begin(), port.end(), [](unsigned char ch) { return std::isdigit(ch); }))
    return "";
  return Lower(host);
}

bool ConstantTimeEqual(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

}  // namespace

std::string MakeToken() {
  std::ifstream in("/dev/urandom", std::ios::binary);
  unsigned char bytes[16];
  if (!in.read(reinterpret_cast<char*>(bytes), sizeof bytes))
    throw Error("live: cannot read /dev/urandom for the access token");
  static const char kHex[] = "0123456789abcdef";
  std::string token;
  for (unsigned char b : bytes) {
    token += kHex[b >> 4];
    token += kHex[b & 15];
  }
  return token;
}

struct LiveServer::Impl {
  LiveSession& session;
  ServerOptions options;
  std::string listen_address;  // what civetweb listens on ("localhost" is 127.0.0.1)
  mg_context* ctx = nullptr;
  int port = 0;
  std::atomic<int> streams{0};  // WebSocket and MJPEG viewers
  std::atomic<bool> stopping{false};

  Impl(LiveSession& s, const ServerOptions& o)
      : session(s), options(o), listen_address(o.bind == "localhost" ? "127.0.0.1" : o.bind) {}

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

  // A Host this server answers to: a DNS name other than localhost is refused, so a page of a
  // name rebound to this address cannot reach it.
  bool HostAllowed(const char* header) const {
    if (!header) return true;  // HTTP/1.0 without Host: nothing was resolved by name
    const std::string host = HostName(header);
    if (host.empty()) return false;
    if (host == "localhost" || host == "127.0.0.1" || host == "[::1]") return true;
    const std::string bound = Lower(listen_address);
    if (host == bound || host == "[" + bound + "]") return true;
    // Bound to every interface: any of the machine's addresses, so any address literal.
    if (bound == "0.0.0.0" || bound == "::" || bound == "[::]")
      return IsIpv4Address(host) || (host.size() > 2 && host.front() == '[' && IsIpv6Address(host.substr(1, host.size() - 2)));
    return false;
  }

  // A request made by a page of another origin: its Origin is not this server as its Host
  // names it, or the browser says it comes from another site.
  static bool Foreign(const mg_connection* c) {
    const char* origin = mg_get_header(c, "Origin");
    if (origin) {
      const char* host = mg_get_header(c, "Host");
      if (!host || Lower(origin) != "http://" + Lower(host)) return true;
    }
    const char* site = mg_get_header(c, "Sec-Fetch-Site");
    return Equal(site, "cross-site") || Equal(site, "same-site");
  }

  // The token from ?token= or the cookie; empty if none.
  static std::string OfferedToken(const mg_connection* c, bool* from_query) {
    const mg_request_info* ri = mg_get_request_info(c);
    char value[128];
    *from_query = false;
    if (ri->query_string && mg_get_var(ri->query_string, std::strlen(ri->query_string), "token",
                                       value, sizeof value) > 0) {
      *from_query = true;
      return value;
    }
    const char* cookie = mg_get_header(c, "Cookie");
    if (cookie && mg_get_cookie(cookie, kTokenCookie, value, sizeof value) > 0) return value;
    return "";
  }

  // ---- HTTP ----------------------------------------------------------------------------------
  int Handle(mg_connection* c) {
    const mg_request_info* ri = mg_get_request_info(c);
    const std::string uri = ri->local_uri ? ri->local_uri : "";
    const std::string method = ri->request_method ? ri->request_method : "";
    if (!HostAllowed(mg_get_header(c, "Host")))
      return SendError(c, 421, "this server answers to " + listen_address +
                                   ", 127.0.0.1 or localhost, not the Host this request names");
    std::string cookie_header;
    if (!options.token.empty()) {
      bool from_query = false;
      if (!ConstantTimeEqual(OfferedToken(c, &from_query), options.token))
        return SendError(c, 401, "this live view needs the token of the address it printed "
                                 "(http://...:PORT/?token=...)");
      // Kept by the page for its own requests (its WebSocket cannot carry a header).
      if (from_query)
        cookie_header = std::string("Set-Cookie: ") + kTokenCookie + "=" + options.token +
                        "; Path=/; HttpOnly; SameSite=Strict\r\n";
    }
    const PageAsset* asset = FindPageAsset(uri);
    // The page itself may be opened from a link anywhere; everything else (state, frames,
    // controls, streams, recordings) only from the page.
    if (!asset && Foreign(c))
      return SendError(c, 403, "requests from another site's page are refused");
    const bool get = method == "GET" || method == "HEAD";
    if (uri == "/control") {
      if (method != "POST")
        return SendError(c, 405, "/control takes POST with a JSON object", "Allow: POST\r\n");
      return HandleControl(c, ri);
    }
    if (uri == "/ws") {
      if (method != "GET") return SendError(c, 405, "/ws takes a WebSocket upgrade (GET)", "Allow: GET\r\n");
      return HandleWebSocket(c, ri);
    }
    if (!get) return SendError(c, 405, uri.substr(0, 100) + " takes GET", "Allow: GET, HEAD\r\n");
    if (uri == "/state") {
      SendBody(c, 200, "application/json", session.StateJson());
      return 200;
    }
    if (uri == "/frame.jpg") {
      if (IsHead(c)) {
        SendBody(c, 200, "image/jpeg", "");
        return 200;
      }
      const auto frame = session.FreshFrame(std::chrono::milliseconds(2000));
      SendBody(c, 200, "image/jpeg", std::string(frame->jpeg(), frame->jpeg_size()));
      return 200;
    }
    if (uri == "/snapshot.png") {
      const std::string name =
          ContentDisposition(session.scene_name() + "-t" + std::to_string(frame_t()) + ".png");
      if (IsHead(c)) {
        SendBody(c, 200, "image/png", "", name);
        return 200;
      }
      try {
        SendBody(c, 200, "image/png", session.SnapshotPng(), name);
      } catch (const std::exception& e) {
        return SendError(c, 503, e.what());
      }
      return 200;
    }
    if (uri == "/timeseries.csv") return HandleTimeseries(c);
    if (uri == "/stream.mjpg") return HandleMjpeg(c);
    if (uri.rfind("/recordings/", 0) == 0) {
      const std::string path = session.RecordingPath(uri.substr(std::strlen("/recordings/")));
      if (path.empty()) return SendError(c, 404, "no such recording of this session");
      mg_send_mime_file(c, path.c_str(), "video/mp4");  // answers HEAD without the body
      return 200;
    }
    if (asset) {
      SendBody(c, 200, asset->mime_type,
               std::string(reinterpret_cast<const char*>(asset->data), asset->size), cookie_header);
      return 200;
    }
    return SendError(c, 404, "not found: " + uri.substr(0, 100));
  }

  long frame_t() const {
    const auto f = session.NewestFrame();
    return f ? static_cast<long>(f->t) : 0;
  }

  int HandleControl(mg_connection* c, const mg_request_info* ri) {
    if (ri->content_length > static_cast<long long>(kMaxControlBytes))
      return SendError(c, 413, "control: expected a JSON object of at most " +
                                   std::to_string(kMaxControlBytes) + " bytes");
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
    const std::string name = ContentDisposition(session.scene_name() + "-live-timeseries.csv");
    mg_printf(c,
              "HTTP/1.1 200 OK\r\nContent-Type: text/csv\r\nCache-Control: no-store\r\n"
              "%sConnection: close\r\n\r\n",
              name.c_str());
    if (IsHead(c)) return 200;
    session.ReadTimeseries([&](const char* data, std::size_t size) {
      return mg_write(c, data, size) > 0;
    });
    return 200;
  }

  int TooMany(mg_connection* c) {
    return SendError(c, 503, "too many viewers (at most " + std::to_string(options.max_viewers) +
                                 " streams at once); try again later",
                     "Retry-After: 5\r\n");
  }

  int HandleMjpeg(mg_connection* c) {
    if (IsHead(c)) {
      mg_printf(c,
                "HTTP/1.1 200 OK\r\nContent-Type: multipart/x-mixed-replace; boundary=%s\r\n"
                "Cache-Control: no-store\r\nConnection: close\r\n\r\n",
                kBoundary);
      return 200;
    }
    if (!TakeStreamSlot()) return TooMany(c);
    mg_printf(c,
              "HTTP/1.1 200 OK\r\nContent-Type: multipart/x-mixed-replace; boundary=%s\r\n"
              "Cache-Control: no-store\r\nConnection: close\r\n\r\n--%s\r\n",
              kBoundary, kBoundary);
    std::uint64_t last = 0;
    while (!session.stopped() && !stopping) {
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
  // Served here rather than by civetweb's WebSocket support: civetweb (1.15) reads each frame
  // whole into memory before a handler sees it, whatever its header announces (up to 2 GiB),
  // with no option to limit it. After the handshake this worker reads the frames itself from
  // the connection's socket, refusing an oversized one by its header, while a thread of the
  // viewer's own writes the frames and the state.
  int HandleWebSocket(mg_connection* c, const mg_request_info* ri) {
    const char* upgrade = mg_get_header(c, "Upgrade");
    const char* key = mg_get_header(c, "Sec-WebSocket-Key");
    const char* version = mg_get_header(c, "Sec-WebSocket-Version");
    const char* connection = mg_get_header(c, "Connection");
    if (!Equal(upgrade, "websocket") || !connection ||
        Lower(connection).find("upgrade") == std::string::npos)
      return SendError(c, 426, "/ws is a WebSocket: expected Upgrade: websocket", "Upgrade: websocket\r\n");
    if (!key || std::strlen(key) != 24 || !Equal(version, "13"))
      return SendError(c, 400, "/ws: expected Sec-WebSocket-Key (24 characters) and Sec-WebSocket-Version: 13",
                       "Sec-WebSocket-Version: 13\r\n");
    if (IsHead(c)) return SendError(c, 405, "/ws takes GET");
    const int fd = FindSocket(ri);
    if (fd < 0) return SendError(c, 500, "/ws: the connection's socket was not found");
    if (!TakeStreamSlot()) return TooMany(c);
    const std::string accept = Base64(Sha1(std::string(key) + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11"));
    const std::string response =
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Accept: " + accept + "\r\n\r\n";
    WsViewer viewer;
    viewer.fd = fd;
    if (SendAll(fd, response.data(), response.size(), Clock::now() + kWriteTimeout)) {
      std::thread sender([this, &viewer] { WsSend(&viewer); });
      WsRead(&viewer);
      viewer.closed = true;
      sender.join();
    }
    ReleaseStreamSlot();
    return 101;
  }

  void WsSend(WsViewer* v) {
    std::uint64_t last = 0, state_sent = ~0ull;
    auto next_state = Clock::now();
    while (!v->closed && !v->closing && !session.stopped() && !stopping) {
      const auto frame = session.WaitFrame(last, std::chrono::milliseconds(100));
      if (v->closed || v->closing) break;
      if (frame) {
        last = frame->number;
        if (!v->Write(kWsBinary, frame->message)) break;
      }
      const auto now = Clock::now();
      const std::uint64_t version = session.state_version();
      if (now >= next_state || version != state_sent) {
        std::string msg = session.StateJson();
        msg.insert(1, "\"type\": \"state\", ");
        if (!v->Write(kWsText, msg)) break;
        state_sent = version;
        next_state = now + kStateEvery;
      }
    }
  }

  void WsRead(WsViewer* v) {
    WsParser parser;
    std::string in;
    std::vector<WsParser::Frame> frames;
    auto last_heard = Clock::now(), last_ping = last_heard;
    while (!v->closed && !session.stopped() && !stopping) {
      pollfd p{v->fd, POLLIN, 0};
      const int r = ::poll(&p, 1, 200);
      if (r < 0 && errno != EINTR) return;
      const auto now = Clock::now();
      if (r > 0) {
        char buf[4096];
        const ssize_t n = ::recv(v->fd, buf, sizeof buf, MSG_DONTWAIT);
        if (n == 0) return;  // the viewer hung up: nobody to say goodbye to
        if (n < 0) {
          if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) continue;
          return;
        }
        in.append(buf, static_cast<std::size_t>(n));
        last_heard = now;
        frames.clear();
        const int error = parser.Take(in, frames);
        for (const WsParser::Frame& f : frames) {
          if (f.opcode == kWsClose) {
            v->Close(1000, "");
            return;
          }
          if (f.opcode == kWsPing) v->Write(kWsPong, f.payload);
          if (f.opcode == kWsText || f.opcode == kWsBinary) WsControl(v, f);
        }
        if (error) {
          v->Close(error, error == 1009 ? "a message is at most " + std::to_string(kMaxWsMessageBytes) + " bytes"
                                        : "protocol error");
          return;
        }
      }
      if (now - last_heard > kWsIdle) {
        v->Close(1001, "idle");
        return;
      }
      if (now - last_ping > kWsPingEvery) {
        v->Write(kWsPing, "", 0);
        last_ping = now;
      }
    }
    if (!v->closed) v->Close(1001, "the live view is stopping");
  }

  void WsControl(WsViewer* v, const WsParser::Frame& f) {
    const LiveSession::Reply r = f.opcode == kWsText
        ? session.Control(f.payload)
        : LiveSession::Reply{400, "{\"error\": \"controls are JSON text messages, not binary\"}"};
    const std::string msg = r.status == 200
                                ? "{\"type\": \"reply\", \"ok\": true, \"state\": " + r.json + "}"
                                : "{\"type\": \"reply\", \"ok\": false, " + r.json.substr(1);
    v->Write(kWsText, msg);
  }
};

namespace {

// Every request, before civetweb's own handling (its CORS preflight answers, its WebSocket
// upgrade): a status > 0 tells it the request was answered.
int OnBeginRequest(mg_connection* c) {
  const mg_request_info* ri = mg_get_request_info(c);
  return static_cast<LiveServer::Impl*>(ri->user_data)->Handle(c);
}
int OnLog(const mg_connection*, const char*) { return 1; }  // quiet: errors reach the viewer

}  // namespace

LiveServer::LiveServer(LiveSession& session, const ServerOptions& options)
    : impl_(std::make_unique<Impl>(session, options)) {
  if (options.port < 0 || options.port > 65535)
    throw Error("live: --port must be 0..65535, got " + std::to_string(options.port));
  if (const std::string why = BindAddressProblem(options.bind); !why.empty())
    throw Error("live: " + why);
  mg_init_library(0);
  const std::string& address = impl_->listen_address;
  const std::string ports = (IsIpv6Address(address) ? "[" + address + "]" : address) + ":" +
                            std::to_string(options.port);
  const std::string threads = std::to_string(options.max_viewers + kSpareWorkers);
  // Nagle's algorithm would hold each frame's tail for ~25 ms: off. No CORS: civetweb's
  // default answers preflights with Access-Control-Allow-Origin: *, which lets any page's
  // script read and steer the view.
  const char* opts[] = {"listening_ports", ports.c_str(), "num_threads", threads.c_str(),
                        "tcp_nodelay", "1", "request_timeout_ms", kRequestTimeoutMs,
                        "enable_keep_alive", "no", "access_control_allow_origin", "",
                        "access_control_allow_methods", "", "access_control_allow_headers", "",
                        nullptr};
  mg_callbacks callbacks{};
  callbacks.log_message = OnLog;
  callbacks.begin_request = OnBeginRequest;
  impl_->ctx = mg_start(&callbacks, impl_.get(), opts);
  if (!impl_->ctx)
    throw Error("live: cannot listen on " + ports + " (in use, or not an address of this machine)");
  mg_server_port p[4]{};
  if (mg_get_server_ports(impl_->ctx, 4, p) < 1) {
    mg_stop(impl_->ctx);
    throw Error("live: the server did not report its port");
  }
  impl_->port = p[0].port;
}

LiveServer::~LiveServer() {
  impl_->stopping = true;  // streams end within their poll interval
  if (impl_->ctx) mg_stop(impl_->ctx);
}

int LiveServer::port() const { return impl_->port; }

std::string LiveServer::url() const {
  const std::string& a = impl_->listen_address;
  std::string u = "http://" + (IsIpv6Address(a) ? "[" + a + "]" : a) + ":" + std::to_string(impl_->port) + "/";
  if (!impl_->options.token.empty()) u += "?token=" + impl_->options.token;
  return u;
}

}  // namespace cablefilm
