// SPDX-License-Identifier: MIT
// The layout of restart files (format 3, src/trifem/analysis/restart.hpp), written out again
// here for tests that damage files on purpose: where each field is, and the header resealed
// (payload size and FNV-1a 64 checksum) so that a damaged value passes the checksum and reaches
// the checks behind it, as a file written that way by another program would.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace trifem::test {

/// Where the fields of one restart file are (byte offsets into the whole file).
struct RestartLayout {
  static constexpr std::size_t kVersion = 16;     ///< int64
  static constexpr std::size_t kPayloadSize = 24; ///< int64
  static constexpr std::size_t kChecksum = 32;    ///< uint64
  static constexpr std::size_t kHeader = 40;      ///< the payload starts here
  static constexpr std::size_t kFingerprintParts = 8;
  static constexpr std::size_t kFingerprint = kHeader; ///< one uint64 per part
  static constexpr std::size_t kTime = kFingerprint + 8 * kFingerprintParts; ///< double
  static constexpr std::size_t kDt = kTime + 8;                              ///< double
  static constexpr std::size_t kSteps = kDt + 8;                             ///< int64
  static constexpr std::size_t kStateLength = kSteps + 8;                    ///< int64
  std::size_t active_step = 0;                                               ///< int64
  std::vector<std::size_t> offsets;   ///< the length field of each condition's offsets
  std::size_t released_count = 0;     ///< int64 (0 if no step is active)
  std::size_t histories_count = 0;    ///< int64
  std::vector<std::size_t> histories; ///< the length field of each term history
  std::size_t velocity = 0;           ///< the length field of the velocity
  std::size_t integrator = 0;         ///< the length field of the explicit integrator's state
  std::size_t end = 0;                ///< the size of the file
};

template <class T>
T get(const std::string& bytes, std::size_t at) {
  if (at + sizeof(T) > bytes.size())
    throw std::out_of_range("restart layout: field beyond the end of the file");
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

template <class T>
void put(std::string& bytes, std::size_t at, T v) {
  if (at + sizeof(T) > bytes.size())
    throw std::out_of_range("restart layout: field beyond the end of the file");
  std::memcpy(bytes.data() + at, &v, sizeof v);
}

/// The fields of an intact restart file (std::out_of_range if it is not one).
inline RestartLayout restart_layout(const std::string& bytes) {
  RestartLayout l;
  std::size_t at = RestartLayout::kStateLength;
  const auto skip_array = [&] {
    at += 8 + 8 * static_cast<std::size_t>(get<std::int64_t>(bytes, at));
  };
  skip_array();
  l.active_step = at;
  at += 8;
  if (get<std::int64_t>(bytes, l.active_step) >= 0) {
    const auto conditions = get<std::int64_t>(bytes, at);
    at += 8;
    for (std::int64_t i = 0; i < conditions; ++i) {
      l.offsets.push_back(at);
      skip_array();
    }
    l.released_count = at;
    at += 8 + 16 * static_cast<std::size_t>(get<std::int64_t>(bytes, at));
  }
  l.histories_count = at;
  const auto terms = get<std::int64_t>(bytes, at);
  at += 8;
  for (std::int64_t i = 0; i < terms; ++i) {
    l.histories.push_back(at);
    skip_array();
  }
  l.velocity = at;
  skip_array();
  l.integrator = at;
  skip_array();
  l.end = at;
  if (l.end != bytes.size())
    throw std::out_of_range("restart layout: the fields do not end at the end of the file");
  return l;
}

/// FNV-1a with 64 bits of `bytes` [from, to), continuing from `hash`.
inline std::uint64_t fnv1a64(const std::string& bytes, std::size_t from, std::size_t to,
                             std::uint64_t hash = 0xcbf29ce484222325ULL) {
  for (std::size_t i = from; i < to; ++i)
    hash = (hash ^ static_cast<unsigned char>(bytes[i])) * 0x00000100000001b3ULL;
  return hash;
}

/// Sets the payload size and the checksum of `bytes` to those of its present contents.
inline void reseal(std::string& bytes) {
  put<std::int64_t>(bytes, RestartLayout::kPayloadSize,
                    static_cast<std::int64_t>(bytes.size() - RestartLayout::kHeader));
  const std::uint64_t head = fnv1a64(bytes, 0, RestartLayout::kChecksum);
  put<std::uint64_t>(bytes, RestartLayout::kChecksum,
                     fnv1a64(bytes, RestartLayout::kHeader, bytes.size(), head));
}

} // namespace trifem::test
