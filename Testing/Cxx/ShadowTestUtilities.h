// Helpers for the image tests: a small test scene, capture, strict comparison
// against committed baselines (OpenImageIO) and world-space probes.
#ifndef ShadowTestUtilities_h
#define ShadowTestUtilities_h

#include "ShadowTechniques.h" // For ErrorCounter
#include "vtkNew.h"
#include "vtkRenderWindow.h" // For TestScene members
#include "vtkRenderer.h"     // For TestScene members
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

class vtkAbstractShadowMapPass;
class vtkActor;
class vtkAlgorithm;
class vtkImageData;
class vtkLight;
class vtkShaderProgram;
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

/// A box of `size` centred at `center`, added to `renderer`.
vtkSmartPointer<vtkActor> AddBox(vtkRenderer* renderer, const glm::dvec3& center, const glm::dvec3& size);

/// Orbits the camera 4 degrees a frame: seven frames drawn as a drag, then a still one.
void OrbitDraggedThenStill(TestScene& scene);

/// A new pass of a preset.
template <typename Pass>
vtkSmartPointer<vtkAbstractShadowMapPass> NewPass()
{
  return vtkSmartPointer<Pass>::New();
}

/// A pass made anew, by the name a test reports it under.
using PassKinds =
  std::vector<std::pair<std::string, std::function<vtkSmartPointer<vtkAbstractShadowMapPass>()>>>;

/// Every preset: uniform, warped and cascaded views of depth maps; dual depth
/// and moments in uniform views; and the automatic pass, the default.
PassKinds EveryPassKind();

/// Resident memory of this process in MiB (llvmpipe keeps textures there),
/// after the allocator gave back what it could.
double ResidentMiB();

/// Renders and returns the frame as RGB.
vtkSmartPointer<vtkImageData> RenderAndCapture(vtkRenderWindow* window);

/// The RGB bytes of a captured frame, to compare frames byte for byte.
std::vector<unsigned char> RgbBytes(vtkImageData* image);

/// The frame last rendered, as RGB, without rendering again.
vtkSmartPointer<vtkImageData> CaptureAsRendered(vtkRenderWindow* window);

/// The RGB bytes of the frame `fresh` renders in place of the renderer's pass,
/// which is then put back; `fresh` releases its graphics resources.
std::vector<unsigned char> FreshPassFrame(
  TestScene& scene, vtkSmartPointer<vtkAbstractShadowMapPass> fresh);

/// Renders `scene` with `pass`, applies `change` and renders once more.
/// Returns an empty string when that frame equals the one a fresh pass made by
/// `fresh` draws, else what differed, named by `what`.
std::string ChangeShownAsFresh(TestScene& scene, vtkAbstractShadowMapPass* pass,
  const std::function<void()>& change,
  const std::function<vtkSmartPointer<vtkAbstractShadowMapPass>()>& fresh, const std::string& what);

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
/// strictly with its baseline (BaselinePath). Returns an empty string on a
/// match, else what differed. With SHADOWMAPS_UPDATE_BASELINES=1 in the
/// environment it writes the baseline instead (and says so in the result): on
/// a VTK other than 9.1 only where the frame differs from 9.1's baseline.
std::string CompareWithBaseline(vtkImageData* image, const std::string& name);

/// Testing/Data/Baseline/<variant>/<name>.png where this VTK version keeps a
/// baseline of its own (it shades the frame differently from VTK 9.1), else
/// Testing/Data/Baseline/<name>.png.
std::string BaselinePath(const std::string& name);

/// Evaluates GLSL on the GPU: a fragment shader made of `functions` (the
/// module's shader files, their #defines and the uniforms they read) whose
/// main() sets `vec4 c` to case i and writes `expression` (a vec4 of c) for it.
/// `uniforms` sets the functions' other uniforms. Returns one vec4 per case; -1
/// everywhere when the shader does not compile.
std::vector<glm::vec4> EvaluateGLSL(const std::string& functions, const std::string& expression,
  const std::vector<glm::vec4>& cases,
  const std::function<void(vtkShaderProgram*)>& uniforms = nullptr);

/// The text of Shaders/<name>.glsl (SHADOWMAPS_SHADER_DIR).
std::string ShaderFile(const std::string& name);

/// Counts VTK errors and warnings (shader compile failures arrive as errors).
using ErrorCounter = shadowbench::MessageLog;

constexpr double ShadowedBelow = 80.0;
constexpr double LitAbove = 120.0;

} // namespace shadowtest

#endif
