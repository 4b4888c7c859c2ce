// HOST:PORT parsing for the runner, its tests and (through armrt._rt.parse_endpoint) the Python side:
// the one place that decides what an address means.
#pragma once

#include <netinet/in.h>

#include <string>

namespace armrt::rt {

// "host:port" -> sockaddr_in (IPv4, numeric host or "localhost"; an empty host is 127.0.0.1, never
// "any"). Port 0..65535 unless require_port (1..65535). Throws std::invalid_argument naming the problem.
sockaddr_in parse_endpoint(const std::string& s, bool require_port = false);

// An allow-list entry "host" or "host:port" (port 0 or none: any port of that host).
struct SourceFilter {
  in_addr_t addr = 0;     // network order
  in_port_t port = 0;     // network order; 0: any
  bool matches(const sockaddr_in& a) const {
    return a.sin_addr.s_addr == addr && (port == 0 || a.sin_port == port);
  }
};
SourceFilter parse_source(const std::string& s);

bool is_loopback(const sockaddr_in& a);
std::string to_string(const sockaddr_in& a);  // "a.b.c.d:port"

}  // namespace armrt::rt
