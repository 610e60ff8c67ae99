#include "vrlis_integration/vpl.hpp"

#include <algorithm>

namespace vrlis::integration {

Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const std::vector<Vpl>& vpls,
                    float bound) {
  Spectrum sum;
  if (!(bound > 0)) return sum;
  for (const Vpl& v : vpls) {
    float g = std::min(GeometryTerm(p, nf, v.p, v.n), bound);
    if (!(g > 0)) continue;
    float tr = scene.Connect(p, v.p);
    if (tr > 0) sum += v.flux * (g * tr);
  }
  return sum * albedo * (1 / kPi);
}

}  // namespace vrlis::integration
