#include "image_stats.hpp"

namespace vrlis::compare {

vrlis::integration::Film ToFilm(const std::vector<double>& rgb, int width, int height) {
  vrlis::integration::Film film(width, height);
  for (std::size_t i = 0; i < film.pixels.size(); ++i)
    film.pixels[i] = {static_cast<float>(rgb[3 * i]), static_cast<float>(rgb[3 * i + 1]),
                      static_cast<float>(rgb[3 * i + 2])};
  return film;
}

std::vector<double> FromFilm(const vrlis::integration::Film& film) {
  std::vector<double> rgb(3 * film.pixels.size());
  for (std::size_t i = 0; i < film.pixels.size(); ++i) {
    rgb[3 * i] = film.pixels[i].r;
    rgb[3 * i + 1] = film.pixels[i].g;
    rgb[3 * i + 2] = film.pixels[i].b;
  }
  return rgb;
}

}  // namespace vrlis::compare
