#include "ShadowTestUtilities.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkAutomaticShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "ShadowMapVTKCompat.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <numeric>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace shadowtest
{
namespace
{
constexpr double SphereRadius = 1.0;
const glm::dvec3 SphereCenter(0.0, 0.0, 1.5);

vtkSmartPointer<vtkActor> AddActor(vtkRenderer* renderer, vtkAlgorithm* source, const glm::dvec3& color)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color.x, color.y, color.z);
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(1.0);
  renderer->AddActor(actor);
  return actor;
}

vtkLight* ReplaceLights(vtkRenderer* renderer)
{
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  renderer->AddLight(light);
  return light;
}
} // namespace

//------------------------------------------------------------------------------
PassKinds EveryPassKind()
{
  return { { "uniform", NewPass<vtkDepthShadowMapPass> },
    { "warped", NewPass<vtkWarpedShadowMapPass> },
    { "cascaded", NewPass<vtkCascadedShadowMapPass> },
    { "dual depth", NewPass<vtkDualDepthShadowMapPass> },
    { "moments", NewPass<vtkVarianceShadowMapPass> },
    { "automatic", NewPass<vtkAutomaticShadowMapPass> } };
}

//------------------------------------------------------------------------------
double ResidentMiB()
{
  // Free heap pages at the top and inside glibc's arenas go back first: what
  // remains is what the process holds.
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  long pages = 0;
  long resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

TestScene::TestScene(int width, int height)
{
  this->Window->SetSize(width, height);
  this->Window->SetOffScreenRendering(1);
  this->Window->SetMultiSamples(0);
  this->Window->AddRenderer(this->Renderer);
  this->Renderer->SetBackground(0.2, 0.3, 0.4);

  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-10, -10, 0);
  ground->SetPoint1(10, -10, 0);
  ground->SetPoint2(-10, 10, 0);
  ground->SetResolution(20, 20);
  this->Ground = AddActor(this->Renderer, ground, { 0.9, 0.9, 0.9 });

  this->SphereSource = vtkSmartPointer<vtkSphereSource>::New();
  this->SphereSource->SetCenter(SphereCenter.x, SphereCenter.y, SphereCenter.z);
  this->SphereSource->SetRadius(SphereRadius);
  this->SphereSource->SetThetaResolution(48);
  this->SphereSource->SetPhiResolution(48);
  this->Sphere = AddActor(this->Renderer, this->SphereSource, { 1.0, 0.55, 0.3 });

  vtkNew<vtkCubeSource> box;
  box->SetCenter(4.0, 2.0, 0.75);
  box->SetXLength(1.5);
  box->SetYLength(1.5);
  box->SetZLength(1.5);
  this->Box = AddActor(this->Renderer, box, { 0.4, 0.7, 1.0 });

  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetPosition(0.0, -16.0, 10.0);
  camera->SetFocalPoint(0.0, 0.0, 0.5);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(35.0);
  this->Renderer->ResetCameraClippingRange();
}

void OrbitDraggedThenStill(TestScene& scene)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  for (int i = 0; i < 8; ++i)
  {
    scene.Window->SetDesiredUpdateRate(i < 7 ? 15.0 : 0.0001);
    camera->Azimuth(4.0);
    scene.Renderer->ResetCameraClippingRange();
    scene.Window->Render();
  }
}

vtkLight* TestScene::SetSun(const glm::dvec3& d)
{
  vtkLight* light = ReplaceLights(this->Renderer);
  light->SetPositional(false);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetPosition(-d.x, -d.y, -d.z);
  return light;
}

vtkLight* TestScene::SetSpot(const glm::dvec3& position, double coneAngle)
{
  vtkLight* light = ReplaceLights(this->Renderer);
  light->SetPositional(true);
  light->SetPosition(position.x, position.y, position.z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetConeAngle(coneAngle);
  light->SetAttenuationValues(1.0, 0.0, 0.0);
  return light;
}

vtkLight* TestScene::SetPoint(const glm::dvec3& position)
{
  return this->SetSpot(position, 180.0);
}

glm::dvec3 GroundShadowOfSphereCenter(const glm::dvec3& direction)
{
  return SphereCenter + direction * (SphereCenter.z / -direction.z);
}

glm::dvec3 GroundShadowOfSphereCenterFrom(const glm::dvec3& lightPosition)
{
  return GroundShadowOfSphereCenter(SphereCenter - lightPosition);
}

namespace
{
// The window's back buffer as RGB; the filter renders the window again first
// unless rerender is off.
vtkSmartPointer<vtkImageData> Capture(vtkRenderWindow* window, bool rerender)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->SetShouldRerender(rerender);
  capture->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(capture->GetOutput());
  return image;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<unsigned char> RgbBytes(vtkImageData* image)
{
  const auto* first = static_cast<const unsigned char*>(image->GetScalarPointer());
  return std::vector<unsigned char>(first, first + image->GetNumberOfPoints() * 3);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> AddSourceActor(vtkRenderer* renderer, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkImageData> RenderAndCapture(vtkRenderWindow* window)
{
  window->Render();
  return Capture(window, true);
}

vtkSmartPointer<vtkImageData> CaptureAsRendered(vtkRenderWindow* window)
{
  return Capture(window, false);
}

//------------------------------------------------------------------------------
std::vector<unsigned char> FreshPassFrame(
  TestScene& scene, vtkSmartPointer<vtkAbstractShadowMapPass> fresh)
{
  vtkRenderPass* kept = scene.Renderer->GetPass();
  kept->Register(nullptr);
  scene.Renderer->SetPass(fresh);
  scene.Window->Render();
  const std::vector<unsigned char> frame = RgbBytes(CaptureAsRendered(scene.Window));
  scene.Renderer->SetPass(kept);
  kept->UnRegister(nullptr);
  fresh->ReleaseGraphicsResources(scene.Window);
  return frame;
}

//------------------------------------------------------------------------------
std::string ChangeShownAsFresh(TestScene& scene, vtkAbstractShadowMapPass* pass,
  const std::function<void()>& change,
  const std::function<vtkSmartPointer<vtkAbstractShadowMapPass>()>& fresh, const std::string& what)
{
  scene.Renderer->SetPass(pass);
  RenderAndCapture(scene.Window);
  change();
  const auto after = RgbBytes(RenderAndCapture(scene.Window));
  return after == FreshPassFrame(scene, fresh())
    ? std::string()
    : what + ": the frame after the change differs from a fresh pass's";
}

namespace
{
// Pixel where `world` is seen, or {-1, -1} when off the image.
glm::ivec2 PixelAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world)
{
  renderer->SetWorldPoint(world.x, world.y, world.z, 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  const glm::ivec2 pixel(static_cast<int>(display[0]), static_cast<int>(display[1]));
  int dims[3];
  image->GetDimensions(dims);
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= dims[0] || pixel.y >= dims[1])
  {
    return { -1, -1 };
  }
  return pixel;
}

const unsigned char* RgbAt(vtkImageData* image, int x, int y)
{
  return static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
}
} // namespace

int CountUndersampled(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  int count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0))[0] == 255;
    }
  }
  return count;
}

namespace
{
// Luminances of the (2 radius + 1)^2 pixels around where `world` is seen; empty
// when it is off the image.
std::vector<double> LuminancesAround(
  vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world, int radius)
{
  std::vector<double> luminances;
  const glm::ivec2 center = PixelAt(renderer, image, world);
  if (center.x < 0)
  {
    return luminances;
  }
  int dims[3];
  image->GetDimensions(dims);
  for (int y = std::max(center.y - radius, 0); y <= std::min(center.y + radius, dims[1] - 1); ++y)
  {
    for (int x = std::max(center.x - radius, 0); x <= std::min(center.x + radius, dims[0] - 1); ++x)
    {
      const unsigned char* rgb = RgbAt(image, x, y);
      luminances.push_back(0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]);
    }
  }
  return luminances;
}
} // namespace

double LuminanceAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world)
{
  const std::vector<double> block = LuminancesAround(renderer, image, world, 1);
  return block.empty() ? -1.0 : std::accumulate(block.begin(), block.end(), 0.0) / block.size();
}

double DarkestAround(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world)
{
  const std::vector<double> block = LuminancesAround(renderer, image, world, 3);
  return block.empty() ? -1.0 : *std::min_element(block.begin(), block.end());
}

glm::ivec3 ColorAt(vtkRenderer* renderer, vtkImageData* image, const glm::dvec3& world)
{
  const glm::ivec2 pixel = PixelAt(renderer, image, world);
  if (pixel.x < 0)
  {
    return glm::ivec3(-1);
  }
  const unsigned char* rgb = RgbAt(image, pixel.x, pixel.y);
  return { rgb[0], rgb[1], rgb[2] };
}

namespace
{
namespace fs = std::filesystem;

// Where a VTK version keeps the baselines it shades differently from VTK 9.1
// (SHADOWMAPS_BASELINE_VARIANT, empty on 9.1; CMake/ShadowMapsVTKCompat.cmake).
fs::path VariantBaseline(const std::string& name)
{
  const std::string variant = SHADOWMAPS_BASELINE_VARIANT;
  return variant.empty() ? fs::path()
                         : fs::path(SHADOWMAPS_BASELINE_DIR) / variant / (name + ".png");
}

fs::path HostBaseline(const std::string& name)
{
  return fs::path(SHADOWMAPS_BASELINE_DIR) / (name + ".png");
}

// The variant's own baseline where it has one, else the host's.
fs::path BaselineOf(const std::string& name)
{
  const fs::path variant = VariantBaseline(name);
  return !variant.empty() && fs::exists(variant) ? variant : HostBaseline(name);
}

// Empty when `actual` equals `baseline` (no pixel off by more than 1/255:
// llvmpipe is bit-identical run to run), else what differed.
std::string CompareFiles(const fs::path& actual, const fs::path& baseline)
{
  if (!fs::exists(baseline))
  {
    return "no baseline " + baseline.string() + "; the frame is at " + actual.string();
  }
  OIIO::ImageBuf actualImage(actual.string());
  OIIO::ImageBuf baselineImage(baseline.string());
  if (actualImage.spec().width != baselineImage.spec().width ||
    actualImage.spec().height != baselineImage.spec().height)
  {
    return "size differs from the baseline " + baseline.string();
  }
  const auto result =
    OIIO::ImageBufAlgo::compare(actualImage, baselineImage, 1.5 / 255.0, 0.5 / 255.0);
  if (result.nfail > 0 || result.error)
  {
    std::ostringstream text;
    text << result.nfail << " pixels differ from " << baseline.string() << " (max error "
         << result.maxerror * 255.0 << "/255 at " << result.maxx << "," << result.maxy
         << "); the frame is at " << actual.string();
    return text.str();
  }
  return {};
}

// SHADOWMAPS_UPDATE_BASELINES=1: on VTK 9.1 the frame becomes the baseline; on
// another version it becomes that version's own baseline only where it
// differs from 9.1's (a frame equal to it removes a variant left over).
std::string UpdateBaseline(const fs::path& actual, const std::string& name)
{
  fs::path baseline = HostBaseline(name);
  const fs::path variant = VariantBaseline(name);
  if (!variant.empty())
  {
    if (CompareFiles(actual, baseline).empty())
    {
      fs::remove(variant);
      return "equals the VTK 9.1 baseline " + baseline.string() + ": no variant kept";
    }
    fs::create_directories(variant.parent_path());
    baseline = variant;
  }
  fs::copy_file(actual, baseline, fs::copy_options::overwrite_existing);
  return "baseline written: " + baseline.string() + " (look at it, then rerun)";
}
}

std::string CompareWithBaseline(vtkImageData* image, const std::string& name)
{
  // The leak runs rerun these tests beside ctest's own runs of them: each run
  // writes its frames to a folder of its own.
  const char* outputOverride = std::getenv("SHADOWMAPS_TEST_OUTPUT_DIR");
  const fs::path outputDir(
    outputOverride && *outputOverride ? outputOverride : SHADOWMAPS_TEST_OUTPUT_DIR);
  fs::create_directories(outputDir);
  const fs::path actual = outputDir / (name + ".png");
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(actual.string().c_str());
  writer->Write();

  const char* update = std::getenv("SHADOWMAPS_UPDATE_BASELINES");
  if (update && std::string(update) == "1")
  {
    return UpdateBaseline(actual, name);
  }
  return CompareFiles(actual, BaselineOf(name));
}

std::string BaselinePath(const std::string& name)
{
  return BaselineOf(name).string();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> AddBox(vtkRenderer* renderer, const glm::dvec3& center, const glm::dvec3& size)
{
  vtkNew<vtkCubeSource> box;
  box->SetCenter(center.x, center.y, center.z);
  box->SetXLength(size.x);
  box->SetYLength(size.y);
  box->SetZLength(size.z);
  return AddSourceActor(renderer, box);
}

//------------------------------------------------------------------------------
std::string ShaderFile(const std::string& name)
{
  std::ifstream file(std::string(SHADOWMAPS_SHADER_DIR) + "/" + name + ".glsl");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

//------------------------------------------------------------------------------
std::vector<glm::vec4> EvaluateGLSL(const std::string& functions, const std::string& expression,
  const std::vector<glm::vec4>& cases, const std::function<void(vtkShaderProgram*)>& uniforms)
{
  const int count = static_cast<int>(cases.size());
  const std::string fragment = "//VTK::System::Dec\n" + functions + "\nuniform vec4 cases[" +
    std::to_string(count) + "];\n//VTK::Output::Dec\nvoid main()\n{\n" +
    "  vec4 c = cases[int(gl_FragCoord.x)];\n  gl_FragData[0] = " + expression + ";\n}\n";

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(true);
  window->SetSize(count, 1);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  gl->MakeCurrent();
  vtkOpenGLState* state = gl->GetState();
  state->PushFramebufferBindings();
  GLuint texture = 0;
  GLuint framebuffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, count, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  state->vtkglViewport(0, 0, count, 1);
  vtkOpenGLState::ScopedglEnableDisable keepBlend(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  std::vector<glm::vec4> results(cases.size(), glm::vec4(-1.0f));
  {
    vtkOpenGLQuadHelper quad(gl, nullptr, fragment.c_str(), "");
    if (quad.Program && quad.Program->GetCompiled())
    {
      quad.Program->SetUniform4fv(
        "cases", count, reinterpret_cast<const float(*)[4]>(cases.data()));
      if (uniforms)
      {
        uniforms(quad.Program);
      }
      quad.Render();
      glReadPixels(0, 0, count, 1, GL_RGBA, GL_FLOAT, results.data());
    }
    quad.ReleaseGraphicsResources(gl);
  }
  state->PopFramebufferBindings();
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
  return results;
}

} // namespace shadowtest
