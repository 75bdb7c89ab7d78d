#include "ImageOutput.h"

#include "AMRDualMeshImageIO.h"

#include "transport/Integrators.h" // For amrdm::heatRamp

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sys/stat.h>
#include <unistd.h>

namespace amrdm_app
{
namespace
{
std::string lower(std::string s)
{
  std::transform(
    s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}
}

bool CheckImageTarget(const std::string& path, ImageTarget& target, std::string& error)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  const std::string ext = dot == std::string::npos || dot == 0 ? "" : lower(name.substr(dot));
  if (ext == ".png")
    target.format = ImageFormat::PngAndExr;
  else if (ext == ".exr")
    target.format = ImageFormat::Exr;
  else if (ext == ".jpg" || ext == ".jpeg")
    target.format = ImageFormat::Jpeg;
  else
  {
    error =
      "-o '" + path + "': " +
      (ext.empty() ? std::string("no file extension") : "unknown image format '" + ext + "'") +
      "; expected NAME.png (with NAME.exr), NAME.exr or NAME.jpg";
    return false;
  }
  target.extension = path.substr(path.size() - ext.size());
  target.base = path.substr(0, path.size() - ext.size());
  const std::string folder = slash == std::string::npos
                               ? std::string(".")
                               : (slash == 0 ? std::string("/") : path.substr(0, slash));
  struct stat st;
  if (stat(folder.c_str(), &st) != 0)
  {
    error =
      "-o '" + path + "': the folder '" + folder + "' does not exist; expected an existing folder";
    return false;
  }
  if (!S_ISDIR(st.st_mode))
  {
    error = "-o '" + path + "': '" + folder + "' is not a folder";
    return false;
  }
  if (access(folder.c_str(), W_OK | X_OK) != 0)
  {
    error = "-o '" + path + "': the folder '" + folder + "' is not writable";
    return false;
  }
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    error = "-o '" + path + "' is a folder; expected a file name";
    return false;
  }
  return true;
}

void ApplyExposure(std::vector<float>& rgba, double stops)
{
  if (stops == 0.0)
    return;
  const float f = float(std::exp2(stops));
  for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c)
      rgba[i + c] *= f;
}

bool RescaleCostImage(std::vector<float>& rgba, double renderedScale, double& whiteCost)
{
  std::vector<double> cost(rgba.size() / 4);
  std::vector<double> nonZero;
  for (std::size_t p = 0; p < cost.size(); ++p)
  {
    cost[p] = (rgba[4 * p] + rgba[4 * p + 1] + rgba[4 * p + 2]) / 3.0 * renderedScale;
    if (cost[p] > 0.0)
      nonZero.push_back(cost[p]);
  }
  whiteCost = 0.0;
  if (nonZero.empty())
    return false;
  const std::size_t k = std::min(nonZero.size() - 1, std::size_t(0.995 * double(nonZero.size())));
  std::nth_element(nonZero.begin(), nonZero.begin() + std::ptrdiff_t(k), nonZero.end());
  whiteCost = nonZero[k];
  for (std::size_t p = 0; p < cost.size(); ++p)
  {
    const glm::vec3 c = amrdm::heatRamp(float(cost[p] / whiteCost));
    rgba[4 * p] = c.x;
    rgba[4 * p + 1] = c.y;
    rgba[4 * p + 2] = c.z;
    rgba[4 * p + 3] = 1.0f;
  }
  return true;
}

bool WriteImage(const ImageTarget& target,
  int width,
  int height,
  const std::vector<float>& rgba,
  const double background[3],
  std::vector<std::string>& written,
  std::string& error)
{
  written.clear();
  const std::string path = target.base + target.extension;
  switch (target.format)
  {
    case ImageFormat::PngAndExr:
      if (!amrdm_vtk::WritePNG(path, width, height, rgba.data(), background, error))
        return false;
      written.push_back(path);
      if (!amrdm_vtk::WriteEXR(target.base + ".exr", width, height, rgba.data(), error))
        return false;
      written.push_back(target.base + ".exr");
      return true;
    case ImageFormat::Exr:
      if (!amrdm_vtk::WriteEXR(path, width, height, rgba.data(), error))
        return false;
      written.push_back(path);
      return true;
    case ImageFormat::Jpeg:
      if (!amrdm_vtk::WriteImage8(
            path, amrdm_vtk::Image8Format::JPEG, width, height, rgba.data(), background, error))
        return false;
      written.push_back(path);
      return true;
  }
  return false;
}
}
