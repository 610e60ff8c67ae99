#include "reference.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <vrlis_scenes/image_io.hpp>
#include "error_to_noise.hpp"
#include "image_stats.hpp"

namespace vrlis::compare {

namespace {

// The reference's noise is tiny next to its mean: keep it in its own file at full range.
std::optional<Reference> LoadCached(const std::filesystem::path& base, const std::string& key, int width, int height) {
  std::ifstream meta(base.string() + ".json");
  if (!meta) return std::nullopt;
  nlohmann::json j = nlohmann::json::parse(meta, nullptr, false);
  if (j.is_discarded() || j.value("key", "") != key) return std::nullopt;
  std::string error;
  auto mean = vrlis::scenes::ReadExr(base.string() + ".exr", &error);
  auto var = vrlis::scenes::ReadExr(base.string() + ".variance.exr", &error);
  if (!mean || !var || mean->width != width || mean->height != height || var->width != width || var->height != height)
    return std::nullopt;
  Reference r;
  r.mean = FromFilm(*mean);
  r.variance_of_mean = FromFilm(*var);
  r.passes = j.value("passes", 0);
  r.dof = j.value("dof", 1.0);
  r.seconds = j.value("seconds", 0.0);
  r.from_cache = true;
  return r;
}

void Store(const std::filesystem::path& base, const std::string& key, const Reference& r, int width, int height) {
  std::string error;
  if (!vrlis::scenes::WriteExr(base.string() + ".exr", ToFilm(r.mean, width, height), &error) ||
      !vrlis::scenes::WriteExr(base.string() + ".variance.exr", ToFilm(r.variance_of_mean, width, height), &error))
    throw std::runtime_error("cannot write reference " + base.string() + ": " + error);
  nlohmann::json j = {{"key", key}, {"passes", r.passes}, {"seconds", r.seconds}, {"dof", r.dof}};
  // Written last: a reference counts as cached only once its images are complete.
  if (!vrlis::scenes::WriteText(base.string() + ".json", j.dump(2) + "\n", &error))
    throw std::runtime_error("cannot write reference metadata: " + error);
}

}  // namespace

Reference GetReference(PassRenderer& renderer, const std::vector<GatherSamplers>& mixture, double seconds,
                       int min_passes, const std::string& dir, const std::string& name, const std::string& key,
                       int width, int height) {
  std::filesystem::create_directories(dir);
  std::filesystem::path base = std::filesystem::path(dir) / name;
  if (auto cached = LoadCached(base, key, width, height)) return *cached;

  PassStatistics stats(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  const std::uint64_t seed = 0x5EEDull;  // never used by the comparison runs
  double elapsed = 0;
  std::vector<std::vector<double>> passes;  // for the noise's degrees of freedom
  // Whole rounds, so that every sampler holds the same share of the mixture.
  while (elapsed < seconds || stats.passes() < std::max(min_passes, 2 * static_cast<int>(mixture.size()))) {
    for (GatherSamplers s : mixture) {
      double t = 0;
      passes.push_back(FromFilm(renderer.Render(Method{s, false}, seed, static_cast<std::uint64_t>(stats.passes()), &t)));
      stats.Add(passes.back());
      elapsed += t;
    }
  }
  Reference r{stats.Mean(), stats.VarianceOfMean(), NoiseDof(passes), stats.passes(), elapsed, false};
  Store(base, key, r, width, height);
  return r;
}

}  // namespace vrlis::compare
