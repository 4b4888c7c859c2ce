// SHA256_Init/Update/Final are deprecated in OpenSSL 3 in favour of EVP, which allocates per message
// (see hmac.h); they remain supported through the 3.x series.
#define OPENSSL_SUPPRESS_DEPRECATED
#include "hmac.h"

#include <openssl/crypto.h>

#include <cstring>
#include <fstream>
#include <sstream>
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
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::invalid_argument("cannot read the key file '" + path + "'");
  std::stringstream ss;
  ss << f.rdbuf();
  std::string key = ss.str();
  if (!key.empty() && key.back() == '\n') key.pop_back();
  if (!key.empty() && key.back() == '\r') key.pop_back();
  if (key.size() < 16)
    throw std::invalid_argument("the key in '" + path + "' is shorter than 16 bytes");
  return key;
}

}  // namespace armrt::rt
