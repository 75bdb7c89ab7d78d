#include "FrameProgress.h"

namespace amrdm_app
{
FrameProgress::FrameProgress(int totalFrames, bool interactive, std::FILE* out)
  : Total(totalFrames > 0 ? totalFrames : 1)
  , Interactive(interactive)
  , Out(out)
{
}

void FrameProgress::Frame(int done, double ms)
{
  this->ElapsedMs += ms;
  if (this->Interactive)
  {
    std::fprintf(this->Out, "\ramrdm-render: frame %d/%d (%.1f ms)", done, this->Total, ms);
    std::fflush(this->Out);
    return;
  }
  const int percent = int(100.0 * double(done) / double(this->Total));
  if (percent < this->NextPercent && done != this->Total)
    return;
  const double leftS = this->ElapsedMs / done * (this->Total - done) / 1e3;
  std::fprintf(this->Out,
    "amrdm-render: frame %d/%d (%d %%, %.1f ms per frame, %.1f s left)\n",
    done,
    this->Total,
    percent,
    this->ElapsedMs / done,
    leftS);
  std::fflush(this->Out);
  while (this->NextPercent <= percent)
    this->NextPercent += 5;
}

void FrameProgress::Finish()
{
  if (this->Interactive)
    std::fprintf(this->Out, "\n");
}
}
