// libFuzzer target: every camera-segment sampler and VrlPoint, in float and double, driven by
// queries decoded from arbitrary bytes, checked against the contract of
// angle/segment_sampler.hpp and samplers/vrl_point.hpp (tests/support/contract.hpp).
// A violation prints the query and aborts.
//
// Input layout: byte 0 selects precision (bit 0), decoding (bits 1-2: raw floats, raw floats
// with the directions normalised, or "structured": every field picked from a table of
// special values and scaled) and the point lobe (bits 3-4); the rest feeds the fields.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "sampler_types.hpp"
#include "contract.hpp"

namespace {

struct Bytes {
  const uint8_t* p;
  size_t n;
  uint8_t Byte() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  template <typename T>
  T Raw() {
    T x{};
    unsigned char b[sizeof(T)] = {};
    for (auto& c : b) c = Byte();
    std::memcpy(&x, b, sizeof(T));
    return x;
  }
};

// Special values the structured decoder draws from.
const double kSpecial[] = {0,    1,     -1,    0.5,   1e-4,  -1e-4,  0.999, -0.999, 0.9999999, 1e-7,
                           1e-6, 1e6,   -1e6,  1e4,   -1e4,  1e-30,  1e30,  0.9,    -0.9,      2,
                           3,    1e-38, 1e-300, 1 - 1e-12, std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()};
constexpr int kSpecialCount = sizeof(kSpecial) / sizeof(kSpecial[0]);

template <typename Real>
Real Structured(Bytes& b) {
  uint8_t k = b.Byte();
  double v = kSpecial[k % kSpecialCount];
  if (k >= 200) v *= 1 + double(int8_t(b.Byte())) * 1e-3;  // a nearby value
  else if (k >= 160) v = double(int16_t(b.Raw<uint16_t>())) / 256;  // a moderate value
  return Real(v);
}

template <typename Real>
vrlis::Vec3<Real> Vec(Bytes& b, int mode) {
  if (mode == 2 || mode == 3) return {Structured<Real>(b), Structured<Real>(b), Structured<Real>(b)};
  return {b.Raw<Real>(), b.Raw<Real>(), b.Raw<Real>()};
}

template <typename Real>
Real Scalar(Bytes& b, int mode) { return mode >= 2 ? Structured<Real>(b) : b.Raw<Real>(); }

template <typename Real>
vrlis::Vec3<Real> MaybeNormalise(vrlis::Vec3<Real> v, int mode) {
  if (mode == 0) return v;
  Real len = vrlis::Length(v);
  if (len > 0 && std::isfinite(len)) return (Real(1) / len) * v;
  return mode == 1 ? v : vrlis::Vec3<Real>{0, 0, 1};
}

template <typename Real>
void Fail(const char* what, const std::string& msg, const vrlis::SegmentQuery<Real>& q) {
  std::fprintf(stderr,
               "CONTRACT VIOLATION (%s, %s): %s\n  origin (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g) t [%.9g, %.9g] g %.9g\n"
               "  point (%.9g, %.9g, %.9g) lobe %d axis (%.9g, %.9g, %.9g) g %.9g sigma_t %.9g\n",
               what, sizeof(Real) == 4 ? "float" : "double", msg.c_str(), double(q.origin.x), double(q.origin.y),
               double(q.origin.z), double(q.dir.x), double(q.dir.y), double(q.dir.z), double(q.tmin), double(q.tmax),
               double(q.g), double(q.point.x), double(q.point.y), double(q.point.z), int(q.lobe.kind),
               double(q.lobe.axis.x), double(q.lobe.axis.y), double(q.lobe.axis.z), double(q.lobe.g),
               double(q.sigma_t));
  std::abort();
}

template <typename Real>
void Run(Bytes& b, int mode, int lobe) {
  vrlis::SegmentQuery<Real> q;
  q.origin = Vec<Real>(b, mode);
  q.dir = MaybeNormalise(Vec<Real>(b, mode), mode);
  q.tmin = Scalar<Real>(b, mode);
  Real len = Scalar<Real>(b, mode);
  q.tmax = mode >= 2 ? q.tmin + std::abs(len) : len;  // structured: near-valid lengths (0, tiny, huge, inf)
  q.g = Scalar<Real>(b, mode);
  if (mode >= 2) {
    // The point relative to the segment: a foot t along it and a distance off it.
    Real foot = Scalar<Real>(b, mode), off = Scalar<Real>(b, mode);
    vrlis::Vec3<Real> n = vrlis::AnyPerpendicular(q.dir);
    q.point = q.origin + (q.tmin + foot) * q.dir + off * n;
  } else {
    q.point = Vec<Real>(b, mode);
  }
  q.lobe.kind = lobe == 1 ? vrlis::LobeKind::HenyeyGreenstein : lobe == 2 ? vrlis::LobeKind::ClampedCosine
                                                                          : vrlis::LobeKind::None;
  q.lobe.axis = MaybeNormalise(Vec<Real>(b, mode), mode);
  q.lobe.g = Scalar<Real>(b, mode);
  q.sigma_t = mode >= 2 ? std::abs(Scalar<Real>(b, mode)) : b.Raw<Real>();

  double us[8] = {0, 1, 0.5, std::nextafter(1.0, 0.0)};
  for (int i = 4; i < 8; ++i) us[i] = double(b.Raw<uint32_t>()) / 4294967295.0;
  const int n = 8;

  // Every camera sampler of the library's registry.
  std::string msg;
  vrlis::test::ForEachSegmentSampler<Real>([&](auto tag) {
    using S = typename decltype(tag)::type;
    msg = vrlis::stability::CheckSegmentSampler(S(q), q, us, n, vrlis::test::RoundTripsPointwise<S>());
    if (!msg.empty()) Fail(vrlis::test::SamplerName<S>().c_str(), msg, q);
  });

  // VrlPoint: the segment as the VRL, the point and lobe axis as the camera line.
  vrlis::VrlPointQuery<Real> v{q.origin, q.dir, q.tmin, q.tmax, q.point, q.lobe.axis};
  if (mode >= 2 && (b.Byte() & 1)) v.line_dir = q.dir;  // parallel lines
  vrlis::VrlPoint<Real> vp(v);
  if (!(msg = vrlis::stability::CheckVrlPoint(vp, v, us, n)).empty()) {
    std::fprintf(stderr,
                 "CONTRACT VIOLATION (VrlPoint, %s): %s\n  origin (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g) t [%.9g, %.9g]\n"
                 "  line origin (%.9g, %.9g, %.9g) line dir (%.9g, %.9g, %.9g)\n",
                 sizeof(Real) == 4 ? "float" : "double", msg.c_str(), double(v.origin.x), double(v.origin.y),
                 double(v.origin.z), double(v.dir.x), double(v.dir.y), double(v.dir.z), double(v.tmin), double(v.tmax),
                 double(v.line_origin.x), double(v.line_origin.y), double(v.line_origin.z), double(v.line_dir.x),
                 double(v.line_dir.y), double(v.line_dir.z));
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  Bytes b{data + 1, size - 1};
  int mode = (data[0] >> 1) & 3, lobe = (data[0] >> 3) & 3;
  if (data[0] & 1)
    Run<double>(b, mode, lobe);
  else
    Run<float>(b, mode, lobe);
  return 0;
}
