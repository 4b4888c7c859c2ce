// HMAC-SHA256 (RFC 2104) of packets with a shared key, for the optional authentication of the UDP
// link (docs/realtime.md, "Threat model"). SHA-256 is OpenSSL's libcrypto. The key's inner and outer
// pad states are hashed once at set-up; each packet then costs two copies of a SHA256_CTX and the
// hashing itself: no heap allocation, no lock (OpenSSL's EVP/HMAC interfaces duplicate provider
// contexts on the heap per message, which the hot loop must not do).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include <openssl/sha.h>

namespace armrt::rt {

class HmacKey {
 public:
  HmacKey() = default;
  explicit HmacKey(const std::string& key);  // throws std::invalid_argument if shorter than 16 bytes
  bool enabled() const { return enabled_; }
  // tag = HMAC-SHA256(key, data[0, n)), 32 bytes.
  void sign(const std::uint8_t* data, long n, std::uint8_t* tag) const;
  // Constant-time comparison of HMAC(data[0, n)) with tag.
  bool verify(const std::uint8_t* data, long n, const std::uint8_t* tag) const;

 private:
  bool enabled_ = false;
  SHA256_CTX inner_{}, outer_{};
};

// The file could not be opened (errno in `error`): a std::invalid_argument to the runner (exit status 2), an
// OSError to Python (armrt._rt.read_key_file), as open() failing is there.
struct KeyFileOpenError : std::invalid_argument {
  KeyFileOpenError(const std::string& what, int err) : std::invalid_argument(what), error(err) {}
  int error;
};

// The key in a file: its bytes, without one trailing newline (so `head -c 32 /dev/urandom | base64 >
// key` and `openssl rand -hex 32 > key` both work). Throws std::invalid_argument naming the problem
// (KeyFileOpenError if it cannot be opened). The one implementation of the rules: armrt-rt --key-file and
// Python's armrt.realtime.read_key_file (through armrt._rt) both call it.
std::string read_key_file(const std::string& path);

}  // namespace armrt::rt
