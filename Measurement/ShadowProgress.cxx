#include "ShadowProgress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowbench
{
namespace
{
std::string MinutesAndSeconds(double seconds)
{
  const long whole = std::lround(std::max(seconds, 0.0));
  char text[32];
  std::snprintf(text, sizeof(text), "%ld:%02ld", whole / 60, whole % 60);
  return text;
}
} // namespace

std::string ProgressLine(double done, double total, double elapsedSeconds)
{
  const double fraction = total > 0.0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
  std::string line = "[" + std::to_string(static_cast<int>(std::floor(100.0 * fraction))) + "%, " +
    MinutesAndSeconds(elapsedSeconds) + " so far";
  if (fraction > 0.0 && fraction < 1.0)
  {
    line += ", about " + MinutesAndSeconds(elapsedSeconds * (1.0 - fraction) / fraction) + " left";
  }
  return line + "]";
}

Progress::Progress(double total)
  : Total(total)
  , Start(std::chrono::steady_clock::now())
{
}

void Progress::Advance(double units)
{
  this->Done += units;
}

std::string Progress::Line() const
{
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  return ProgressLine(this->Done, this->Total, elapsed);
}

} // namespace shadowbench
