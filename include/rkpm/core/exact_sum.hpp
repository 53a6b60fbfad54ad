#pragma once
// exact_sum: a sum of doubles held exactly, so that its value does not depend on the order the
// terms were added in, nor on how they were split among threads or processes (docs/method.md
// section 9.8: a history row's sums on several processes, one MPI_SUM of each part's limbs).
//
// Every finite double is m 2^e with an integer |m| < 2^53 and -1074 <= e <= 971, so the sum of
// up to 2^31 of them is an integer multiple of 2^-1074 below 2^1056: it is held as 67 signed
// 64-bit limbs of 32 bits each, limb k worth 2^(32 k - 1074). add() puts a term's bits into the
// (at most three) limbs they cover, each of which then holds less than 2^33 more; normalize()
// carries every limb's excess into the next, which leaves limbs 0..65 in [0, 2^32) and the sign
// in limb 66: one representation per value. value() is that value rounded to a double by adding
// its magnitude's limbs from the highest down (within a unit or two in the last place; the same bits for the
// same exact sum). Non-finite terms (NaN, infinities) are summed apart as doubles and win.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

namespace rkpm {

class exact_sum {
 public:
  static constexpr int limb_count = 67;
  static constexpr int limb_bits = 32;

  exact_sum& add(double x) {
    if (!std::isfinite(x)) {
      special_ += x;
      return *this;
    }
    if (x == 0.0) return *this;
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
    if (biased != 0) m |= std::uint64_t{1} << 52;                // normal: the hidden bit
    const int shift = (biased == 0 ? 1 : biased) - 1;            // e + 1074, the bit position of m's lowest bit
    const int k = shift / limb_bits, r = shift % limb_bits;
    const std::uint64_t low = (m & 0xffffffffu) << r, high = (m >> 32) << r;  // each below 2^63
    const std::int64_t sign = std::signbit(x) ? -1 : 1;
    limb_[k] += sign * static_cast<std::int64_t>(low & 0xffffffffu);
    limb_[k + 1] += sign * static_cast<std::int64_t>((low >> 32) + (high & 0xffffffffu));
    limb_[k + 2] += sign * static_cast<std::int64_t>(high >> 32);
    if (++pending_ == max_pending) normalize();
    return *this;
  }

  // Adds another sum (a thread's or a process's part).
  exact_sum& operator+=(const exact_sum& other) {
    exact_sum o = other;
    o.normalize();
    normalize();
    for (int k = 0; k < limb_count; ++k) limb_[k] += o.limb_[k];
    special_ += o.special_;
    pending_ = 1;
    normalize();
    return *this;
  }

  // Limbs 0..65 in [0, 2^32), the sign in limb 66: one representation per value.
  void normalize() {
    for (int k = 0; k + 1 < limb_count; ++k) {
      const std::int64_t carry = limb_[k] >> limb_bits;  // floor(limb / 2^32), negative limbs included
      limb_[k] -= carry * (std::int64_t{1} << limb_bits);
      limb_[k + 1] += carry;
    }
    pending_ = 0;
  }

  // The sum rounded to a double.
  double value() const {
    if (special_ != 0.0 || std::isnan(special_)) return special_;
    exact_sum n = *this;
    n.normalize();
    const bool negative = n.limb_[limb_count - 1] < 0;  // then its magnitude's limbs, lest the top ones overflow
    if (negative) {
      for (std::int64_t& l : n.limb_) l = -l;
      n.normalize();
    }
    double v = 0.0;
    for (int k = limb_count - 1; k >= 0; --k)
      if (n.limb_[k] != 0) v += std::ldexp(static_cast<double>(n.limb_[k]), limb_bits * k - 1074);
    return negative ? -v : v;
  }

  // The limbs, normalized, for an MPI_SUM of MPI_INT64_T over the processes' parts (at most
  // 2^31 of them), and the non-finite terms' sum (an MPI_SUM of a double); normalize() after.
  std::span<std::int64_t, limb_count> limbs() { return limb_; }
  double& special() { return special_; }

 private:
  static constexpr int max_pending = 1 << 28;  // adds before a limb could overflow: 2^28 x 2^33 < 2^63
  std::array<std::int64_t, limb_count> limb_{};
  double special_ = 0.0;
  int pending_ = 0;
};

}  // namespace rkpm
