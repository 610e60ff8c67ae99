#pragma once
// Counts of rejected gather queries by reason. A rejected gather weighs 0, so a renderer
// whose every query is invalid (a misfilled medium, unnormalised directions) sees only a dark
// image; these counts say why. Every failed validation of a gather query or of one of its
// parts (gather_query.hpp) adds one, from any thread: a relaxed atomic increment on the
// failing path only, so valid queries cost nothing and the counts can stay on in every build.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "query.hpp"

namespace vrlis {

// A snapshot of the counts; count[int(e)] for each QueryError e (None stays 0).
struct QueryRejections {
  std::array<std::uint64_t, kQueryErrorCount> count{};

  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (std::uint64_t c : count) sum += c;
    return sum;
  }
  // The rejections after `earlier` (an earlier snapshot): those of one pass, one test.
  QueryRejections since(const QueryRejections& earlier) const {
    QueryRejections d;
    for (int e = 0; e < kQueryErrorCount; ++e) d.count[e] = count[e] - earlier.count[e];
    return d;
  }
};

namespace detail {
inline std::atomic<std::uint64_t> rejected_queries[kQueryErrorCount];

// Returns e, counted if it rejects the query.
inline QueryError Counted(QueryError e) {
  if (e != QueryError::None) rejected_queries[static_cast<int>(e)].fetch_add(1, std::memory_order_relaxed);
  return e;
}
}  // namespace detail

// The counts since the program started, over all threads.
inline QueryRejections RejectedQueries() {
  QueryRejections r;
  for (int e = 0; e < kQueryErrorCount; ++e) r.count[e] = detail::rejected_queries[e].load(std::memory_order_relaxed);
  return r;
}

// "12 non-finite input, 3 segment has tmax < tmin": the nonzero counts, by reason.
inline std::string Describe(const QueryRejections& r) {
  std::string out;
  for (int e = 1; e < kQueryErrorCount; ++e) {
    if (r.count[e] == 0) continue;
    if (!out.empty()) out += ", ";
    out += std::to_string(r.count[e]) + " " + Describe(static_cast<QueryError>(e));
  }
  return out;
}

}  // namespace vrlis
