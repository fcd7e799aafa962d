// Helpers for the image tests: a small test scene, capture, strict comparison
// against committed baselines (OpenImageIO) and world-space probes.
#ifndef ShadowTestUtilities_h
#define ShadowTestUtilities_h

#include "ShadowTechniques.h" // For ErrorCounter
#include "vtkNew.h"
#include "vtkRenderWindow.h" // For TestScene members
#include "vtkRenderer.h"     // For TestScene members
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

#include <glm/glm.hpp>

class vtkActor;
class vtkAlgorithm;
class vtkImageData;
class vtkLight;
class vtkSphereSource;

namespace shadowtest
{

/// A window, one renderer and the standard test scene: a 20 x 20 ground at
/// z = 0, a unit sphere floating at (0, 0, 1.5) and a 1.5 box on the ground at
/// (4, 2). Ambient 0.15 keeps shadowed areas dark but not black.
struct TestScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Ground;
  vtkSmartPointer<vtkActor> Sphere;
  vtkSmartPointer<vtkActor> Box;
  vtkSmartPointer<vtkSphereSource> SphereSource;

  explicit TestScene(int width = 400, int height = 300);
  /// Replaces all lights by one light and turns automatic lights off.
  vtkLight* SetSun(const glm::dvec3& directionToScene);
  vtkLight* SetSpot(const glm::dvec3& position, double coneAngle);
  vtkLight* SetPoint(const glm::dvec3& position);
};

/// Where the sphere's centre casts its shadow on the ground for a light
/// travelling along `direction`, or from `position` (positional lights).
glm::dvec3 GroundShadowOfSphereCenter(const glm::dvec3& direction);
glm::dvec3 GroundShadowOfSphereCenterFrom(const glm::dvec3& lightPosition);

/// An actor drawing `source`'s output with a vtkPolyDataMapper, added to `renderer`.
vtkSmartPointer<vtkActor> AddSourceActor(vtkRenderer* renderer, vtkAlgorithm* source);

/// Renders and returns the frame as RGB.
vtkSmartPointer<vtkImageData> RenderAndCapture(vtkRenderWindow* window);

/// The RGB bytes of a captured frame, to compare frames byte for byte.
std::vector<unsigned char> RgbBytes(vtkImageData* image);

/// The frame last rendered, as RGB, without rendering again.
vtkSmartPointer<vtkImageData> CaptureAsRendered(vtkRenderWindow* window);

/// Mean luminance (0-255) of a 3 x 3 block around the pixel where `world` is seen.
double LuminanceAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world);

/// Least luminance (0-255) of a 7 x 7 block around the pixel where `world` is
/// seen: a lit surface with acne shows its dark texels there.
double DarkestAround(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world);

/// RGB of the pixel where `world` is seen; -1 components when off the image.
glm::ivec3 ColorAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world);

/// Pixels a TEXEL_DENSITY analysis frame marks undersampled (full red).
int CountUndersampled(vtkImageData* image);

/// Writes `image` to the test output folder as <name>.png and compares it
/// strictly with Testing/Data/Baseline/<name>.png. Returns an empty string on a
/// match, else what differed. With SHADOWMAPS_UPDATE_BASELINES=1 in the
/// environment it writes the baseline instead (and says so in the result).
std::string CompareWithBaseline(vtkImageData* image, const std::string& name);

/// Counts VTK errors and warnings (shader compile failures arrive as errors).
using ErrorCounter = shadowbench::MessageLog;

constexpr double ShadowedBelow = 80.0;
constexpr double LitAbove = 120.0;

} // namespace shadowtest

#endif
