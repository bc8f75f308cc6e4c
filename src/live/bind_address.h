#pragma once
// The address the live view listens on, checked before anything is loaded (the command line
// checks --bind with these; the program links them without the live view, which it loads as a
// module when it serves).
#include <string>

namespace cablefilm {

bool IsIpv4Address(const std::string& s);
bool IsIpv6Address(const std::string& s);  // without brackets
// Why `bind` cannot be listened on ("" if it can): an IPv4 address or "localhost" (and an
// IPv6 address where civetweb was built with IPv6).
std::string BindAddressProblem(const std::string& bind);
// 127.0.0.0/8, ::1 and localhost: only this machine can connect.
bool IsLoopbackAddress(const std::string& bind);

}  // namespace cablefilm
