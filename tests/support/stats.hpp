#pragma once
// Quadrature, Pearson's chi-square test and the suite's summary file.
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "integrand.hpp"

namespace vrlis::test {

// ---- Quadrature -----------------------------------------------------------------------

// Adaptive Gauss-Kronrod on [a, b]. Callers split at peaks first: an adaptive rule only
// refines where its error estimate sees trouble, and a spike between two nodes is invisible.
template <typename F>
double Integrate(F f, double a, double b, double tol = 1e-12, unsigned depth = 30) {
  if (!(b > a)) return 0;
  double error = 0;
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, depth, tol, &error);
}

// Cell edges on [a, b]: a uniform grid, the features, and geometric refinement towards
// every feature and both ends (spikes of Henyey-Greenstein lobes with |g| -> 1 and of the
// Cauchy fits sit exactly there), so that every cell is smooth enough for Gauss-Kronrod
// and fine enough for chi-square bins to resolve a spike's shape.
inline std::vector<double> RefinedGrid(double a, double b, std::vector<double> features, int uniform_cells = 96,
                                       int levels = 24) {
  std::vector<double> x;
  double w = b - a;
  for (int i = 0; i <= uniform_cells; ++i) x.push_back(a + w * i / uniform_cells);
  features.push_back(a);
  features.push_back(b);
  for (double f : features) {
    x.push_back(f);
    for (int k = 1; k <= levels; ++k)
      for (double sub : {1.0, 1.5}) {  // two cells per octave: a spike's shape, not just its mass
        double d = sub * w * std::ldexp(1.0, -k);
        x.push_back(f - d);
        x.push_back(f + d);
      }
  }
  std::vector<double> out;
  for (double v : x)
    if (v >= a && v <= b) out.push_back(v);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(), [&](double p, double q) { return q - p <= 1e-14 * w; }), out.end());
  out.front() = a;
  out.back() = b;
  return out;
}

// Gauss-Kronrod on [a, b], bisected until its error estimate is below abs_tol.
template <typename F>
double AdaptiveGaussKronrod(F& f, double a, double b, double abs_tol, unsigned depth, double estimate, double error) {
  if (error <= abs_tol || depth == 0 || !std::isfinite(estimate)) return estimate;
  double mid = (a + b) / 2, e1 = 0, e2 = 0;
  double i1 = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, mid, 0, 0, &e1);
  double i2 = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, mid, b, 0, 0, &e2);
  return AdaptiveGaussKronrod(f, a, mid, abs_tol / 2, depth - 1, i1, e1) +
         AdaptiveGaussKronrod(f, mid, b, abs_tol / 2, depth - 1, i2, e2);
}

// The integral of f over each cell [x_i, x_i+1], to a tolerance relative to the whole
// integral. (Boost's adaptive rule is relative per call: on a cell holding a negligible
// mass of a noisy integrand, such as any float pdf, or a double one next to theta = pi/2,
// it would bisect to the bottom chasing digits below the noise.) The depth is capped
// because the grid already resolves the features.
template <typename F>
std::vector<double> CellIntegrals(F f, const std::vector<double>& edges, double tol = 1e-11, unsigned depth = 6) {
  std::size_t cells = edges.size() - 1;
  std::vector<double> estimate(cells), error(cells);
  double total = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    estimate[i] = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, edges[i], edges[i + 1], 0, 0, &error[i]);
    total += std::abs(estimate[i]);
  }
  double abs_tol = tol * total / std::sqrt(double(cells));  // cell errors are not all of one sign
  for (std::size_t i = 0; i < cells; ++i)
    estimate[i] = AdaptiveGaussKronrod(f, edges[i], edges[i + 1], abs_tol, depth, estimate[i], error[i]);
  return estimate;
}

inline double Sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

// ---- Pearson's chi-square -------------------------------------------------------------

// Each chi-square test in tests/lib is run at significance 0.01 / kChiSquareBudget
// (Bonferroni; valid without any independence assumption). The budget is an upper bound on
// the number of chi-square tests the suite runs; the summary step counts them and fails if
// the suite outgrows it.
inline constexpr double kChiSquareFamilyAlpha = 0.01;
inline constexpr int kChiSquareBudget = 4000;
inline constexpr double kChiSquareAlpha = kChiSquareFamilyAlpha / kChiSquareBudget;

struct ChiSquare {
  double statistic = 0;
  int dof = 0;
  double p_value = 1;
  int bins = 0;
  long unexpected = 0;  // samples in bins of expected probability zero: an outright failure
  bool Passes() const { return unexpected == 0 && p_value >= kChiSquareAlpha; }
};

// Pearson's test of counts against probabilities. Adjacent bins are pooled until the
// expected count reaches 5, the usual condition for the chi-square approximation.
inline ChiSquare PearsonTest(const std::vector<long>& observed, const std::vector<double>& probability, long n) {
  ChiSquare r;
  double total_p = 0;
  for (double p : probability) total_p += p;
  std::vector<double> e_pooled;
  std::vector<long> o_pooled;
  double e = 0;
  long o = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    double expected = n * probability[i] / total_p;
    if (!(probability[i] > 0) && observed[i] > 0) r.unexpected += observed[i];
    e += expected;
    o += observed[i];
    if (e >= 5) {
      e_pooled.push_back(e);
      o_pooled.push_back(o);
      e = 0;
      o = 0;
    }
  }
  if (!e_pooled.empty()) {
    e_pooled.back() += e;
    o_pooled.back() += o;
  }
  r.bins = int(e_pooled.size());
  r.dof = r.bins - 1;
  for (std::size_t i = 0; i < e_pooled.size(); ++i) r.statistic += Square(double(o_pooled[i]) - e_pooled[i]) / e_pooled[i];
  r.p_value = r.dof > 0 ? boost::math::cdf(boost::math::complement(boost::math::chi_squared(r.dof), r.statistic)) : 1.0;
  return r;
}

// Bins for a chi-square test from cells and their probabilities: consecutive cells merge
// until a bin holds `target` probability and `wide_enough(lo, hi)` holds. The latter lets a
// float sampler be tested only at scales its t can resolve (its ulp), not below.
template <typename WideEnough>
void MergeCells(const std::vector<double>& edges, const std::vector<double>& cell_p, double target,
                WideEnough wide_enough, std::vector<double>& bin_edges, std::vector<double>& bin_p) {
  bin_edges = {edges.front()};
  bin_p.clear();
  double p = 0;
  for (std::size_t i = 0; i < cell_p.size(); ++i) {
    p += cell_p[i];
    if (p >= target && wide_enough(bin_edges.back(), edges[i + 1])) {
      bin_edges.push_back(edges[i + 1]);
      bin_p.push_back(p);
      p = 0;
    }
  }
  if (bin_p.empty() || p > 0 || bin_edges.back() < edges.back()) {
    if (bin_p.empty()) {
      bin_edges.push_back(edges.back());
      bin_p.push_back(p);
    } else {
      bin_edges.back() = edges.back();
      bin_p.back() += p;
    }
  }
}

// Counts of the values x in the bins [edges_i, edges_i+1] (closed at the last edge).
inline std::vector<long> Histogram(const std::vector<double>& x, const std::vector<double>& edges) {
  std::vector<long> counts(edges.size() - 1, 0);
  for (double v : x) {
    auto it = std::upper_bound(edges.begin(), edges.end(), v);
    long i = long(it - edges.begin()) - 1;
    i = std::clamp(i, 0L, long(counts.size()) - 1);
    counts[std::size_t(i)]++;
  }
  return counts;
}

// ---- Summary --------------------------------------------------------------------------

// The worst value of each metric seen by this process, per sampler label, written on exit
// to VRLIS_LIB_SUMMARY_DIR/<file>.txt as "label metric value note" lines; lib_summary
// merges the files of all test processes.
class Summary {
 public:
  static Summary& Get() {
    static Summary s;
    return s;
  }
  void SetFile(const std::string& name) { file_ = name; }
  void Max(const std::string& label, const std::string& metric, double value, const std::string& note = "") {
    auto key = label + " " + metric;
    auto it = worst_.find(key);
    if (it == worst_.end() || value > it->second.first || std::isnan(value)) worst_[key] = {value, note};
  }
  void Count(const std::string& label, const std::string& metric, double n = 1) { counts_[label + " " + metric] += n; }
  ~Summary() {
#ifdef VRLIS_LIB_SUMMARY_DIR
    if (file_.empty() || (worst_.empty() && counts_.empty())) return;
    std::ofstream out(std::string(VRLIS_LIB_SUMMARY_DIR) + "/" + file_ + ".txt");
    out.precision(6);
    for (auto& [key, v] : worst_) out << "max " << key << " " << v.first << " " << v.second << "\n";
    for (auto& [key, n] : counts_) out << "count " << key << " " << n << "\n";
#endif
  }

 private:
  std::string file_;
  std::map<std::string, std::pair<double, std::string>> worst_;
  std::map<std::string, double> counts_;
};

}  // namespace vrlis::test
