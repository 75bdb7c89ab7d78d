// Progress of amrdm-render's frames on stderr: one line rewritten with '\r' on a terminal, and
// whole lines every 5 % (at most 21 lines) when stderr is a file or a pipe.
#ifndef FrameProgress_h
#define FrameProgress_h

#include <cstdio>

namespace amrdm_app
{
class FrameProgress
{
public:
  /// `interactive`: stderr is a terminal (isatty(2)).
  FrameProgress(int totalFrames, bool interactive, std::FILE* out = stderr);
  /// Frame `done` (1-based) took `ms` milliseconds.
  void Frame(int done, double ms);
  /// Ends the '\r' line on a terminal.
  void Finish();

private:
  int Total;
  bool Interactive;
  std::FILE* Out;
  int NextPercent = 5; ///< next line when not interactive
  double ElapsedMs = 0.0;
};
}

#endif
