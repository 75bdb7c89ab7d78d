// amrdm-devcheck's command line (see DevCheckOptions.h).
#include "DevCheckOptions.h"

#include <cstdlib>

namespace amrdm_devcheck
{
namespace
{
bool number(const char* text, double lo, double hi, double& out)
{
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end && *end == '\0' && end != text && out >= lo && out <= hi;
}
} // namespace

std::string devCheckUsage()
{
  return "usage: amrdm-devcheck [options] SCENE.amrdmscene...\n"
         "  --device cuda|cpu|auto  renderer checked against the CPU reference (default cuda)\n"
         "  --json FILE             write the JSON summary there\n"
         "  --compare-size N        agreement image edge (default 128)\n"
         "  --batches K             independent batches per estimate, >= 2 (default 16)\n"
         "  --batch-spp M           samples per pixel per batch (default 8)\n"
         "  --alpha A               false-failure chance of the whole run (default 0.01)\n"
         "  --fps-size N            frames-per-second image edge (default 1024)\n"
         "  --fps-frames N          frames; FPS = mean of frames 11..N (default 510)\n"
         "  --fps-seconds S         wall-time cap of one FPS run (default 60)\n"
         "  --threads N             CPU threads (default all cores)\n"
         "  --require-power         fail when the comparison cannot reject a 1.5x denser medium\n"
         "                          on the device (reported either way)\n"
         "Exit status: 0 when every check passed, 1 on any failure.\n"
         "Below about 6 batches x 4 spp a silhouette pixel can have zero sample variance in both\n"
         "renders with different means, which the test must reject: keep the defaults on a GPU.\n";
}

bool parseDevCheckOptions(int argc, char* argv[], DevCheckOptions& o, std::string& error)
{
  struct IntOption
  {
    const char* name;
    int* value;
    int lo, hi;
  };
  const IntOption ints[] = { { "--compare-size", &o.compareSize, 1, 4096 },
    { "--batches", &o.batches, 2, 100000 },
    { "--batch-spp", &o.batchSpp, 1, 4096 },
    { "--fps-size", &o.fpsSize, 1, 16384 },
    { "--fps-frames", &o.fpsFrames, 1, 1000000 },
    { "--threads", &o.threads, 0, 4096 } };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    bool matched = false;
    for (const IntOption& opt : ints)
    {
      if (a != opt.name)
        continue;
      double v = 0.0;
      if (!hasValue || !number(argv[i + 1], opt.lo, opt.hi, v) || v != double(int(v)))
      {
        error =
          a + " expects an integer in " + std::to_string(opt.lo) + ".." + std::to_string(opt.hi);
        return false;
      }
      *opt.value = int(v);
      ++i;
      matched = true;
    }
    if (matched)
      continue;
    if (a == "--device")
    {
      if (!hasValue || !amrdm::parseRenderDevice(argv[i + 1], o.device))
      {
        error = "--device expects cuda, cpu or auto";
        return false;
      }
      ++i;
    }
    else if (a == "--json" && hasValue)
      o.json = argv[++i];
    else if (a == "--alpha" || a == "--fps-seconds")
    {
      double v = 0.0;
      const bool alpha = a == "--alpha";
      if (!hasValue || !number(argv[i + 1], alpha ? 1e-12 : 1e-3, alpha ? 0.5 : 1e6, v))
      {
        error = a + (alpha ? " expects a number in (0, 0.5]" : " expects seconds > 0");
        return false;
      }
      (alpha ? o.alpha : o.fpsSeconds) = v;
      ++i;
    }
    else if (a == "--require-power")
      o.requirePower = true;
    else if (a == "--help" || a == "-h")
      o.help = true;
    else if (!a.empty() && a[0] == '-')
    {
      error = "unknown option " + a + (hasValue ? "" : " (or its value is missing)");
      return false;
    }
    else
      o.scenes.push_back(a);
  }
  if (o.scenes.empty() && !o.help)
  {
    error = "no scene files given; expected one or more .amrdmscene files";
    return false;
  }
  return true;
}

} // namespace amrdm_devcheck
