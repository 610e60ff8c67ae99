#pragma once
// A sample of the medium-to-medium gather queries a render makes, each with the weight the
// image gives it, for the noise-free accuracy study (vrlis_accuracy --queries FILE; see
// docs/accuracy_scenes.md). Header-only and dependent on the core library alone, so that
// the study reads what the renderer writes.
//
// File format, version 1, every number little-endian:
//   bytes 0-7    the magic "VRLQLOG1"
//   bytes 8-15   uint64: the record count N
//   then N records of 19 IEEE-754 float32 (76 bytes each):
//     camera origin x y z, camera dir x y z, tmin, tmax (may be +infinity),
//     VRL origin x y z, VRL dir x y z, VRL length, g, sigma_s, sigma_t, weight.
// The weight is what the image multiplies the gather's estimate f / pdf by: the VRL's flux
// times the camera path's throughput, as the root mean square over RGB (the image error the
// project measures is the RMSE over the three channels, so a query's share of it goes as
// the square of this weight).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <vrlis/core/gather_query.hpp>

namespace vrlis::integration {

struct QueryRecord {
  vrlis::MediumGatherQuery<float> query;
  float weight = 0;
};

namespace query_log {
inline constexpr char kMagic[8] = {'V', 'R', 'L', 'Q', 'L', 'O', 'G', '1'};
inline constexpr int kFloats = 19;
inline constexpr std::size_t kHeaderBytes = 16, kRecordBytes = 4 * kFloats;

inline std::array<float, kFloats> Flatten(const QueryRecord& r) {
  const auto& c = r.query.camera;
  const auto& v = r.query.vrl;
  const auto& m = r.query.medium;
  return {c.origin.x, c.origin.y, c.origin.z, c.dir.x, c.dir.y, c.dir.z, c.tmin, c.tmax, v.origin.x, v.origin.y,
          v.origin.z, v.dir.x,    v.dir.y,    v.dir.z,  v.length, m.g,   m.sigma_s, m.sigma_t, r.weight};
}

inline QueryRecord Unflatten(const std::array<float, kFloats>& f) {
  QueryRecord r;
  r.query.camera = {{f[0], f[1], f[2]}, {f[3], f[4], f[5]}, f[6], f[7]};
  r.query.vrl = {{f[8], f[9], f[10]}, {f[11], f[12], f[13]}, f[14]};
  r.query.medium = vrlis::Medium<float>::FromScatteringExtinction(f[15], f[16], f[17]);
  r.weight = f[18];
  return r;
}

inline std::uint32_t Bits(float x) {
  std::uint32_t b;
  std::memcpy(&b, &x, 4);
  return b;
}

// The record's identity: a hash of its bits (SplitMix64 steps), independent of when and on
// which thread it was made.
inline std::uint64_t Hash(const std::array<float, kFloats>& f) {
  std::uint64_t h = 0x243F6A8885A308D3ull;
  for (int i = 0; i + 1 < kFloats; ++i) {  // the query only, not its weight
    h = (h ^ Bits(f[i])) + 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    h ^= h >> 31;
  }
  return h;
}

inline void PutLittleEndian(std::string& out, std::uint64_t x, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((x >> (8 * i)) & 0xFF));
}
inline std::uint64_t GetLittleEndian(const unsigned char* p, int bytes) {
  std::uint64_t x = 0;
  for (int i = 0; i < bytes; ++i) x |= std::uint64_t(p[i]) << (8 * i);
  return x;
}
}  // namespace query_log

// A thread-safe recorder that keeps about one gather query in `every`. Which ones is decided
// by a hash of the query itself, so the sample, and the file (sorted by that hash), are the
// same at every thread count; recording draws no random numbers, so the image is unchanged.
class QueryLog {
 public:
  explicit QueryLog(std::uint64_t every) : every_(std::max<std::uint64_t>(every, 1)) {}

  // Invalid queries are not kept: the gather returns nothing for them.
  void Record(const vrlis::MediumGatherQuery<float>& q, float weight) {
    QueryRecord r{q, weight};
    auto flat = query_log::Flatten(r);
    std::uint64_t h = query_log::Hash(flat);
    if (h % every_ != 0 || vrlis::Validate(q) != vrlis::QueryError::None || !(weight >= 0) || !std::isfinite(weight))
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    kept_.push_back({h, flat});
  }

  // The kept records in a deterministic order.
  std::vector<QueryRecord> Records() const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto kept = kept_;
    std::sort(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) {
      return std::tie(a.hash, a.flat) < std::tie(b.hash, b.flat);
    });
    std::vector<QueryRecord> out;
    out.reserve(kept.size());
    for (const Kept& k : kept) out.push_back(query_log::Unflatten(k.flat));
    return out;
  }

 private:
  struct Kept {
    std::uint64_t hash;
    std::array<float, query_log::kFloats> flat;
  };
  std::uint64_t every_;
  mutable std::mutex mutex_;
  std::vector<Kept> kept_;
};

// Writes the records to `path` through a temporary file renamed at the end, so a failure
// never leaves a half-written log. Returns false and sets *error on failure.
inline bool WriteQueryLog(const std::string& path, const std::vector<QueryRecord>& records, std::string* error) {
  std::string bytes(query_log::kMagic, sizeof query_log::kMagic);
  query_log::PutLittleEndian(bytes, records.size(), 8);
  for (const QueryRecord& r : records)
    for (float x : query_log::Flatten(r)) query_log::PutLittleEndian(bytes, query_log::Bits(x), 4);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!f.flush()) {
      std::remove(tmp.c_str());
      *error = "cannot write '" + path + "'";
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    *error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}

// Reads a log written by WriteQueryLog; nullopt and a one-line *error for anything else (a
// wrong magic, a size that does not match the count, an invalid query or weight).
inline std::optional<std::vector<QueryRecord>> ReadQueryLog(const std::string& path, std::string* error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = "cannot open '" + path + "'";
    return std::nullopt;
  }
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < query_log::kHeaderBytes || std::memcmp(p, query_log::kMagic, sizeof query_log::kMagic) != 0) {
    *error = "'" + path + "' is not a query log (no VRLQLOG1 header)";
    return std::nullopt;
  }
  std::uint64_t count = query_log::GetLittleEndian(p + 8, 8);
  std::uint64_t body = bytes.size() - query_log::kHeaderBytes;
  if (body % query_log::kRecordBytes != 0 || body / query_log::kRecordBytes != count) {
    *error = "'" + path + "' is truncated or corrupt: header says " + std::to_string(count) + " records, file holds " +
             std::to_string(double(body) / query_log::kRecordBytes);
    return std::nullopt;
  }
  std::vector<QueryRecord> records;
  records.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    std::array<float, query_log::kFloats> flat;
    for (int k = 0; k < query_log::kFloats; ++k) {
      auto b = static_cast<std::uint32_t>(
          query_log::GetLittleEndian(p + query_log::kHeaderBytes + i * query_log::kRecordBytes + 4 * k, 4));
      std::memcpy(&flat[k], &b, 4);
    }
    QueryRecord r = query_log::Unflatten(flat);
    vrlis::QueryError e = vrlis::Validate(r.query);
    if (e != vrlis::QueryError::None || !(r.weight >= 0) || !std::isfinite(r.weight)) {
      *error = "'" + path + "': record " + std::to_string(i) + " is invalid (" +
               (e != vrlis::QueryError::None ? vrlis::Describe(e) : "weight not finite and >= 0") + ")";
      return std::nullopt;
    }
    records.push_back(r);
  }
  return records;
}

}  // namespace vrlis::integration
