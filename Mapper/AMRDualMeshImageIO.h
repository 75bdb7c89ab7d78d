// Writing rendered images: float RGBA to OpenEXR (linear, premultiplied, lossless float) and an
// 8-bit PNG or JPEG composited over a background with sRGB encoding. Not wrapped for Python.
#ifndef AMRDualMeshImageIO_h
#define AMRDualMeshImageIO_h

#include "AMRDualMeshMapperModule.h" // For export macro

#include <string>

namespace amrdm_vtk
{
/// `rgba`: width*height premultiplied RGBA floats, rows from the bottom (VTK order). Writes 32-bit
/// float R, G, B, A channels. Returns false and sets `error` on failure.
AMRDUALMESHMAPPER_EXPORT bool WriteEXR(const std::string& path,
  int width,
  int height,
  const float* rgba,
  std::string& error);

/// 8-bit formats: lossless PNG, or JPEG at quality 95.
enum class Image8Format
{
  PNG,
  JPEG
};

/// Composites `rgba` over `background` (linear RGB), encodes sRGB, writes an 8-bit RGB image.
AMRDUALMESHMAPPER_EXPORT bool WriteImage8(const std::string& path,
  Image8Format format,
  int width,
  int height,
  const float* rgba,
  const double background[3],
  std::string& error);

/// WriteImage8 as PNG.
AMRDUALMESHMAPPER_EXPORT bool WritePNG(const std::string& path,
  int width,
  int height,
  const float* rgba,
  const double background[3],
  std::string& error);
}

#endif
