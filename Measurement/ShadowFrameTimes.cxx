#include "ShadowFrameTimes.h"

#include <vtkAbstractShadowMapPass.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderPass.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>
#include <numeric>

namespace shadowbench
{

//------------------------------------------------------------------------------
MovingCameraRenders::MovingCameraRenders(vtkRenderWindow* window, bool interactive)
  : Window(window)
  , RateBefore(window->GetDesiredUpdateRate())
{
  this->Window->SetDesiredUpdateRate(interactive ? 15.0 : 0.0001);
}

//------------------------------------------------------------------------------
MovingCameraRenders::~MovingCameraRenders()
{
  this->Window->SetDesiredUpdateRate(this->RateBefore);
}

//------------------------------------------------------------------------------
namespace
{
double ThreadCpuSeconds()
{
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}
} // namespace

//------------------------------------------------------------------------------
FrameTime TimedRender(vtkRenderWindow* window)
{
  const double cpuStart = ThreadCpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  static_cast<vtkOpenGLRenderWindow*>(window)->WaitForCompletion();
  return { std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
    ThreadCpuSeconds() - cpuStart };
}

//------------------------------------------------------------------------------
void ReadMapWork(vtkRenderPass* pass, int& layers, int& casterDraws)
{
  if (auto* ours = vtkAbstractShadowMapPass::SafeDownCast(pass))
  {
    layers = ours->GetNumberOfRenderedLayers();
    // The pass's draw count is that of the last frame that rendered layers.
    casterDraws = layers > 0 ? ours->GetNumberOfCasterDraws() : 0;
  }
}

//------------------------------------------------------------------------------
double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

namespace
{
std::vector<double> Of(const std::vector<FrameTime>& frames, double FrameTime::*which)
{
  std::vector<double> values;
  values.reserve(frames.size());
  for (const FrameTime& frame : frames)
  {
    values.push_back(frame.*which);
  }
  return values;
}

/// The last frame's milliseconds in each of the pass's frame steps; empty for
/// a pass not of this module.
std::vector<double> FrameStepMilliseconds(vtkRenderPass* pass)
{
  std::vector<double> steps;
  if (auto* ours = vtkAbstractShadowMapPass::SafeDownCast(pass))
  {
    for (int step = 0; step < vtkAbstractShadowMapPass::NUMBER_OF_FRAME_STEPS; ++step)
    {
      steps.push_back(ours->GetFrameStepMilliseconds(step));
    }
  }
  return steps;
}

/// TimedRender's, with what one of this module's passes rendered into its maps.
FrameTime TimedPassRender(vtkRenderWindow* window, vtkRenderPass* pass)
{
  FrameTime time = TimedRender(window);
  ReadMapWork(pass, time.Layers, time.CasterDraws);
  return time;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<Timing> MeasureFrameTimes(vtkRenderWindow* window, vtkRenderer* renderer,
  const std::vector<vtkRenderPass*>& passes, int frames, const CameraMotion& motion,
  bool interactiveMoving)
{
  constexpr int Rounds = 3;
  constexpr int WarmUpFrames = 2;
  const int motionFrames = Rounds * frames + 1;
  std::vector<Timing> timing(passes.size());
  std::vector<std::vector<FrameTime>> steady(passes.size());
  std::vector<std::vector<FrameTime>> moving(passes.size());
  for (int round = 0; round < Rounds; ++round)
  {
    for (size_t p = 0; p < passes.size(); ++p)
    {
      renderer->SetPass(passes[p]);
      motion(0, motionFrames);
      const double first = TimedRender(window).Wall;
      if (round == 0)
      {
        timing[p].First = first;
        timing[p].FirstStepMilliseconds = FrameStepMilliseconds(passes[p]);
      }
      for (int i = 0; i < WarmUpFrames; ++i)
      {
        TimedRender(window);
      }
      std::vector<FrameTime> steadyRound;
      for (int i = 0; i < frames; ++i)
      {
        steadyRound.push_back(TimedPassRender(window, passes[p]));
      }
      std::vector<FrameTime> movingRound;
      {
        const MovingCameraRenders drag(window, interactiveMoving);
        for (int i = 0; i < frames; ++i)
        {
          motion(round * frames + i + 1, motionFrames);
          movingRound.push_back(TimedPassRender(window, passes[p]));
        }
      }
      timing[p].SteadyMainThreadCpuPerRound.push_back(
        Median(Of(steadyRound, &FrameTime::MainThreadCpu)));
      timing[p].MovingMainThreadCpuPerRound.push_back(
        Median(Of(movingRound, &FrameTime::MainThreadCpu)));
      steady[p].insert(steady[p].end(), steadyRound.begin(), steadyRound.end());
      moving[p].insert(moving[p].end(), movingRound.begin(), movingRound.end());
    }
  }
  for (size_t p = 0; p < passes.size(); ++p)
  {
    const std::vector<double> steadyWall = Of(steady[p], &FrameTime::Wall);
    const std::vector<double> movingWall = Of(moving[p], &FrameTime::Wall);
    timing[p].Steady = Median(steadyWall);
    timing[p].Moving = Median(movingWall);
    timing[p].MovingMean = movingWall.empty()
      ? std::numeric_limits<double>::quiet_NaN()
      : std::accumulate(movingWall.begin(), movingWall.end(), 0.0) / movingWall.size();
    timing[p].SteadyMainThreadCpu = Median(Of(steady[p], &FrameTime::MainThreadCpu));
    timing[p].MovingMainThreadCpu = Median(Of(moving[p], &FrameTime::MainThreadCpu));
    timing[p].SteadyFrames = steady[p];
    timing[p].MovingFrames = moving[p];
  }
  motion(0, motionFrames);
  return timing;
}

} // namespace shadowbench
