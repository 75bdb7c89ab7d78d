#include "AMRDualMeshImageIO.h"

#include "vtkImageData.h"
#include "vtkImageWriter.h"
#include "vtkNew.h"
#include "vtkJPEGWriter.h"
#include "vtkPNGWriter.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkPointData.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace amrdm_vtk
{

bool WriteEXR(const std::string& path, int width, int height, const float* rgba, std::string& error)
{
  if (width <= 0 || height <= 0 || !rgba)
  {
    error = "WriteEXR: empty image";
    return false;
  }
  try
  {
    Imf::Header header(width, height);
    const char* names[4] = { "R", "G", "B", "A" };
    for (const char* name : names)
    {
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    Imf::FrameBuffer frame;
    // EXR rows run top-down; ours bottom-up: start at the last row with a negative stride.
    const std::size_t rowBytes = sizeof(float) * 4 * static_cast<std::size_t>(width);
    const char* top = reinterpret_cast<const char*>(rgba) + rowBytes * (height - 1);
    for (int c = 0; c < 4; ++c)
    {
      frame.insert(names[c],
        Imf::Slice(Imf::FLOAT,
          const_cast<char*>(top + c * sizeof(float)),
          4 * sizeof(float),
          -static_cast<std::ptrdiff_t>(rowBytes)));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  }
  catch (const std::exception& e)
  {
    error = std::string("cannot write EXR '") + path + "': " + e.what();
    return false;
  }
  return true;
}

namespace
{
unsigned char encodeSRGB(double linear)
{
  const double c = std::min(1.0, std::max(0.0, linear));
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(255.0 * s));
}
}

bool WriteImage8(const std::string& path,
  Image8Format format,
  int width,
  int height,
  const float* rgba,
  const double background[3],
  std::string& error)
{
  if (width <= 0 || height <= 0 || !rgba)
  {
    error = "WriteImage8: empty image";
    return false;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(width) * height; ++i)
  {
    const float* p = rgba + 4 * i;
    for (int c = 0; c < 3; ++c)
    {
      pixels->SetValue(3 * i + c, encodeSRGB(p[c] + (1.0 - p[3]) * background[c]));
    }
  }
  image->GetPointData()->SetScalars(pixels);
  const bool png = format == Image8Format::PNG;
  vtkSmartPointer<vtkImageWriter> writer;
  if (png)
  {
    writer = vtkSmartPointer<vtkPNGWriter>::New();
  }
  else
  {
    auto jpeg = vtkSmartPointer<vtkJPEGWriter>::New();
    jpeg->SetQuality(95);
    writer = jpeg;
  }
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = std::string("cannot write ") + (png ? "PNG" : "JPEG") + " '" + path + "'";
    return false;
  }
  return true;
}

bool WritePNG(const std::string& path,
  int width,
  int height,
  const float* rgba,
  const double background[3],
  std::string& error)
{
  return WriteImage8(path, Image8Format::PNG, width, height, rgba, background, error);
}
}
