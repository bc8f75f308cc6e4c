#include "live/bind_address.h"

#include <arpa/inet.h>
#include <civetweb.h>
#include <netinet/in.h>

namespace cablefilm {

bool IsIpv4Address(const std::string& s) {
  in_addr a{};
  return inet_pton(AF_INET, s.c_str(), &a) == 1;
}

bool IsIpv6Address(const std::string& s) {
  in6_addr a{};
  return inet_pton(AF_INET6, s.c_str(), &a) == 1;
}

std::string BindAddressProblem(const std::string& bind) {
  if (bind == "localhost" || IsIpv4Address(bind)) return "";
  std::string v6 = bind;
  if (v6.size() > 2 && v6.front() == '[' && v6.back() == ']') v6 = v6.substr(1, v6.size() - 2);
  if (IsIpv6Address(v6)) {
    if (mg_check_feature(8)) return "";
    return "--bind: this build's civetweb has no IPv6; expected an IPv4 address such as "
           "127.0.0.1, got \"" + bind + "\"";
  }
  std::string shown = bind.substr(0, 80);
  for (char& ch : shown)
    if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f) ch = '?';
  return "--bind: expected an IPv4 address such as 127.0.0.1 (or localhost), got \"" + shown + "\"";
}

bool IsLoopbackAddress(const std::string& bind) {
  if (bind == "localhost" || bind == "::1" || bind == "[::1]") return true;
  in_addr a{};
  return inet_pton(AF_INET, bind.c_str(), &a) == 1 && (ntohl(a.s_addr) >> 24) == 127;
}

}  // namespace cablefilm
