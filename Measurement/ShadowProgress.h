// Progress through a long measurement, with the time left estimated from the
// time the work done so far took (vtkshadows bench and analyze).
#ifndef ShadowProgress_h
#define ShadowProgress_h

#include <chrono>
#include <string>

namespace shadowbench
{

/// "[40%, 0:48 so far, about 1:12 left]" for `done` of `total` units of work
/// after `elapsedSeconds` (no estimate before any work is done).
std::string ProgressLine(double done, double total, double elapsedSeconds);

/// Work in units of roughly equal cost (frames rendered, say), timed from
/// construction.
class Progress
{
public:
  explicit Progress(double total);
  /// `units` more are done.
  void Advance(double units);
  /// ProgressLine now.
  std::string Line() const;

private:
  double Total;
  double Done = 0.0;
  std::chrono::steady_clock::time_point Start;
};

} // namespace shadowbench

#endif
