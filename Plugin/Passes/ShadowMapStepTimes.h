// Where one frame's shadow work went: milliseconds of the thread that renders,
// per step of FrameUpdate, in the order they run. A driver that defers GL work
// to a GPU leaves most of the drawing out of it; llvmpipe shades the casters'
// vertices on this thread, so there the drawing shows. Not a VTK class.
#ifndef ShadowMapStepTimes_h
#define ShadowMapStepTimes_h

#include <array>
#include <chrono>
#include <cstddef>

namespace shadowmaps
{
enum class FrameStep : int
{
  /// The lights, the casters and the camera collected.
  Reading,
  /// The lights' views fitted.
  Fitting,
  /// The storage chosen (the casters' closedness analysed) and the maps reserved.
  Storage,
  /// The receivers' shadow code made.
  Shaders,
  /// The layers that changed drawn.
  Drawing,
  /// The maps combined across processes and post-processed (blurs, mipmaps).
  Finishing,
  Count
};

class StepTimes
{
public:
  void Clear() { this->Milliseconds.fill(0.0); }
  double Get(FrameStep step) const { return this->Milliseconds[Index(step)]; }
  /// Adds another's times, step by step.
  void Add(const StepTimes& other)
  {
    for (std::size_t i = 0; i < this->Milliseconds.size(); ++i)
    {
      this->Milliseconds[i] += other.Milliseconds[i];
    }
  }

  /// Adds the time from its making to its end to `step`.
  class Scope
  {
  public:
    Scope(StepTimes& times, FrameStep step)
      : Times(times)
      , Step(step)
      , Start(std::chrono::steady_clock::now())
    {
    }
    ~Scope()
    {
      const std::chrono::duration<double, std::milli> spent =
        std::chrono::steady_clock::now() - this->Start;
      this->Times.Milliseconds[Index(this->Step)] += spent.count();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    StepTimes& Times;
    FrameStep Step;
    std::chrono::steady_clock::time_point Start;
  };

private:
  static std::size_t Index(FrameStep step) { return static_cast<std::size_t>(step); }

  std::array<double, static_cast<std::size_t>(FrameStep::Count)> Milliseconds{};
};
} // namespace shadowmaps

#endif
