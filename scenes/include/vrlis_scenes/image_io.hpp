#pragma once
// Output files, each written to a temporary file beside its target and renamed into place,
// so a failed run never leaves a partial or corrupt file.
#include <optional>
#include <string>

#include <vrlis_integration/film.hpp>

namespace vrlis::scenes {

// Linear float RGB OpenEXR. Return false (and remove the temporary) on failure.
bool WriteExr(const std::string& path, const vrlis::integration::Film& film, std::string* error);
// An 8-bit sRGB preview of film * exposure.
bool WritePng(const std::string& path, const vrlis::integration::Film& film, float exposure, std::string* error);
bool WriteText(const std::string& path, const std::string& text, std::string* error);
std::optional<vrlis::integration::Film> ReadExr(const std::string& path, std::string* error);

// A scale that maps the 99th percentile of luminance to 0.8 (1 for a black image).
float AutoExposure(const vrlis::integration::Film& film);

// Whether a file can be created at path (tested with a temporary that is removed again).
bool CanWrite(const std::string& path);

}  // namespace vrlis::scenes
