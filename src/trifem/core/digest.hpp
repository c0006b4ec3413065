// SPDX-License-Identifier: MIT
// FNV-1a with 64 bits (Fowler–Noll–Vo): a digest of bytes to tell whether two inputs are the
// same (the processes of a parallel run, the fingerprint and checksum of restart files). Every
// step is a bijection of the running hash, so a change of any single byte always changes the
// result. Not a defence against deliberate tampering.
#pragma once

#include <cstddef>
#include <cstdint>

namespace trifem {

class Fnv1a64 {
public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ULL;
  static constexpr std::uint64_t kPrime = 0x00000100000001b3ULL;

  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i)
      hash_ = (hash_ ^ p[i]) * kPrime;
  }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = kOffsetBasis;
};

} // namespace trifem
