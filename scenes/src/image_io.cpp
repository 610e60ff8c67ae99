#include "vrlis_scenes/image_io.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <vector>

namespace vrlis::scenes {
namespace {

std::string TempPath(const std::string& path) { return path + ".tmp" + std::to_string(getpid()); }

// Runs write(temporary), then renames the temporary to path.
template <typename F>
bool Atomically(const std::string& path, std::string* error, F&& write) {
  std::string tmp = TempPath(path);
  bool ok = false;
  try {
    ok = write(tmp);
  } catch (const std::exception& e) {
    *error = e.what();
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    *error = "cannot rename into " + path;
    ok = false;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    if (error->empty()) *error = "cannot write " + path;
  }
  return ok;
}

std::uint8_t ToSrgb8(float v) {
  v = std::clamp(v, 0.f, 1.f);
  float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(s * 255));
}

}  // namespace

bool WriteExr(const std::string& path, const vrlis::integration::Film& film, std::string* error) {
  return Atomically(path, error, [&](const std::string& tmp) {
    Imf::Header header(film.width, film.height);
    Imf::FrameBuffer fb;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(film.pixels.data()));
    const std::size_t xs = sizeof(vrlis::integration::Spectrum), ys = xs * static_cast<std::size_t>(film.width);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
    }
    Imf::OutputFile file(tmp.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(film.height);
    return true;
  });
}

std::optional<vrlis::integration::Film> ReadExr(const std::string& path, std::string* error) {
  try {
    Imf::InputFile file(path.c_str());
    Imath::Box2i dw = file.header().dataWindow();
    vrlis::integration::Film film(dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1);
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(film.pixels.data());
    const std::size_t xs = sizeof(vrlis::integration::Spectrum), ys = xs * static_cast<std::size_t>(film.width);
    base -= (static_cast<std::ptrdiff_t>(dw.min.x) * xs + static_cast<std::ptrdiff_t>(dw.min.y) * ys);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return film;
  } catch (const std::exception& e) {
    *error = e.what();
    return std::nullopt;
  }
}

bool WritePng(const std::string& path, const vrlis::integration::Film& film, float exposure, std::string* error) {
  return Atomically(path, error, [&](const std::string& tmp) {
    std::vector<std::uint8_t> rgb;
    rgb.reserve(film.pixels.size() * 3);
    for (const vrlis::integration::Spectrum& s : film.pixels)
      for (float v : {s.r, s.g, s.b}) rgb.push_back(ToSrgb8(v * exposure));
    return stbi_write_png(tmp.c_str(), film.width, film.height, 3, rgb.data(), film.width * 3) != 0;
  });
}

bool WriteText(const std::string& path, const std::string& text, std::string* error) {
  return Atomically(path, error, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    return static_cast<bool>(out);
  });
}

float AutoExposure(const vrlis::integration::Film& film) {
  std::vector<float> lum;
  for (const vrlis::integration::Spectrum& s : film.pixels) lum.push_back(0.2126f * s.r + 0.7152f * s.g + 0.0722f * s.b);
  if (lum.empty()) return 1;
  auto k = lum.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(lum.size() - 1));
  std::nth_element(lum.begin(), k, lum.end());
  return *k > 0 && std::isfinite(*k) ? 0.8f / *k : 1.f;
}

bool CanWrite(const std::string& path) {
  std::string tmp = TempPath(path);
  std::ofstream probe(tmp, std::ios::binary);
  bool ok = static_cast<bool>(probe);
  probe.close();
  if (ok) std::remove(tmp.c_str());
  return ok;
}

}  // namespace vrlis::scenes
