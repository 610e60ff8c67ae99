#pragma once
// Output files, each written to a temporary file beside its target and renamed into place,
// so a failed run never leaves a partial or corrupt file.
#include <optional>
#include <string>

#include <vrlis_integration/film.hpp>

namespace vrl_render {

// Linear float RGB OpenEXR. Return false (and remove the temporary) on failure.
bool WriteExr(const std::string& path, const vrli::Film& film, std::string* error);
// An 8-bit sRGB preview of film * exposure.
bool WritePng(const std::string& path, const vrli::Film& film, float exposure, std::string* error);
bool WriteText(const std::string& path, const std::string& text, std::string* error);
std::optional<vrli::Film> ReadExr(const std::string& path, std::string* error);

// A scale that maps the 99th percentile of luminance to 0.8 (1 for a black image).
float AutoExposure(const vrli::Film& film);

// Whether a file can be created at path (tested with a temporary that is removed again).
bool CanWrite(const std::string& path);

}  // namespace vrl_render
