// Statistical image test of the path tracer, after Mitsuba 3's image tests: a 256-spp render of
// the embedded Enzo set against a 4096-spp reference EXR holding the mean AND the variance of the
// mean per pixel and channel (Testing/Data/Reference/PathTracerEnzo.exr; README.md there).
// Both are batch means: K renders with distinct seeds (disjoint random streams) of m samples; the
// variance of the mean is the sample variance of the batch means / K (K - 1 degrees of freedom).
//
// H0: the render and the reference estimate the same image. Overall significance alpha = 0.01
// (the chance that an unbiased render fails), split evenly (Bonferroni) between two criteria:
// 1. Per pixel and channel, Welch's t-test, t = (mean_test - mean_ref) / sqrt(v_test + v_ref),
//    Welch-Satterthwaite dof, two-sided Student p; Sidak over the N = 64 x 64 x 4 tests: reject
//    when p < 1 - (1 - 0.005)^(1/N) = 3.1e-7. v_test is floored at the reference's per-sample
//    variance over the test's sample count (under H0 both draw the same per-sample distribution;
//    unfloored, a pixel whose test samples all missed a rare region has v_test = 0: the first
//    unbiased render was rejected so). Catches local errors (a bounce, the phase function, ...).
// 2. Per channel, the summed difference z = sum(mean_test - mean_ref) / sqrt(sum(v_test + v_ref))
//    (independent pixels, unbiased means: standard normal over ~900 non-empty pixels); Sidak over
//    the 4 channels at 0.005. Catches small global biases that no single pixel resolves.
// Pairs with both variances zero (background) pass only when the means agree. The test checks
// its power: a 5% denser medium, a 2% brighter image, a one-bounce path tracer must be rejected.
//
// `TestPathTracerStatistics --regenerate` rewrites the reference; `--calibrate N` renders N
// unbiased images with new seeds and counts rejections; on a failure the candidate and its
// p-values go to the folder after -T.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "RealData.h"

#include "AMRDualMeshImageIO.h"
#include "render/CpuRenderer.h"
#include "render/StatisticalImageTest.h"
#include "vtkAMRDualMesh.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
// --- The experiment (change any of it and regenerate the reference) --------------------------
constexpr int kSize = 64;                              // image width = height
constexpr int kRefBatches = 64, kRefSppPerBatch = 64;  // reference: 4096 spp
constexpr int kTestBatches = 32, kTestSppPerBatch = 8; // test: 256 spp
constexpr std::uint32_t kRefSeed = 1000000;            // seeds kRefSeed + batch
constexpr std::uint32_t kTestSeed = 1;                 // seeds kTestSeed + batch (< kRefSeed)
constexpr double kAlpha = 0.01;                        // overall; half per criterion
const char* const kReferenceName = "PathTracerEnzo";
std::string gTempDir; // -T: where a failing run writes its images

// Student's t, Sidak and the two criteria: Kernels/render/StatisticalImageTest.h (shared with
// amrdm-devcheck's CPU-against-CUDA comparison).
using amrdm::sidak;
using amrdm::studentTwoSidedP;

// --- Scene and batch-mean renders -----------------------------------------------------------
struct Scene
{
  vtkSmartPointer<vtkAMRDualMesh> field;
  amrdm::TransferFunction tf;
  amrdm::RenderParams params;
};

/// The Enzo set (log10 density, 8 levels), a blue-to-orange table with an opacity ramp, a
/// perspective camera seeing both blobs, a key light, a grey environment and forward
/// scattering: delta tracking, NEE with ratio tracking, phase sampling, roulette all contribute.
bool makeScene(Scene& scene)
{
  amrdm_test::RealSet enzo;
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
    if (set.name == "enzo-moving7")
      enzo = set;
  if (enzo.path.empty())
    return false;
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(enzo);
  scene.field = vtkSmartPointer<vtkAMRDualMesh>::New();
  scene.field->SetInputData(amr);
  scene.field->SetArrayName("Density");
  scene.field->SetLogScale(true);
  if (!amr || !scene.field->Update())
    return false;
  double b[6];
  amr->GetBounds(b);
  const glm::vec3 centre(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  const float radius = 0.5f * glm::length(glm::vec3(b[1] - b[0], b[3] - b[2], b[5] - b[4]));
  amrdm::TransferFunction& tf = scene.tf;
  tf.lo = -27.0f; // log10 density: background about -27.2, blobs -26 to -24.5, cores to -20.8
  tf.hi = -24.5f;
  tf.unitDistance = 0.03f;
  tf.table.resize(256);
  const glm::vec3 cold(0.35f, 0.55f, 0.95f), warm(1.0f, 0.6f, 0.2f);
  for (int i = 0; i < 256; ++i)
    tf.table[i] = glm::vec4(glm::mix(cold, warm, i / 255.0f), (i / 255.0f) * (i / 255.0f));
  amrdm::RenderParams& p = scene.params;
  p.width = p.height = kSize;
  p.camera.direction = glm::normalize(glm::vec3(1.0f, -1.0f, -0.3f));
  p.camera.position = centre - p.camera.direction * (2.6f * radius);
  p.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  p.camera.viewAngle = 30.0f;
  p.numLights = 1;
  p.lights[0].direction = glm::normalize(glm::vec3(-0.5f, -0.6f, 1.0f));
  p.lights[0].intensity = 6.0f;
  p.ambient = glm::vec3(0.25f);
  p.anisotropy = 0.3f;
  return true;
}

/// Per pixel and channel (RGBA, rows from the bottom): mean and variance of the mean, with the
/// degrees of freedom of that variance and the total samples.
struct Estimate : amrdm::ImageEstimate
{
  std::uint64_t majorantViolations = 0; ///< must stay 0
};

/// `batches` renders of `sppPerBatch` samples with seeds seed, seed + 1, ...; Welford's update
/// over the batch means.
Estimate renderBatchMeans(const Scene& scene,
  const amrdm::TransferFunction& tf,
  amrdm::RenderParams params,
  std::uint32_t seed,
  int batches,
  int sppPerBatch)
{
  amrdm::CpuRenderer renderer;
  renderer.setMesh(scene.field->GetDualMesh(), params.majorantResolution, params.threads);
  renderer.setTransferFunction(tf, params.threads);
  params.samplesPerPass = sppPerBatch;
  const std::size_t n = std::size_t(params.width) * params.height * 4;
  Estimate e;
  e.mean.assign(n, 0.0);
  std::vector<double> m2 = e.mean;
  for (int k = 0; k < batches; ++k)
  {
    renderer.reset();
    params.seed = seed + std::uint32_t(k);
    renderer.renderPass(params);
    e.majorantViolations += renderer.stats().majorantViolations;
    const std::vector<float> image = renderer.image();
    for (std::size_t i = 0; i < n; ++i)
    {
      const double delta = image[i] - e.mean[i];
      e.mean[i] += delta / (k + 1);
      m2[i] += delta * (image[i] - e.mean[i]);
    }
  }
  e.var = m2;
  for (double& v : e.var)
    v /= double(batches - 1) * batches;
  e.dof = batches - 1;
  e.spp = batches * sppPerBatch;
  return e;
}

// --- Reference EXR: R, G, B, A = mean; varR, varG, varB, varA = variance of the mean ---------
const char* const kChannels[8] = { "R", "G", "B", "A", "varR", "varG", "varB", "varA" };

/// One float slice per channel into `planes` (8 planes of kSize^2, rows from the bottom; EXR
/// rows run top-down, so each slice starts at the last row with a negative stride).
Imf::FrameBuffer frameBuffer(std::vector<float>& planes)
{
  const std::size_t n = std::size_t(kSize) * kSize;
  Imf::FrameBuffer frame;
  for (int c = 0; c < 8; ++c)
    frame.insert(kChannels[c],
      Imf::Slice(Imf::FLOAT,
        reinterpret_cast<char*>(&planes[c * n + std::size_t(kSize - 1) * kSize]),
        sizeof(float),
        -static_cast<std::ptrdiff_t>(sizeof(float) * kSize)));
  return frame;
}

/// Attributes `spp` and `batches` give the sample count and the degrees of freedom + 1.
void writeEstimate(const std::string& path, const Estimate& e)
{
  const std::size_t n = std::size_t(kSize) * kSize;
  std::vector<float> planes(8 * n);
  for (std::size_t i = 0; i < 4 * n; ++i)
  {
    planes[(i % 4) * n + i / 4] = float(e.mean[i]);
    planes[(4 + i % 4) * n + i / 4] = float(e.var[i]);
  }
  Imf::Header header(kSize, kSize);
  for (const char* name : kChannels)
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  header.insert("spp", Imf::IntAttribute(e.spp));
  header.insert("batches", Imf::IntAttribute(int(e.dof) + 1));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frameBuffer(planes));
  file.writePixels(kSize);
}

/// Reads an estimate written by writeEstimate; false (with a message) when it does not fit.
bool readEstimate(const std::string& path, Estimate& e)
{
  Imf::InputFile file(path.c_str());
  const Imath::Box2i box = file.header().dataWindow();
  const auto* spp = file.header().findTypedAttribute<Imf::IntAttribute>("spp");
  const auto* batches = file.header().findTypedAttribute<Imf::IntAttribute>("batches");
  bool ok = box.min.x == 0 && box.min.y == 0 && box.max.x + 1 == kSize && box.max.y + 1 == kSize &&
            spp && batches && batches->value() >= 2;
  for (const char* name : kChannels)
    ok = ok && file.header().channels().findChannel(name);
  if (!ok)
  {
    std::printf("%s: not a %dx%d estimate (channels R..A, varR..varA; attributes spp, batches)\n",
      path.c_str(),
      kSize,
      kSize);
    return false;
  }
  const std::size_t n = std::size_t(kSize) * kSize;
  std::vector<float> planes(8 * n, 0.0f);
  file.setFrameBuffer(frameBuffer(planes));
  file.readPixels(0, kSize - 1);
  e.mean.resize(4 * n);
  e.var.resize(4 * n);
  for (std::size_t i = 0; i < 4 * n; ++i)
  {
    e.mean[i] = planes[(i % 4) * n + i / 4];
    e.var[i] = planes[(4 + i % 4) * n + i / 4];
  }
  e.spp = spp->value();
  e.dof = batches->value() - 1;
  return true;
}

// --- The two criteria (StatisticalImageTest.h) -------------------------------------------------
struct Verdict : amrdm::ImageVerdict
{
  std::uint64_t majorantViolations = 0; ///< of the test render; must stay 0
};

Verdict compare(const Estimate& test, const Estimate& ref)
{
  Verdict v;
  static_cast<amrdm::ImageVerdict&>(v) = amrdm::compareImages(test, ref, kAlpha);
  return v;
}

void report(const std::string& what, const Estimate& test, const Estimate& ref, const Verdict& v)
{
  std::printf(
    "%s: %d spp (%d batches) vs reference %d spp (%d batches), alpha = %.3g overall\n"
    "  per pixel (Welch): %zu of %d pixels rejected (%zu of %zu pixel-channel tests; %zu empty), "
    "threshold p < %.3g (Sidak, %.3g over all tests), min p = %.3g, p < 0.01 in %.2f%% of the "
    "non-empty tests\n  image-wide (summed differences): z = %+.2f %+.2f %+.2f %+.2f (RGBA), "
    "p = %.2g %.2g %.2g %.2g, threshold p < %.3g: %d of 4 channels rejected -> %s\n",
    what.c_str(),
    test.spp,
    int(test.dof) + 1,
    ref.spp,
    int(ref.dof) + 1,
    kAlpha,
    v.rejectedPixels,
    kSize * kSize,
    v.rejectedTests,
    v.tests,
    v.empty,
    v.pixelThreshold,
    0.5 * kAlpha,
    v.minP,
    100.0 * v.below1Percent,
    v.imageZ[0],
    v.imageZ[1],
    v.imageZ[2],
    v.imageZ[3],
    v.imageP[0],
    v.imageP[1],
    v.imageP[2],
    v.imageP[3],
    v.imageThreshold,
    v.rejectedChannels,
    v.rejected() ? "REJECTED" : "accepted");
}

Scene* gScene = nullptr;
Estimate gReference;

/// A test render (seeds from `seed`), RGB optionally scaled by `brightness` (coverage is unchanged
/// by a brightness error), compared with the reference and reported.
Verdict check(const std::string& what,
  const amrdm::TransferFunction& tf,
  const amrdm::RenderParams& params,
  double brightness = 1.0,
  std::uint32_t seed = kTestSeed,
  Estimate* rendered = nullptr)
{
  const auto t0 = std::chrono::steady_clock::now();
  Estimate e = renderBatchMeans(*gScene, tf, params, seed, kTestBatches, kTestSppPerBatch);
  std::printf("rendered %d spp at %dx%d in %.2f s\n",
    e.spp,
    kSize,
    kSize,
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  for (std::size_t k = 0; k < e.mean.size(); ++k)
  {
    e.mean[k] *= k % 4 != 3 ? brightness : 1.0;
    e.var[k] *= k % 4 != 3 ? brightness * brightness : 1.0;
  }
  Verdict v = compare(e, gReference);
  v.majorantViolations = e.majorantViolations;
  report(what, e, gReference, v);
  if (rendered)
    *rendered = std::move(e);
  return v;
}
} // namespace

TEST_CASE("Student's t p-values match closed forms")
{
  // dof 1 is Cauchy: p = 1 - 2 atan(t) / pi; dof 2: p = 1 - t / sqrt(2 + t^2); large dof: normal.
  for (double t : { 0.1, 1.0, 3.0, 30.0, 3000.0 })
  {
    const double cauchy = 1.0 - 2.0 / M_PI * std::atan(t), dof2 = 1.0 - t / std::sqrt(2.0 + t * t);
    CHECK(studentTwoSidedP(t, 1.0) == doctest::Approx(cauchy).epsilon(1e-9));
    CHECK(studentTwoSidedP(t, 2.0) == doctest::Approx(dof2).epsilon(1e-9));
  }
  for (double t : { 0.5, 2.0, 5.0, 8.0 })
    CHECK(studentTwoSidedP(t, 1e7) == doctest::Approx(std::erfc(t / std::sqrt(2.0))).epsilon(1e-5));
  CHECK(studentTwoSidedP(0.0, 5.0) == doctest::Approx(1.0));
  CHECK(sidak(0.01, 1.0) == doctest::Approx(0.01));
}

TEST_CASE("an unbiased 256-spp render is accepted")
{
  Estimate e;
  const Verdict v = check("unbiased path tracer", gScene->tf, gScene->params, 1.0, kTestSeed, &e);
  if (v.rejected() && !gTempDir.empty())
  {
    // Mitsuba's error_output: the candidate with its per-pixel p-values in varR..varA.
    e.var.assign(v.p.begin(), v.p.end());
    writeEstimate(gTempDir + "/PathTracerEnzo-unbiased.exr", e);
    std::printf("wrote %s/PathTracerEnzo-unbiased.exr (varR..varA = p-values)\n", gTempDir.c_str());
  }
  CHECK(v.majorantViolations == 0);
  CHECK(v.rejectedPixels == 0);
  CHECK(v.rejectedChannels == 0);
}

TEST_CASE("biased renders are rejected (the test's power)")
{
  const Scene& scene = *gScene;
  amrdm::TransferFunction denser = scene.tf;
  denser.unitDistance /= 1.05f; // extinction x 1.05
  const Verdict dense = check("density x 1.05 (must be REJECTED)", denser, scene.params);
  CHECK(dense.rejected());
  CHECK(check("brightness x 1.02 (must be REJECTED)", scene.tf, scene.params, 1.02).rejected());
  amrdm::RenderParams oneBounce = scene.params;
  oneBounce.maxBounces = 1; // multiple scattering dropped: a local error, caught per pixel
  const Verdict local = check("one bounce (must be REJECTED per pixel)", scene.tf, oneBounce);
  CHECK(local.rejectedPixels > 0);
  CHECK(dense.majorantViolations + local.majorantViolations == 0);
}

int main(int argc, char** argv)
{
  // Testing/Data: $AMRDM_TEST_DATA (ctest sets it), else the source folder of this build.
  setenv("AMRDM_TEST_DATA", AMRDM_STAT_TEST_DATA, 0); // RealData.h reads it too
  const std::string dir = std::string(std::getenv("AMRDM_TEST_DATA")) + "/Reference/";
  bool regenerate = false;
  int calibrate = 0;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--regenerate")
      regenerate = true;
    else if (a == "--calibrate" && i + 1 < argc)
      calibrate = std::max(1, std::atoi(argv[++i]));
    else if (a == "-T" && i + 1 < argc)
      gTempDir = argv[++i];
    else
      rest.push_back(argv[i]); // doctest's own options
  }
  Scene scene;
  if (!makeScene(scene))
  {
    std::printf("SKIP: the Enzo set (Testing/Data/enzo-moving7_DD0010) is missing or unreadable\n");
    return 125;
  }
  gScene = &scene;
  const std::string path = dir + kReferenceName + ".exr";
  if (regenerate)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const Estimate ref =
      renderBatchMeans(scene, scene.tf, scene.params, kRefSeed, kRefBatches, kRefSppPerBatch);
    if (ref.majorantViolations != 0)
    {
      std::printf("FAIL: majorant violations; no reference written\n");
      return 1;
    }
    writeEstimate(path, ref);
    const std::vector<float> rgba(ref.mean.begin(), ref.mean.end());
    const double black[3] = { 0.0, 0.0, 0.0 };
    std::string error, png = dir + kReferenceName + ".png";
    if (!amrdm_vtk::WritePNG(png, kSize, kSize, rgba.data(), black, error))
      std::printf("%s\n", error.c_str());
    std::printf("wrote %s (%d spp in %d batches, %.1f s) and the preview %s\n",
      path.c_str(),
      ref.spp,
      kRefBatches,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
      png.c_str());
    return 0;
  }
  bool ok = false;
  try
  {
    ok = readEstimate(path, gReference);
  }
  catch (const std::exception& e) // OpenEXR throws on a missing or broken file
  {
    std::printf("cannot read %s: %s\n", path.c_str(), e.what());
  }
  if (!ok)
  {
    std::printf("FAIL: no usable reference; make it with `%s --regenerate`\n", argv[0]);
    return 1;
  }
  if (calibrate > 0)
  {
    int rejected = 0; // the empirical false-rejection rate: unbiased renders, fresh seeds
    for (std::uint32_t seed = kTestSeed + 1000; seed <= kTestSeed + 1000u * calibrate; seed += 1000)
      rejected +=
        check("calibration, seeds from " + std::to_string(seed), scene.tf, scene.params, 1.0, seed)
          .rejected();
    std::printf("calibration: %d of %d unbiased renders rejected (alpha = %.3g)\n",
      rejected,
      calibrate,
      kAlpha);
    return 0;
  }
  doctest::Context context(int(rest.size()), rest.data());
  return context.run();
}
