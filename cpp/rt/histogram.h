// Fixed-memory record of a per-cycle duration (ns) for percentiles over runs of any length: a
// log-linear histogram in the manner of HdrHistogram (128 exact buckets below 128 ns, then 64 linear
// sub-buckets per power of two, so every value is kept within 1/64 = 1.6 % of its size; 18 KB for
// values up to 2^40 ns). min, max, count and mean are exact. record() is a few integer operations:
// no allocation, no lock.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace armrt::rt {

class LogHistogram {
 public:
  static constexpr int kSubBits = 7;                     // 2^7 exact buckets, then 2^6 per octave
  static constexpr int kExact = 1 << kSubBits;           // 128
  static constexpr int kHalf = kExact / 2;               // 64
  static constexpr int kMaxExponent = 40;                // values are capped at 2^40 ns (18 min)
  static constexpr int kBuckets = kExact + (kMaxExponent - kSubBits + 1) * kHalf;

  void record(std::int64_t v) {
    if (v < 0) v = 0;
    if (v >= (std::int64_t{1} << kMaxExponent)) v = (std::int64_t{1} << kMaxExponent) - 1;
    ++counts_[index(v)];
    if (count_ == 0 || v < min_) min_ = v;
    if (v > max_) max_ = v;
    ++count_;
    sum_ += static_cast<double>(v);
  }
  void clear() { *this = LogHistogram(); }

  std::int64_t count() const { return count_; }
  std::int64_t min() const { return count_ ? min_ : 0; }
  std::int64_t max() const { return max_; }
  double mean() const { return count_ ? sum_ / static_cast<double>(count_) : 0.0; }

  // Nearest-rank q-quantile (0 < q <= 1): the middle of the bucket holding it, kept inside [min, max].
  double quantile(double q) const {
    if (count_ == 0) return 0.0;
    std::int64_t rank = static_cast<std::int64_t>(std::ceil(q * static_cast<double>(count_)));
    rank = std::clamp<std::int64_t>(rank, 1, count_);
    std::int64_t cum = 0;
    for (int i = 0; i < kBuckets; ++i) {
      cum += static_cast<std::int64_t>(counts_[i]);
      if (cum >= rank) {
        const double mid = lower(i) + 0.5 * (width(i) - 1);
        return std::clamp(mid, static_cast<double>(min()), static_cast<double>(max_));
      }
    }
    return static_cast<double>(max_);
  }

  static int index(std::int64_t v) {
    if (v < kExact) return static_cast<int>(v);
    const int msb = 63 - __builtin_clzll(static_cast<unsigned long long>(v));
    const int shift = msb - kSubBits + 1;                 // >= 1
    const int sub = static_cast<int>(v >> shift);         // in [64, 128)
    return kExact + (shift - 1) * kHalf + (sub - kHalf);
  }
  static double lower(int i) {
    if (i < kExact) return i;
    const int shift = (i - kExact) / kHalf + 1;
    const int sub = (i - kExact) % kHalf + kHalf;
    return std::ldexp(static_cast<double>(sub), shift);
  }
  static double width(int i) { return i < kExact ? 1.0 : std::ldexp(1.0, (i - kExact) / kHalf + 1); }

 private:
  std::array<std::uint32_t, kBuckets> counts_{};  // 2^32 cycles = 50 days at 1 kHz
  std::int64_t count_ = 0, min_ = 0, max_ = 0;
  double sum_ = 0;
};

}  // namespace armrt::rt
