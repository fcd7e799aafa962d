// Which view shades a receiver, checked through the receivers' shader itself
// (the PARTITION analysis view colours each pixel by the view that shaded it)
// against the rule each layout states: cube faces by the dominant axis of the
// direction from the light, cascades by view depth between the splits. No C++
// copy of the shader's selection exists to drift from it.
#include "ShadowTestUtilities.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"

#include <gtest/gtest.h>

#include <array>

using namespace shadowtest;

namespace
{
// vtkShadowPartitionColor's palette (Shaders/vtkShadowMapsAnalysisFS.glsl): the
// documented colours of views 0 to 5.
const std::array<glm::dvec3, 6> Palette = { glm::dvec3(0.9, 0.2, 0.2), glm::dvec3(0.2, 0.8, 0.2),
  glm::dvec3(0.2, 0.4, 1.0), glm::dvec3(0.95, 0.85, 0.2), glm::dvec3(0.8, 0.3, 0.9),
  glm::dvec3(0.2, 0.85, 0.85) };

// The view whose palette colour the pixel shows (dimmed by up to half in
// shadow: the hue stays); -1 off the image, -2 for no palette colour (black:
// outside the map the shader picked).
int ViewShown(const glm::ivec3& color, int views)
{
  const glm::dvec3 c(color);
  if (color.r < 0)
  {
    return -1;
  }
  if (glm::length(c) < 1.0)
  {
    return -2;
  }
  int best = -1;
  double closest = 0.0;
  for (int i = 0; i < views; ++i)
  {
    const double cosine = glm::dot(glm::normalize(c), glm::normalize(Palette[i]));
    if (cosine > closest)
    {
      closest = cosine;
      best = i;
    }
  }
  return closest > 0.995 ? best : -2;
}

// Only the ground stays, so that every ground point is what its pixel shows.
void KeepOnlyTheGround(TestScene& scene)
{
  scene.Sphere->SetVisibility(false);
  scene.Box->SetVisibility(false);
}
} // namespace

// Faces +x, -x, +y, -y, +z, -z: the dominant axis of the direction from the light.
TEST(ShadowReceiverSelection, CubeFacesByTheDominantAxis)
{
  TestScene scene;
  KeepOnlyTheGround(scene);
  const glm::dvec3 light(-1.0, 0.5, 3.0);
  scene.SetPoint(light);
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetAnalysisView(vtkAbstractShadowMapPass::PARTITION);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  ASSERT_EQ(pass->GetNumberOfShadowMapLayers(), 6);
  int checked = 0;
  for (double x = -9.5; x <= 9.5; x += 0.5)
  {
    for (double y = -9.5; y <= 9.5; y += 0.5)
    {
      const glm::dvec3 d = glm::dvec3(x, y, 0.0) - light;
      glm::dvec3 a = glm::abs(d);
      const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
      const int face = 2 * axis + (d[axis] >= 0.0 ? 0 : 1);
      a[axis] = 0.0;
      if (std::abs(d[axis]) < 1.1 * std::max({ a.x, a.y, a.z }))
      {
        continue; // too near an edge between faces for a pixel to tell
      }
      const int shown = ViewShown(ColorAt(scene.Renderer, image, { x, y, 0.0 }), 6);
      if (shown == -1)
      {
        continue; // off the image
      }
      EXPECT_EQ(shown, face) << "ground at (" << x << ", " << y << ")";
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}

// Cascade i shades view depths from split i to split i + 1.
TEST(ShadowReceiverSelection, CascadesByViewDepth)
{
  TestScene scene(480, 320);
  KeepOnlyTheGround(scene);
  scene.SetSun(glm::normalize(glm::dvec3(-0.3, 0.4, -1.0)));
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.0, -12.0, 2.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  scene.Renderer->ResetCameraClippingRange();
  vtkNew<vtkCascadedShadowMapPass> pass;
  pass->SetBlendFraction(0.0);
  pass->SetAnalysisView(vtkAbstractShadowMapPass::PARTITION);
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  ASSERT_EQ(pass->GetNumberOfSplits(), 5);
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  int checked = 0;
  int cascadesSeen = 0;
  std::array<bool, 4> seen{};
  for (double x = -9.5; x <= 9.5; x += 0.5)
  {
    for (double y = -9.5; y <= 9.5; y += 0.5)
    {
      const double p[4] = { x, y, 0.0, 1.0 };
      double v[4];
      view->MultiplyPoint(p, v);
      const double depth = -v[2];
      int cascade = -1;
      bool nearSplit = false;
      for (int i = 0; i < 4; ++i)
      {
        cascade = depth >= pass->GetSplit(i) ? i : cascade;
        nearSplit = nearSplit || std::abs(depth - pass->GetSplit(i + 1)) < 0.02 * depth;
      }
      if (nearSplit || cascade < 0 || depth >= pass->GetSplit(4))
      {
        continue;
      }
      const int shown = ViewShown(ColorAt(scene.Renderer, image, { x, y, 0.0 }), 4);
      if (shown == -1)
      {
        continue;
      }
      EXPECT_EQ(shown, cascade) << "ground at (" << x << ", " << y << "), view depth " << depth;
      seen[cascade] = true;
      ++checked;
    }
  }
  for (bool s : seen)
  {
    cascadesSeen += s ? 1 : 0;
  }
  EXPECT_GT(checked, 300);
  EXPECT_EQ(cascadesSeen, 4);
  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(scene.Window);
}
