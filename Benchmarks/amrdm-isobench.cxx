// amrdm-isobench: the first isosurface hit of a grid of parallel rays through our exact
// isosurface search (transport/Isosurface.h, findIsoHit on the dual mesh), for the accuracy
// benchmark (Benchmarks/iso_accuracy.py scores the hits against the analytic surface and
// against ParaView's Contour along the same rays). Never a ctest timing: only hit points.
//
//   amrdm-isobench FILE.vthb --array f --iso 0.2,0.5 --rays 256 --dir 1,0.7,0.45
//                  --centre 0.5,0.5,0.5 --radius 0.45 --out hits.bin
//
// Rays: an N x N orthographic grid on the plane through `centre` perpendicular to `dir`, side
// 2 * radius, each ray clipped to the data's bounds. Output: per iso value, per ray, 13 float64
// (iso, origin xyz, unit direction xyz, hit 0/1, t, hit point xyz, our interpolant at the hit),
// world coordinates; the direction and origin are the same for every iso value.
#include "AMRFileReader.h"

#include "render/RenderScene.h"
#include "transport/Isosurface.h"

#include "vtkAMRDualMesh.h"
#include "vtkOverlappingAMR.h"
#include "vtkSmartPointer.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

namespace
{

bool parseList(const std::string& text, std::vector<double>& out)
{
  out.clear();
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    try
    {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size())
        return false;
    }
    catch (const std::exception&)
    {
      return false;
    }
  }
  return !out.empty();
}

bool parseVec3(const std::string& text, glm::dvec3& out)
{
  std::vector<double> v;
  if (!parseList(text, v) || v.size() != 3)
    return false;
  out = glm::dvec3(v[0], v[1], v[2]);
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{ "First isosurface hits of a ray grid through the exact dual-mesh isosurface" };
  std::string file, array = "f", isoText, dirText = "1,0.7,0.45", centreText = "0.5,0.5,0.5";
  std::string outPath;
  int rays = 256;
  double radius = 0.45;
  app.add_option("file", file, "AMR file (.vthb, Enzo, AMReX)")->required();
  app.add_option("--array", array, "cell or point array");
  app.add_option("--iso", isoText, "iso values, comma separated")->required();
  app.add_option("--rays", rays, "rays per side of the grid")->check(CLI::Range(1, 4096));
  app.add_option("--dir", dirText, "ray direction x,y,z");
  app.add_option("--centre", centreText, "centre of the ray grid x,y,z (world)");
  app.add_option("--radius", radius, "half the side of the ray grid (world)")
    ->check(CLI::PositiveNumber);
  app.add_option("--out", outPath, "output file (float64 records)")->required();
  long trace = -1;
  app.add_option("--trace",
    trace,
    "also print, for this ray (index j * rays + i) and each iso value, every sign change of "
    "interpolant - iso sampled at 1/64 of the finest cell along it, next to the hit found");
  CLI11_PARSE(app, argc, argv);

  std::vector<double> isoValues;
  glm::dvec3 dir, centre;
  if (!parseList(isoText, isoValues))
  {
    std::cerr << "amrdm-isobench: --iso '" << isoText
              << "': expected numbers separated by commas\n";
    return 1;
  }
  if (!parseVec3(dirText, dir) || glm::length(dir) == 0.0)
  {
    std::cerr << "amrdm-isobench: --dir '" << dirText << "': expected a nonzero x,y,z\n";
    return 1;
  }
  if (!parseVec3(centreText, centre))
  {
    std::cerr << "amrdm-isobench: --centre '" << centreText << "': expected x,y,z\n";
    return 1;
  }
  std::string error;
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_app::ReadAMRFile(file, error);
  if (!amr)
  {
    std::cerr << "amrdm-isobench: " << error << "\n";
    return 1;
  }
  auto field = vtkSmartPointer<vtkAMRDualMesh>::New();
  field->SetInputData(amr);
  field->SetArrayName(array.c_str());
  if (!field->Update() || !field->GetDualMesh())
  {
    std::cerr << "amrdm-isobench: cannot build the dual mesh of array '" << array << "' of " << file
              << "\n";
    return 1;
  }
  const amrdm::DualMesh& mesh = *field->GetDualMesh();
  const double* range = field->GetValueRange();

  // Opaque grey ramp: nothing is culled, the majorant grid holds the per-macrocell value ranges.
  amrdm::TransferFunction tf;
  tf.lo = float(range[0]);
  tf.hi = float(range[1]) > tf.lo ? float(range[1]) : tf.lo + 1.0f;
  tf.table.assign(256, glm::vec4(1.0f));
  amrdm::RenderScene scene;
  scene.setMesh(&mesh, glm::ivec3(0), 1);
  scene.setTransferFunction(tf, 1);
  amrdm::RenderParams params;
  params.cullInvisiblePrimitives = false;
  params = scene.resolve(params);
  const amrdm::DualMeshMedium medium = scene.medium(params);
  const amrdm::MajorantGridView grid = scene.majorantGrid().view();

  double b[6];
  amr->GetBounds(b);
  const glm::dvec3 origin = mesh.sceneOrigin;
  const glm::vec3 lo(glm::dvec3(b[0], b[2], b[4]) - origin);
  const glm::vec3 hi(glm::dvec3(b[1], b[3], b[5]) - origin);
  const glm::dvec3 w = glm::normalize(dir);
  const glm::dvec3 helper = std::abs(w.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(w, helper)), v = glm::cross(u, w);

  std::ofstream out(outPath, std::ios::binary);
  if (!out)
  {
    std::cerr << "amrdm-isobench: cannot write " << outPath << "\n";
    return 1;
  }
  long hits = 0, records = 0;
  for (const double isoValue : isoValues)
  {
    const float iso = float(isoValue);
    for (int j = 0; j < rays; ++j)
      for (int i = 0; i < rays; ++i)
      {
        const double x = (2.0 * (i + 0.5) / rays - 1.0) * radius;
        const double y = (2.0 * (j + 0.5) / rays - 1.0) * radius;
        const glm::dvec3 o = centre + x * u + y * v - 4.0 * radius * w;
        amrdm::Ray ray;
        ray.o = glm::vec3(o - origin);
        ray.d = glm::vec3(w);
        float t0 = 0.0f, t1 = amrdm::kInfinity;
        amrdm::IsoHit hit;
        amrdm::TraceCounters counters;
        if (amrdm::clipRayToBox(ray, lo, hi, t0, t1))
          hit = amrdm::findIsoHit(medium, grid, ray, t0, t1, &iso, 1, 1.0f, counters);
        const glm::dvec3 p = glm::dvec3(ray.at(hit.hit() ? hit.t : 0.0f)) + origin;
        float f = NAN;
        if (hit.hit() && !medium.value(ray.at(hit.t), f, counters))
          f = NAN;
        if (long(j) * rays + i == trace)
        {
          const float dt =
            float(std::min({ mesh.finestSpacing.x, mesh.finestSpacing.y, mesh.finestSpacing.z })) /
            64.0f;
          float prev = NAN;
          std::printf("ray %ld iso %g: t in [%g, %g], hit %s t = %.7g\n",
            trace,
            isoValue,
            t0,
            t1,
            hit.hit() ? "yes" : "no",
            hit.hit() ? hit.t : 0.0f);
          for (float s = t0; s <= t1; s += dt)
          {
            float fs = NAN;
            if (!medium.value(ray.at(s), fs, counters))
              continue;
            if (!std::isnan(prev) && ((prev - iso) > 0.0f) != ((fs - iso) > 0.0f))
            {
              amrdm::SampleHit where;
              float fw = 0.0f;
              amrdm::sampleField(
                mesh.view(), medium.toGrid(ray.at(s)), amrdm::ElementTestParams(), fw, &where);
              const bool gridlet =
                where.prim != ~0u && amrdm::primType(where.prim) == amrdm::PrimGridlet;
              std::printf("  sign change of f - iso in [%.7g, %.7g]: %g -> %g (%s)\n",
                s - dt,
                s,
                prev,
                fs,
                gridlet ? "gridlet" : "element");
            }
            prev = fs;
          }
          amrdm::MajorantGridView noRanges = grid;
          noRanges.range = nullptr; // every macrocell searched
          const amrdm::IsoHit all =
            amrdm::findIsoHit(medium, noRanges, ray, t0, t1, &iso, 1, 1.0f, counters);
          std::printf("  without the macrocell ranges: hit %s t = %.7g\n",
            all.hit() ? "yes" : "no",
            all.hit() ? all.t : 0.0f);
        }
        const glm::dvec3 o2 = glm::dvec3(ray.o) + origin; // what was traced
        const double rec[13] = { isoValue,
          o2.x,
          o2.y,
          o2.z,
          w.x,
          w.y,
          w.z,
          hit.hit() ? 1.0 : 0.0,
          hit.hit() ? double(hit.t) : 0.0,
          p.x,
          p.y,
          p.z,
          double(f) };
        out.write(reinterpret_cast<const char*>(rec), sizeof(rec));
        hits += hit.hit();
        ++records;
      }
  }
  if (!out)
  {
    std::cerr << "amrdm-isobench: writing " << outPath << " failed\n";
    return 1;
  }
  std::printf("%s: %zu iso values x %d^2 rays, %ld hits -> %s\n",
    file.c_str(),
    isoValues.size(),
    rays,
    hits,
    outPath.c_str());
  return records > 0 ? 0 : 1;
}
