// amrdm-render's image output: the format chosen by the extension of -o and checked (with the
// folder) before anything is rendered, the exposure, the cost view's own scale, and the writers.
#ifndef ImageOutput_h
#define ImageOutput_h

#include <string>
#include <vector>

namespace amrdm_app
{
enum class ImageFormat
{
  PngAndExr, ///< NAME.png: an sRGB PNG over the background and NAME.exr (float RGBA) next to it
  Exr,       ///< NAME.exr only
  Jpeg       ///< NAME.jpg or NAME.jpeg: sRGB over the background, quality 95
};

struct ImageTarget
{
  ImageFormat format = ImageFormat::PngAndExr;
  std::string base;      ///< the path without its extension
  std::string extension; ///< ".png", ".exr", ".jpg" or ".jpeg" (as given)
};

/// Checks `path`'s extension (.png, .exr, .jpg, .jpeg, any case) and that its folder exists and
/// is writable. Returns false and sets `error` naming what was wrong and what was expected.
bool CheckImageTarget(const std::string& path, ImageTarget& target, std::string& error);

/// Multiplies the premultiplied RGB of `rgba` by 2^stops (alpha unchanged).
void ApplyExposure(std::vector<float>& rgba, double stops);

/// The cost debug view renders heatRamp(cost / scale) per sample; with a scale above every cost
/// (no clamping) the mean cost per pixel is (R + G + B) / 3 * scale. This rescales the image to
/// its own range: black = 0, white = the 99.5th percentile of the costs of the pixels that have
/// any (`whiteCost`, in steps + primitive tests per sample). Returns false when no pixel has cost.
bool RescaleCostImage(std::vector<float>& rgba, double renderedScale, double& whiteCost);

/// Writes the image in `target`'s format. `written` receives the paths written.
bool WriteImage(const ImageTarget& target,
  int width,
  int height,
  const std::vector<float>& rgba,
  const double background[3],
  std::vector<std::string>& written,
  std::string& error);
}

#endif
