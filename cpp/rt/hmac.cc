// SHA256_Init/Update/Final are deprecated in OpenSSL 3 in favour of EVP, which allocates per message
// (see hmac.h); they remain supported through the 3.x series.
#define OPENSSL_SUPPRESS_DEPRECATED
#include "hmac.h"

#include <fcntl.h>
#include <openssl/crypto.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include <cstring>
#include <stdexcept>

namespace armrt::rt {

HmacKey::HmacKey(const std::string& key) {
  if (key.size() < 16)
    throw std::invalid_argument("the shared key must be at least 16 bytes (got " + std::to_string(key.size()) + ")");
  std::uint8_t k[SHA256_CBLOCK] = {};
  if (key.size() > SHA256_CBLOCK) {
    SHA256(reinterpret_cast<const unsigned char*>(key.data()), key.size(), k);
  } else {
    std::memcpy(k, key.data(), key.size());
  }
  std::uint8_t ipad[SHA256_CBLOCK], opad[SHA256_CBLOCK];
  for (int i = 0; i < SHA256_CBLOCK; ++i) {
    ipad[i] = k[i] ^ 0x36;
    opad[i] = k[i] ^ 0x5c;
  }
  SHA256_Init(&inner_);
  SHA256_Update(&inner_, ipad, sizeof ipad);
  SHA256_Init(&outer_);
  SHA256_Update(&outer_, opad, sizeof opad);
  OPENSSL_cleanse(k, sizeof k);
  OPENSSL_cleanse(ipad, sizeof ipad);
  OPENSSL_cleanse(opad, sizeof opad);
  enabled_ = true;
}

void HmacKey::sign(const std::uint8_t* data, long n, std::uint8_t* tag) const {
  SHA256_CTX c = inner_;
  std::uint8_t h[SHA256_DIGEST_LENGTH];
  SHA256_Update(&c, data, static_cast<std::size_t>(n));
  SHA256_Final(h, &c);
  c = outer_;
  SHA256_Update(&c, h, sizeof h);
  SHA256_Final(tag, &c);
}

bool HmacKey::verify(const std::uint8_t* data, long n, const std::uint8_t* tag) const {
  std::uint8_t t[SHA256_DIGEST_LENGTH];
  sign(data, n, t);
  return CRYPTO_memcmp(t, tag, sizeof t) == 0;
}

std::string read_key_file(const std::string& path) {
  // As ssh treats a private key: only a regular file (a device such as /dev/zero would be read forever,
  // a FIFO would block) that neither the group nor others may read or write. The checks are on the opened
  // descriptor (fstat), so the file checked is the file read. O_NONBLOCK: opening a FIFO does not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    throw KeyFileOpenError("cannot read the key file '" + path + "': " + std::strerror(err), err);
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw std::invalid_argument("the key file '" + path + "' is not a regular file");
  }
  if (st.st_mode & 077) {
    ::close(fd);
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw std::invalid_argument("the key file '" + path + "' is accessible by group or others (mode " + mode +
                                "); it must be readable by its owner only, as ssh requires of a private key: "
                                "chmod 600 '" + path + "'");
  }
  constexpr off_t kMaxKeyBytes = 4096;  // a shared key, not a data file
  if (st.st_size > kMaxKeyBytes) {
    ::close(fd);
    throw std::invalid_argument("the key file '" + path + "' is " + std::to_string(st.st_size) +
                                " bytes (a key is 16 .. 4096 bytes)");
  }
  std::string key(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < key.size()) {
    const ssize_t n = ::read(fd, &key[got], key.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  key.resize(got);
  if (!key.empty() && key.back() == '\n') key.pop_back();
  if (!key.empty() && key.back() == '\r') key.pop_back();
  if (key.size() < 16)
    throw std::invalid_argument("the key in '" + path + "' is shorter than 16 bytes");
  return key;
}

}  // namespace armrt::rt
