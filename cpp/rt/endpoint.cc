#include "endpoint.h"

#include <arpa/inet.h>

#include <cstdlib>
#include <stdexcept>

namespace armrt::rt {

namespace {
in_addr parse_host(std::string host, const std::string& whole) {
  if (host.empty() || host == "localhost") host = "127.0.0.1";
  in_addr a{};
  if (inet_pton(AF_INET, host.c_str(), &a) != 1)
    throw std::invalid_argument("bad IPv4 address in '" + whole + "' (numeric addresses or localhost)");
  return a;
}
std::uint16_t parse_port(const std::string& port, const std::string& whole, bool require) {
  char* end = nullptr;
  const long p = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || p < (require ? 1 : 0) || p > 65535)
    throw std::invalid_argument("bad port in '" + whole + "' (" + (require ? "1" : "0") + "..65535)");
  return static_cast<std::uint16_t>(p);
}
}  // namespace

sockaddr_in parse_endpoint(const std::string& s, bool require_port) {
  const auto colon = s.rfind(':');
  if (colon == std::string::npos) throw std::invalid_argument("expected HOST:PORT, got '" + s + "'");
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr = parse_host(s.substr(0, colon), s);
  a.sin_port = htons(parse_port(s.substr(colon + 1), s, require_port));
  return a;
}

SourceFilter parse_source(const std::string& s) {
  SourceFilter f;
  // "::" or any IPv6 form: the runner is IPv4 only, and "::" is a wildcard, which as a source matches nobody.
  if (s.find(':') != s.rfind(':') || s.find('[') != std::string::npos)
    throw std::invalid_argument("'" + s + "' is an IPv6 address; the runner listens on IPv4 only "
                                "(HOST or HOST:PORT, e.g. 127.0.0.1)");
  const auto colon = s.rfind(':');
  const std::string host = colon == std::string::npos ? s : s.substr(0, colon);
  if (host.empty()) throw std::invalid_argument("expected HOST or HOST:PORT, got '" + s + "'");
  f.addr = parse_host(host, s).s_addr;
  // 0.0.0.0 means "any address" to bind(), but no packet comes from it: as an allow-list entry it would
  // silently let nobody own the session. Allowing every host is the default (no --allow).
  if (f.addr == htonl(INADDR_ANY))
    throw std::invalid_argument("'" + s + "' matches no sender (0.0.0.0 is the wildcard for listening, never a "
                                "source address); name the controller's address, or give no --allow to let any "
                                "host own the session");
  if (colon != std::string::npos) f.port = htons(parse_port(s.substr(colon + 1), s, false));
  return f;
}

bool is_loopback(const sockaddr_in& a) { return (ntohl(a.sin_addr.s_addr) >> 24) == 127; }

std::string to_string(const sockaddr_in& a) {
  char b[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a.sin_addr, b, sizeof b);
  return std::string(b) + ":" + std::to_string(ntohs(a.sin_port));
}

}  // namespace armrt::rt
