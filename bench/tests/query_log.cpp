// The query log that carries a render's gather queries to the accuracy study
// (vrlis_integration/query_log.hpp): what is written is read back bit for bit, damaged
// files are refused with a message, and the recorder's sample is the same whatever the
// order of the gathers (threads) and keeps one query in K within a binomial interval.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <vrlis_integration/query_log.hpp>

#include "study/config.hpp"

namespace {

using vrlis::integration::QueryRecord;

std::vector<QueryRecord> RandomRecords(int n) {
  std::vector<QueryRecord> out;
  for (const auto& c : vrlis::study::MakeConfigs(7, n, 0.5)) {
    auto f = c.as<float>();
    out.push_back({f.query, f.xi_cam * 10});
  }
  return out;
}

bool SameBits(const QueryRecord& a, const QueryRecord& b) {
  auto fa = vrlis::integration::query_log::Flatten(a), fb = vrlis::integration::query_log::Flatten(b);
  return std::memcmp(fa.data(), fb.data(), sizeof fa) == 0;
}

std::string TempPath(const char* name) { return std::string("vrlis_query_log_test_") + name; }

}  // namespace

TEST_CASE("a query log reads back what was written, unbounded segments included", "[query_log]") {
  std::vector<QueryRecord> records = RandomRecords(200);
  bool unbounded = false;
  for (const QueryRecord& r : records) unbounded = unbounded || std::isinf(r.query.camera.tmax);
  REQUIRE(unbounded);
  std::string path = TempPath("roundtrip"), error;
  REQUIRE(vrlis::integration::WriteQueryLog(path, records, &error));
  auto read = vrlis::integration::ReadQueryLog(path, &error);
  REQUIRE(read);
  REQUIRE(read->size() == records.size());
  for (std::size_t i = 0; i < records.size(); ++i) CHECK(SameBits((*read)[i], records[i]));
  std::remove(path.c_str());
}

TEST_CASE("a damaged query log is refused with a message", "[query_log]") {
  std::vector<QueryRecord> records = RandomRecords(3);
  std::string path = TempPath("damaged"), error;
  REQUIRE(vrlis::integration::WriteQueryLog(path, records, &error));
  std::string bytes;
  {
    std::ifstream f(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  auto reject = [&](std::string content) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << content;
    std::string e;
    bool refused = !vrlis::integration::ReadQueryLog(path, &e);
    INFO(e);
    return refused && !e.empty();
  };
  CHECK(!reject(bytes));                                   // the intact file is accepted
  CHECK(reject(bytes.substr(0, bytes.size() - 1)));        // truncated
  CHECK(reject("VRLQLOG2" + bytes.substr(8)));             // wrong magic or version
  std::string nan = bytes;
  float x = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[16], &x, 4);                            // a NaN camera origin
  CHECK(reject(nan));
  std::string error2;
  CHECK(!vrlis::integration::ReadQueryLog(TempPath("missing"), &error2));
  CHECK(!error2.empty());
  std::remove(path.c_str());
}

TEST_CASE("the recorder keeps one query in K, the same ones in any order", "[query_log]") {
  const int n = 20000, every = 50;
  std::vector<QueryRecord> records = RandomRecords(n);
  vrlis::integration::QueryLog forward(every), backward(every);
  for (const QueryRecord& r : records) forward.Record(r.query, r.weight);
  for (auto it = records.rbegin(); it != records.rend(); ++it) backward.Record(it->query, it->weight);
  auto a = forward.Records(), b = backward.Records();
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) CHECK(SameBits(a[i], b[i]));
  // Binomial(n, 1/every): mean 400, standard deviation about 19.8; five of them either side.
  double mean = double(n) / every, sd = std::sqrt(mean * (1 - 1.0 / every));
  CHECK(std::abs(double(a.size()) - mean) < 5 * sd);
  // An invalid query or weight is never kept.
  vrlis::integration::QueryLog all(1);
  QueryRecord bad = records[0];
  bad.query.medium.g = 1;
  all.Record(bad.query, 1);
  all.Record(records[0].query, -1);
  all.Record(records[0].query, 1);
  CHECK(all.Records().size() == 1);
}
