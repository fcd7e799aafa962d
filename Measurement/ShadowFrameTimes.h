// Frame times of several passes on one renderer, measured in one process with
// interleaved rounds: shared by the benchmark (ShadowBench) and the speed
// benchmark (ShadowSpeed).
#ifndef ShadowFrameTimes_h
#define ShadowFrameTimes_h

#include <functional>
#include <vector>

class vtkRenderPass;
class vtkRenderWindow;
class vtkRenderer;

namespace shadowbench
{

/// One frame's wall time and its rendering thread's CPU time, in seconds, and
/// for this module's passes the map layers it rendered and their caster draws.
struct FrameTime
{
  double Wall = 0.0;
  double MainThreadCpu = 0.0;
  int Layers = -1;
  int CasterDraws = -1;
};

/// Seconds per frame.
struct Timing
{
  /// The first frame of a pass on the scene (its maps and shaders built).
  double First = 0.0;
  /// This module's passes: the first frame's milliseconds in each frame step
  /// (vtkAbstractShadowMapPass::GetFrameStepMilliseconds); empty otherwise.
  std::vector<double> FirstStepMilliseconds;
  /// Median of frames with nothing changed.
  double Steady = 0.0;
  /// Median of frames with the camera moved a little before each, rendered
  /// as an interactor renders a drag (MovingCameraRenders).
  double Moving = 0.0;
  /// Their mean: kept maps make most moving frames cheap and some dear.
  double MovingMean = 0.0;
  /// The CPU time of the rendering thread in steady and moving frames
  /// (medians): VTK's and the pass's work and the GL driver's on that thread,
  /// without the frames' rasterisation where the driver does it on threads of
  /// its own (llvmpipe) or on a GPU.
  double SteadyMainThreadCpu = 0.0;
  double MovingMainThreadCpu = 0.0;
  /// The same per round of MeasureFrameTimes, to compare passes within a
  /// round: the machine's speed drifts between rounds.
  std::vector<double> SteadyMainThreadCpuPerRound;
  std::vector<double> MovingMainThreadCpuPerRound;
  /// Every timed frame, round after round.
  std::vector<FrameTime> SteadyFrames;
  std::vector<FrameTime> MovingFrames;
};

/// Renders of a moving camera, while the object lives: `interactive`, as a
/// user's drag (the window's desired update rate at vtkRenderWindowInteractor's
/// default DesiredUpdateRate, 15, as vtkInteractorStyle sets it), else as a
/// scripted animation (at its StillUpdateRate, 0.0001); after, the rate it had.
class MovingCameraRenders
{
public:
  explicit MovingCameraRenders(vtkRenderWindow* window, bool interactive = true);
  ~MovingCameraRenders();
  MovingCameraRenders(const MovingCameraRenders&) = delete;
  MovingCameraRenders& operator=(const MovingCameraRenders&) = delete;

private:
  vtkRenderWindow* Window;
  double RateBefore;
};

/// Sets the camera for moving frame `frame` of `frames` (frame 0: the start).
using CameraMotion = std::function<void(int frame, int frames)>;

/// Renders and waits for the GL to finish.
FrameTime TimedRender(vtkRenderWindow* window);

/// The map layers and caster draws of `pass`'s last frame, if it is one of this
/// module's passes (else left as they are).
void ReadMapWork(vtkRenderPass* pass, int& layers, int& casterDraws);

/// The median (NaN for none).
double Median(std::vector<double> values);

/// Frame times of each pass (nullptr: no shadows), in three interleaved rounds
/// so that a slow patch of the machine affects all passes alike: per round and
/// pass a first frame at the start of the motion, two warm-up frames (switching
/// passes rebuilds the mappers' shaders), `frames` steady frames, then
/// `frames` moving frames (MovingCameraRenders, interactive when `interactiveMoving`).
/// Leaves the camera at the start of the motion.
std::vector<Timing> MeasureFrameTimes(vtkRenderWindow* window, vtkRenderer* renderer,
  const std::vector<vtkRenderPass*>& passes, int frames, const CameraMotion& motion,
  bool interactiveMoving = true);

} // namespace shadowbench

#endif
