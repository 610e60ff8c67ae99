#include <vrlis_scenes/image_io.hpp>

#include "reference.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "image_stats.hpp"

namespace vrl_compare {

vrli::Film ToFilm(const std::vector<double>& rgb, int width, int height) {
  vrli::Film film(width, height);
  for (std::size_t i = 0; i < film.pixels.size(); ++i)
    film.pixels[i] = {static_cast<float>(rgb[3 * i]), static_cast<float>(rgb[3 * i + 1]),
                      static_cast<float>(rgb[3 * i + 2])};
  return film;
}

std::vector<double> FromFilm(const vrli::Film& film) {
  std::vector<double> rgb(3 * film.pixels.size());
  for (std::size_t i = 0; i < film.pixels.size(); ++i) {
    rgb[3 * i] = film.pixels[i].r;
    rgb[3 * i + 1] = film.pixels[i].g;
    rgb[3 * i + 2] = film.pixels[i].b;
  }
  return rgb;
}

namespace {

// The reference's noise is tiny next to its mean: keep it in its own file at full range.
std::optional<Reference> LoadCached(const std::filesystem::path& base, const std::string& key, int width, int height) {
  std::ifstream meta(base.string() + ".json");
  if (!meta) return std::nullopt;
  nlohmann::json j = nlohmann::json::parse(meta, nullptr, false);
  if (j.is_discarded() || j.value("key", "") != key) return std::nullopt;
  std::string error;
  auto mean = vrl_render::ReadExr(base.string() + ".exr", &error);
  auto var = vrl_render::ReadExr(base.string() + ".variance.exr", &error);
  if (!mean || !var || mean->width != width || mean->height != height || var->width != width || var->height != height)
    return std::nullopt;
  Reference r;
  r.mean = FromFilm(*mean);
  r.variance_of_mean = FromFilm(*var);
  r.passes = j.value("passes", 0);
  r.seconds = j.value("seconds", 0.0);
  r.from_cache = true;
  return r;
}

void Store(const std::filesystem::path& base, const std::string& key, const Reference& r, int width, int height) {
  std::string error;
  if (!vrl_render::WriteExr(base.string() + ".exr", ToFilm(r.mean, width, height), &error) ||
      !vrl_render::WriteExr(base.string() + ".variance.exr", ToFilm(r.variance_of_mean, width, height), &error))
    throw std::runtime_error("cannot write reference " + base.string() + ": " + error);
  nlohmann::json j = {{"key", key}, {"passes", r.passes}, {"seconds", r.seconds}};
  // Written last: a reference counts as cached only once its images are complete.
  if (!vrl_render::WriteText(base.string() + ".json", j.dump(2) + "\n", &error))
    throw std::runtime_error("cannot write reference metadata: " + error);
}

}  // namespace

Reference GetReference(vrli::Renderer& renderer, double seconds, const std::string& dir,
                       const std::string& name, const std::string& key, int width, int height) {
  std::filesystem::create_directories(dir);
  std::filesystem::path base = std::filesystem::path(dir) / name;
  if (auto cached = LoadCached(base, key, width, height)) return *cached;

  PassStatistics stats(width, height);
  const std::uint64_t seed = 0x5EEDull;  // never used by the comparison runs
  auto start = std::chrono::steady_clock::now();
  double elapsed = 0;
  while (elapsed < seconds || stats.passes() < 2) {
    vrli::PassStats pass_stats;
    stats.Add(renderer.RenderPass(seed, static_cast<std::uint64_t>(stats.passes()), &pass_stats));
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  Reference r{stats.Mean(), stats.VarianceOfMean(), stats.passes(), elapsed, false};
  Store(base, key, r, width, height);
  return r;
}

}  // namespace vrl_compare
