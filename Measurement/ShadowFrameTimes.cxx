#include "ShadowFrameTimes.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderPass.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
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
double TimedRender(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  static_cast<vtkOpenGLRenderWindow*>(window)->WaitForCompletion();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

//------------------------------------------------------------------------------
std::vector<Timing> MeasureFrameTimes(vtkRenderWindow* window, vtkRenderer* renderer,
  const std::vector<vtkRenderPass*>& passes, int frames, const CameraMotion& motion,
  bool interactiveMoving)
{
  constexpr int Rounds = 3;
  constexpr int WarmUpFrames = 2;
  const int motionFrames = Rounds * frames + 1;
  std::vector<Timing> timing(passes.size());
  std::vector<std::vector<double>> steady(passes.size());
  std::vector<std::vector<double>> moving(passes.size());
  for (int round = 0; round < Rounds; ++round)
  {
    for (size_t p = 0; p < passes.size(); ++p)
    {
      renderer->SetPass(passes[p]);
      motion(0, motionFrames);
      const double first = TimedRender(window);
      if (round == 0)
      {
        timing[p].First = first;
      }
      for (int i = 0; i < WarmUpFrames; ++i)
      {
        TimedRender(window);
      }
      for (int i = 0; i < frames; ++i)
      {
        steady[p].push_back(TimedRender(window));
      }
      const MovingCameraRenders drag(window, interactiveMoving);
      for (int i = 0; i < frames; ++i)
      {
        motion(round * frames + i + 1, motionFrames);
        moving[p].push_back(TimedRender(window));
      }
    }
  }
  for (size_t p = 0; p < passes.size(); ++p)
  {
    timing[p].Steady = Median(steady[p]);
    timing[p].Moving = Median(moving[p]);
    timing[p].MovingMean = moving[p].empty()
      ? std::numeric_limits<double>::quiet_NaN()
      : std::accumulate(moving[p].begin(), moving[p].end(), 0.0) / moving[p].size();
  }
  motion(0, motionFrames);
  return timing;
}

} // namespace shadowbench
