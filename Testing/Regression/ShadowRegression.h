// What the VTK-style regression tests share: render the standard test scene
// through a pass, assert the probes and the strict baseline comparison
// (OpenImageIO), then hand the frame to VTK's own regression test.
#ifndef ShadowRegression_h
#define ShadowRegression_h

#include "ShadowTestUtilities.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderPass.h"
#include "vtkTesting.h"

#include <iostream>
#include <string>

namespace shadowregression
{
/// Renders `scene` through `pass` and returns the test's exit code: failure
/// when a VTK error was reported, the ground at `shadowed` is not dark, the
/// ground at `lit` is not lit, the frame differs from its baseline
/// (shadowtest::BaselinePath) by more than 1/255 anywhere, or VTK's own
/// regression test against the same baseline fails.
inline int RenderAndCheck(int argc, char* argv[], shadowtest::TestScene& scene, vtkRenderPass* pass,
  const std::string& name, const glm::dvec3& shadowed, const glm::dvec3& lit)
{
  shadowtest::ErrorCounter errors;
  scene.Renderer->SetPass(pass);
  vtkSmartPointer<vtkImageData> image = shadowtest::RenderAndCapture(scene.Window);
  bool ok = errors.Errors() == 0;
  const double dark = shadowtest::LuminanceAt(scene.Renderer, image, shadowed);
  const double bright = shadowtest::LuminanceAt(scene.Renderer, image, lit);
  if (dark >= shadowtest::ShadowedBelow || bright <= shadowtest::LitAbove)
  {
    std::cerr << name << ": shadowed probe " << dark << ", lit probe " << bright << "\n";
    ok = false;
  }
  const std::string difference = shadowtest::CompareWithBaseline(image, name);
  if (!difference.empty())
  {
    std::cerr << name << ": " << difference << "\n";
    ok = false;
  }
  // VTK's comparison (its own, tolerant metric) on the same frame and baseline:
  // vtkRegressionTestImageThreshold's, with the baseline of this VTK version
  // as the -V argument (vtkTesting reads the baseline from its arguments).
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    const bool baselineValue = i > 0 && std::string(argv[i - 1]) == "-V";
    testing->AddArgument(baselineValue ? shadowtest::BaselinePath(name).c_str() : argv[i]);
  }
  testing->SetRenderWindow(scene.Window);
  const int vtkResult = testing->RegressionTest(0.05);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
  return ok && vtkResult == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
} // namespace shadowregression

#endif
