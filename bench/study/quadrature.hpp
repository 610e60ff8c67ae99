#pragma once
// Globally adaptive Gauss-Kronrod (7/15-point) quadrature of a vector-valued integrand:
// one pass integrates f and f^2 / p for every sampler at once, sharing the expensive
// geometry. The interval with the largest relative error is bisected until the summed
// error of every component is below rel_tol times that component's integral.
// The error of an interval is |K15 - G7|, the error of the 7-point rule: a pessimistic
// bound for the 15-point value we keep, so the true error is usually far smaller.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace vrlis::study {

template <int N>
struct QuadratureResult {
  std::array<double, N> value{}, error{};
  int evaluations = 0;
  bool converged = false;
};

template <int N, typename F>
QuadratureResult<N> Integrate(F&& f, std::vector<double> breaks, double rel_tol, int max_evaluations,
                              double abs_floor = 1e-300) {
  using Vec = std::array<double, N>;
  static constexpr double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                    0.207784955007898467600689403773245, 0.0};
  static constexpr double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
  static constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                   0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
  struct Piece {
    double a, b;
    Vec value, error;
    double priority;
  };
  QuadratureResult<N> result;
  auto rule = [&](double a, double b) {
    Piece p{a, b, {}, {}, 0};
    double c = (a + b) / 2, h = (b - a) / 2;
    Vec k{}, g{};
    Vec fc = f(c);
    for (int n = 0; n < N; ++n) {
      k[n] = wgk[7] * fc[n];
      g[n] = wg[3] * fc[n];
    }
    for (int j = 0; j < 7; ++j) {
      Vec f1 = f(c - h * xgk[j]), f2 = f(c + h * xgk[j]);
      for (int n = 0; n < N; ++n) {
        k[n] += wgk[j] * (f1[n] + f2[n]);
        if (j % 2 == 1) g[n] += wg[j / 2] * (f1[n] + f2[n]);
      }
    }
    result.evaluations += 15;
    for (int n = 0; n < N; ++n) {
      p.value[n] = k[n] * h;
      p.error[n] = std::abs((k[n] - g[n]) * h);
    }
    return p;
  };

  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<Piece> pieces;
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    if (breaks[i + 1] > breaks[i]) pieces.push_back(rule(breaks[i], breaks[i + 1]));

  auto totals = [&] {
    result.value.fill(0);
    result.error.fill(0);
    for (const Piece& p : pieces)
      for (int n = 0; n < N; ++n) {
        result.value[n] += p.value[n];
        result.error[n] += p.error[n];
      }
  };
  totals();
  Vec scale;
  auto rescale = [&] {
    for (int n = 0; n < N; ++n) scale[n] = std::max(std::abs(result.value[n]), abs_floor);
    for (Piece& p : pieces) {
      p.priority = 0;
      for (int n = 0; n < N; ++n) p.priority = std::max(p.priority, p.error[n] / scale[n]);
    }
    std::make_heap(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.priority < y.priority; });
  };
  auto done = [&] {
    for (int n = 0; n < N; ++n)
      if (!(result.error[n] <= rel_tol * std::abs(result.value[n]) || result.error[n] <= abs_floor)) return false;
    return true;
  };
  auto less = [](const Piece& x, const Piece& y) { return x.priority < y.priority; };
  rescale();
  int since_rescale = 0;
  while (!done() && result.evaluations + 30 <= max_evaluations && !pieces.empty()) {
    std::pop_heap(pieces.begin(), pieces.end(), less);
    Piece worst = pieces.back();
    pieces.pop_back();
    double mid = (worst.a + worst.b) / 2;
    if (!(mid > worst.a && mid < worst.b)) {  // no more digits to split: keep it, stop
      pieces.push_back(worst);
      break;
    }
    for (Piece child : {rule(worst.a, mid), rule(mid, worst.b)}) {
      child.priority = 0;
      for (int n = 0; n < N; ++n) {
        result.value[n] += child.value[n];
        result.error[n] += child.error[n];
        child.priority = std::max(child.priority, child.error[n] / scale[n]);
      }
      pieces.push_back(child);
      std::push_heap(pieces.begin(), pieces.end(), less);
    }
    for (int n = 0; n < N; ++n) {
      result.value[n] -= worst.value[n];
      result.error[n] -= worst.error[n];
    }
    if (++since_rescale == 64) {  // refresh the sums (drift) and the scales
      totals();
      rescale();
      since_rescale = 0;
    }
  }
  totals();
  result.converged = done();
  return result;
}

}  // namespace vrlis::study
