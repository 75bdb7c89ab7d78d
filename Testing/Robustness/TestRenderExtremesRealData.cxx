// Rays exactly along dual-cell faces, edges and vertices of a real AMR set (the Enzo set: 8
// levels, stitching elements at every level transition; the kernel-only twin on a synthetic
// hierarchy is TestRenderExtremes). Parallel cameras along each axis put every pixel centre on a
// multiple of half a cell of some level, i.e. on the dual-cell faces (cell centres) of that level
// and all coarser ones; the ray-marched image must match the one of a camera shifted off the
// faces, pixel by pixel: a ray that slipped between primitives would lose its opacity.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RealData.h"

#include "AMRDualMeshVTKCompat.h"
#include "vtkAMRDualMesh.h"
#include "vtkImageData.h"

#include "render/CpuRenderer.h"

#include <chrono>
#include <cmath>

TEST_CASE("face-aligned rays on the Enzo set: no pinholes, no NaN")
{
  const amrdm_test::RealSet set = amrdm_test::realSets()[0];
  REQUIRE(!set.path.empty()); // shipped in Testing/Data (AMRDM_TEST_DATA)
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
  REQUIRE(amr);
  vtkNew<vtkAMRDualMesh> field;
  field->SetInputData(amr);
  field->SetArrayName(set.array.c_str());
  field->SetLogScale(true);
  REQUIRE(field->Update());
  const amrdm::DualMesh& mesh = *field->GetDualMesh();
  MESSAGE(set.name, ": ", mesh.counts.toJson());
  REQUIRE(mesh.counts.totalElements() > 0);
  // The windows below rely on exact dyadic coordinates: origin 0, spacings powers of two.
  REQUIRE(mesh.origin == glm::dvec3(0.0));
  const int finest = int(amrdm_vtk::amrcompat::NumberOfLevels(amr)) - 1;
  const double h = mesh.finestSpacing.x;
  REQUIRE(std::exp2(std::round(std::log2(h))) == h);

  // A ramp over the log-density range, opacity rising to 0.8.
  const double* range = field->GetValueRange();
  amrdm::TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.0f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.2f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.5f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.8f) };
  tf.lo = float(range[0]);
  tf.hi = float(range[1]);
  tf.unitDistance = 0.05f;
  amrdm::CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(tf);

  // Window centres: the finest block's centre (the deepest stitching), and the domain centre.
  double bounds[6];
  amrdm_vtk::amrcompat::Block(amr, finest, 0)->GetBounds(bounds);
  const glm::dvec3 deep(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  struct Window
  {
    glm::dvec3 centre;
    double pitch; ///< pixel pitch, world units: half a cell of some level
  };
  const Window windows[] = { { deep, 0.5 * h }, { deep, 4.0 * h }, { glm::dvec3(0.5), 64.0 * h } };
  constexpr int kSize = 64;
  const float shift = 1e-6f; // world: ~2e-3 finest cells, 16 float ulps at 0.5
  auto camera = [&](const Window& w, int axis, float offset)
  {
    amrdm::RenderParams p;
    p.width = p.height = kSize;
    p.pixelJitter = false;
    p.threads = 2;
    p.integrator = amrdm::IntegratorType::RayMarch;
    p.earlyTermination = 1.0f;
    p.stepSize = float(std::min(64.0 * h, 32.0 * w.pitch));
    p.camera.parallel = true;
    p.camera.parallelScale = float(0.5 * kSize * w.pitch);
    p.camera.direction = glm::vec3(0.0f);
    p.camera.direction[axis] = -1.0f;
    p.camera.up = glm::vec3(0.0f);
    p.camera.up[(axis + 2) % 3] = 1.0f;
    // Pixel (0, 0) on a multiple of the pitch: image right = axis + 1, image up = axis + 2.
    p.camera.position = glm::vec3(0.0f);
    p.camera.position[axis] = 2.0f;
    for (int a : { (axis + 1) % 3, (axis + 2) % 3 })
    {
      const double first = std::round(w.centre[a] / w.pitch - 0.5 * kSize) * w.pitch;
      p.camera.position[a] = float(first + (0.5 * kSize - 0.5) * w.pitch) + offset;
    }
    return p;
  };
  for (const Window& w : windows)
    for (int axis = 0; axis < 3; ++axis)
    {
      INFO("pitch ", w.pitch / h, " finest cells, axis ", axis);
      const amrdm::RenderParams p0 = camera(w, axis, 0.0f);
      const amrdm::Ray ray =
        amrdm::generateCameraRay(p0.camera, kSize, kSize, 0, 0, glm::vec2(0.5f));
      const double g = double(ray.o[(axis + 1) % 3]) / w.pitch;
      REQUIRE(g == std::round(g)); // exactly on a face plane
      const auto t0 = std::chrono::steady_clock::now();
      std::vector<float> images[3];
      const float offsets[3] = { 0.0f, shift, -shift };
      for (int k = 0; k < 3; ++k)
      {
        r.reset();
        REQUIRE(r.renderPass(camera(w, axis, offsets[k])));
        images[k] = r.image();
        CHECK(r.stats().majorantViolations == 0);
      }
      // Rays exactly on the data's outer boundary see it (the domain is closed), rays shifted
      // outward do not: a true edge, not a pinhole; those are compared separately.
      glm::vec3 lo, hi;
      mesh.gridBounds(lo, hi);
      lo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * lo;
      hi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * hi;
      float worst = 0.0f, boundary = 0.0f;
      double alpha = 0.0;
      for (int k = 1; k < 3; ++k)
        for (std::size_t i = 0; i < images[0].size(); ++i)
        {
          REQUIRE(std::isfinite(images[0][i]));
          REQUIRE(std::isfinite(images[k][i]));
          const amrdm::Ray pr = amrdm::generateCameraRay(
            p0.camera, kSize, kSize, int(i / 4) % kSize, int(i / 4) / kSize, glm::vec2(0.5f));
          bool onBoundary = false;
          for (int a : { (axis + 1) % 3, (axis + 2) % 3 })
            onBoundary = onBoundary || pr.o[a] == lo[a] || pr.o[a] == hi[a];
          float& into = onBoundary ? boundary : worst;
          into = std::max(into, std::fabs(images[0][i] - images[k][i]));
          alpha += (k == 1 && i % 4 == 3) ? images[0][i] : 0.0f;
        }
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      MESSAGE("pitch ",
        w.pitch / h,
        " finest cells, axis ",
        axis,
        ": mean alpha ",
        alpha / (kSize * kSize),
        ", largest difference to the shifted cameras ",
        worst,
        " (rays on the outer boundary: ",
        boundary,
        "; ",
        s,
        " s)");
      CHECK(alpha > 0.01 * kSize * kSize); // the window sees the data
      CHECK(worst <= 1e-3f);
    }
}
