// vrlis_stability: the stability table (docs/stability.md). For every sampler and hard case:
//   - the largest weight f / (pdf * integral) (the firefly risk; 1 for a perfect sampler),
//     over 10^5 stratified samples and a 10^4-point grid in the angle variable, in double
//     and in float, and the mean weight over the stratified samples (~1: unbiasedness check);
//   - float-versus-double disagreement: max over u of |F(t_float(u)) - F(t_double(u))|, with F
//     the double sampler's CDF (invert), i.e. how far apart the two samples are in u;
//   - the round-trip error max |invert(sample(u)) - u| in float and double (for
//     CauchyMixture, whose sample() picks a component first, the Kolmogorov-Smirnov distance
//     of invert(sample(u)) from uniform instead, marked KS);
//   - contract violations (non-finite sample, sample outside [tmin, tmax], pdf not finite,
//     pdf 0 where the integrand is positive), listed below the tables.
// Writes Markdown to stdout. Usage: vrlis_stability [samples]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "reference.hpp"

using namespace vrlis::stability;

namespace {

std::vector<std::string> g_violations;

std::string Fmt(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

struct WeightStats {
  double max_w = 0, mean_w = 0;
  int violations = 0;
};

// The weights of one sampler (in precision Real) on one case.
template <typename Sampler, typename Real, typename Ref>
WeightStats Weights(const Sampler& s, const Ref& ref, double integral, double tmin, double tmax,
                    const std::vector<double>& grid_t, int n, const std::string& label, bool check_positive = true) {
  WeightStats st;
  double sum = 0;
  auto note = [&](const std::string& what, double u, double t) {
    if (st.violations++ < 2) {
      std::ostringstream os;
      os.precision(17);
      os << label << ": " << what << " (u = " << u << ", t = " << t << ")";
      g_violations.push_back(os.str());
    }
  };
  auto weigh = [&](double t, double u, bool sampled) {
    double pdf = double(s.pdf(Real(t)));
    double f = ref.f(t);
    if (!std::isfinite(pdf) || pdf < 0) note("pdf not finite or negative", u, t);
    if (f > 0 && std::isfinite(f)) {
      double w = pdf > 0 ? f / (pdf * integral) : kInf;
      if (check_positive && !(pdf > 0) && f / integral > 1e-30) note("pdf 0 where the integrand is positive", u, t);
      if (pdf > 0 || f / integral > 1e-30) st.max_w = std::max(st.max_w, w);
      if (sampled) sum += pdf > 0 ? w : 0;
    }
  };
  for (int i = 0; i <= n + 1; ++i) {
    double u = i == 0 ? 0.0 : i == n + 1 ? 1.0 : (i - 0.5) / n;
    Real t = s.sample(Real(u));
    if (!std::isfinite(t) || t < Real(tmin) || t > Real(tmax)) {
      note("sample not finite or outside [tmin, tmax]", u, double(t));
      continue;
    }
    weigh(double(t), u, i > 0 && i <= n);
  }
  st.mean_w = sum / n;
  for (double t : grid_t)
    if (double(Real(t)) >= tmin && double(Real(t)) <= tmax) weigh(double(Real(t)), -1, false);
  return st;
}

template <typename Sampler>
double RoundTrip(const Sampler& s, int n, bool ks) {
  using Real = typename Sampler::Real;
  std::vector<double> us;
  double worst = 0;
  for (int i = 0; i <= n + 1; ++i) {
    double u = i == 0 ? 0.0 : i == n + 1 ? 1.0 : (i - 0.5) / n;
    double back = double(s.invert(s.sample(Real(u))));
    if (ks) {
      if (i > 0 && i <= n) us.push_back(back);
    } else {
      worst = std::max(worst, std::isfinite(back) ? std::abs(back - u) : kInf);
    }
  }
  if (!ks) return worst;
  std::sort(us.begin(), us.end());
  for (int i = 0; i < n; ++i)
    worst = std::max({worst, std::abs(us[i] - double(i) / n), std::abs(us[i] - double(i + 1) / n)});
  return worst;
}

template <typename SF, typename SD>
double Disagreement(const SF& sf, const SD& sd, int n) {
  double worst = 0;
  for (int i = 0; i <= n + 1; ++i) {
    double u = i == 0 ? 0.0 : i == n + 1 ? 1.0 : (i - 0.5) / n;
    double tf = double(sf.sample(float(u)));
    double td = sd.sample(u);
    double d = std::abs(sd.invert(tf) - sd.invert(td));
    worst = std::max(worst, std::isfinite(d) ? d : kInf);
  }
  return worst;
}

struct Row {
  std::string name;
  std::map<std::string, std::string> cell;  // metric|sampler -> text
};

// One registry entry (a segment sampler) on one hard case; `in_distribution`: its round trip
// holds in distribution only (the registry's property), so it is measured by KS.
template <typename Entry>
void Measure(bool in_distribution, const HardCase& hc, Row& row, int n) {
  using SD = typename Entry::template Sampler<double>;
  using SF = typename Entry::template Sampler<float>;
  const std::string method(Entry::kName);
  auto qd = Rounded(hc.q);
  auto qf = Cast<float>(hc.q);
  RefQuery ref(qd);
  SD sd(qd);
  SF sf(qf);
  bool mixture = in_distribution;
  double integral = hc.integrable ? Integral(ref) : kInf;
  std::vector<double> grid;
  double h = ref.h();
  if (h > 0) {
    double ta = ref.theta_of(ref.tmin), tb = std::isfinite(ref.tmax) ? ref.theta_of(ref.tmax) : kPi / 2;
    const int m = 10000;
    for (int i = 0; i <= m; ++i) {
      double t = ref.t_of(ta + (tb - ta) * i / m);
      if (std::isfinite(t)) grid.push_back(std::clamp(t, ref.tmin, ref.tmax));
    }
  }
  std::string key = method;
  if (!(integral > 0) || !std::isfinite(integral)) {
    // No weights: a zero integral (zero length) or a divergent one (p on the segment).
    WeightStats a = Weights<SD, double>(sd, ref, 1.0, ref.tmin, ref.tmax, {}, 2000, hc.name + " / " + method + " / double", integral != 0);
    WeightStats b = Weights<SF, float>(sf, ref, 1.0, ref.tmin, ref.tmax, {}, 2000, hc.name + " / " + method + " / float", integral != 0);
    std::string why = integral == 0 ? "(integral 0)" : "(diverges)";
    row.cell["wd|" + key] = why + (a.violations ? " !" : "");
    row.cell["wf|" + key] = why + (b.violations ? " !" : "");
  } else {
    WeightStats a = Weights<SD, double>(sd, ref, integral, ref.tmin, ref.tmax, grid, n, hc.name + " / " + method + " / double");
    WeightStats b = Weights<SF, float>(sf, ref, integral, ref.tmin, ref.tmax, grid, n, hc.name + " / " + method + " / float");
    row.cell["wd|" + key] = Fmt(a.max_w) + " (" + Fmt(a.mean_w) + ")" + (a.violations ? " !" : "");
    row.cell["wf|" + key] = Fmt(b.max_w) + " (" + Fmt(b.mean_w) + ")" + (b.violations ? " !" : "");
  }
  row.cell["fd|" + key] = Fmt(Disagreement(sf, sd, n / 10));
  std::string ks = mixture ? " KS" : "";
  if (!(qd.tmax > qd.tmin)) {
    row.cell["rt|" + key] = "n/a (zero length)";
    return;
  }
  row.cell["rt|" + key] = Fmt(RoundTrip(sf, n / 10, mixture)) + " / " + Fmt(RoundTrip(sd, n / 10, mixture)) + ks;
}

void PrintTable(const std::string& title, const std::string& metric, const std::vector<Row>& rows,
                const std::vector<std::string>& methods) {
  std::printf("\n### %s\n\n| case |", title.c_str());
  for (auto& m : methods) std::printf(" %s |", m.c_str());
  std::printf("\n|---|");
  for (size_t i = 0; i < methods.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (auto& r : rows) {
    std::printf("| %s |", r.name.c_str());
    for (auto& m : methods) {
      auto it = r.cell.find(metric + "|" + m);
      std::printf(" %s |", it == r.cell.end() ? "" : it->second.c_str());
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int n = argc > 1 ? std::max(100, std::atoi(argv[1])) : 100000;
  auto start = std::chrono::steady_clock::now();
  using Registry = vrlis::SegmentSamplers;
  std::vector<std::string> methods(Registry::kNames.begin(), Registry::kNames.end());
  std::vector<Row> rows;
  for (const HardCase& hc : HardCases()) {
    Row row{hc.name, {}};
    for (vrlis::SegmentChoice c : vrlis::kSegmentSamplers)
      Registry::WithEntry(c, [&](auto entry) {
        Measure<decltype(entry)>(Registry::kRoundTripInDistribution[std::size_t(c.index())], hc, row, n);
      });
    rows.push_back(row);
  }

  std::printf("## Camera-segment samplers\n\n");
  std::printf("Hard cases: the base geometry is the segment x(t) = (t, 0, 0), t in [-1, 3], seen from p = (0, 1, 0),\n"
              "both lobes Henyey-Greenstein with the point lobe's axis in the plane, peaking at theta = 0.3;\n"
              "each case changes one thing (see `tests/stability/reference.hpp`). Float runs use the case rounded\n"
              "to float; double runs use that same rounded query. %d stratified samples per cell.\n",
              n);
  PrintTable("Largest weight f / (pdf * integral), double (mean weight in parentheses; 1 is perfect)", "wd", rows,
             methods);
  PrintTable("Largest weight f / (pdf * integral), float (mean weight in parentheses)", "wf", rows, methods);
  PrintTable("Float versus double: max over u of |F(t_float(u)) - F(t_double(u))| (F: the double CDF)", "fd", rows,
             methods);
  PrintTable("Round trip max |invert(sample(u)) - u|, float / double (KS: Kolmogorov-Smirnov distance of "
             "invert(sample(U)) from uniform, for the mixture)",
             "rt", rows, methods);

  // VrlPoint.
  std::printf("\n## VrlPoint (step one)\n\nTarget: 1 / distance from y(v) to the camera line.\n\n");
  std::printf("| case | max weight, double (mean) | max weight, float (mean) | float vs double | round trip float / double |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const HardVrlCase& hc : HardVrlCases()) {
    auto qd = Rounded(hc.q);
    auto qf = Cast<float>(hc.q);
    RefVrlQuery<double> ref(qd);
    vrlis::VrlPoint<double> sd(qd);
    vrlis::VrlPoint<float> sf(qf);
    double integral = hc.integrable ? ref.Integral() : kInf;
    std::vector<double> grid;
    for (int i = 0; i <= 10000; ++i) grid.push_back(ref.tmin + (ref.tmax - ref.tmin) * i / 10000);
    std::string wd, wf;
    if (integral > 0 && std::isfinite(integral)) {
      WeightStats a = Weights<vrlis::VrlPoint<double>, double>(sd, ref, integral, ref.tmin, ref.tmax, grid, n,
                                                                "VrlPoint " + hc.name + " / double");
      WeightStats b = Weights<vrlis::VrlPoint<float>, float>(sf, ref, integral, ref.tmin, ref.tmax, grid, n,
                                                              "VrlPoint " + hc.name + " / float");
      wd = Fmt(a.max_w) + " (" + Fmt(a.mean_w) + ")" + (a.violations ? " !" : "");
      wf = Fmt(b.max_w) + " (" + Fmt(b.mean_w) + ")" + (b.violations ? " !" : "");
    } else {
      WeightStats a = Weights<vrlis::VrlPoint<double>, double>(sd, ref, 1.0, ref.tmin, ref.tmax, {}, 2000,
                                                                "VrlPoint " + hc.name + " / double", integral != 0);
      WeightStats b = Weights<vrlis::VrlPoint<float>, float>(sf, ref, 1.0, ref.tmin, ref.tmax, {}, 2000,
                                                              "VrlPoint " + hc.name + " / float", integral != 0);
      std::string why = integral == 0 ? "(integral 0)" : "(diverges)";
      wd = why + (a.violations ? " !" : "");
      wf = why + (b.violations ? " !" : "");
    }
    std::string rt = qd.tmax > qd.tmin
                         ? Fmt(RoundTrip(sf, n / 10, false)) + " / " + Fmt(RoundTrip(sd, n / 10, false))
                         : std::string("n/a (zero length)");
    std::printf("| %s | %s | %s | %s | %s |\n", hc.name.c_str(), wd.c_str(), wf.c_str(),
                Fmt(Disagreement(sf, sd, n / 10)).c_str(), rt.c_str());
  }

  std::printf("\n## Contract violations (cells marked !)\n\n");
  if (g_violations.empty()) std::printf("None.\n");
  for (auto& v : g_violations) std::printf("- %s\n", v.c_str());
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "vrlis_stability: %.1f s\n", secs);
  return 0;
}
