// Translucent casters (docs/TRANSLUCENT.md): what a translucent slab, two
// slabs, a coloured slab let through to the ground under every kind of map,
// against the transmission model; opaque casters as before; no cost (no
// transmittance maps, no shader change) without translucent casters.
#include "ColorByTable.h"
#include "ShadowTestUtilities.h"
#include "TranslucentScene.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapPass.h"
#include "vtkCascadedShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkContourFilter.h"
#include "vtkMapper.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace shadowtest;
using namespace translucenttest;


TEST(ShadowTranslucent, SlabLetsThroughTheModelsShareUnderEveryPassAndLight)
{
  const glm::dvec3 color(0.9, 0.6, 0.3);
  const glm::dvec3 slabCentre(0.0, 0.0, 2.0);
  // Every opacity under the depth pass's sun; one under each other pass and light.
  const std::vector<double> everyOpacity = { 0.0, 0.25, 0.5, 0.75, 1.0 };
  for (const auto& pass : Passes)
  {
    for (LightKind kind : { LightKind::Sun, LightKind::Spot, LightKind::Point })
    {
      const bool first = pass.first == Passes.front().first && kind == LightKind::Sun;
      for (double opacity : first ? everyOpacity : std::vector<double>{ 0.5 })
      {
        SlabScene scene(kind);
        scene.AddSlab(slabCentre, 2.0, color, opacity);
        vtkSmartPointer<vtkAbstractShadowMapPass> shadows = pass.second();
        auto image = scene.Render(shadows);
        const std::string what =
          pass.first + ", " + KindName(kind) + ", opacity " + std::to_string(opacity);
        // Opacity 1 is today's opaque caster; opacity 0 shadows nothing.
        ExpectNear(scene.Measured(image, scene.GroundUnder(slabCentre)),
          opacity >= 1.0 ? glm::dvec3(0.0) : Model(color, opacity), 0.02, what + ", under");
        ExpectNear(scene.Measured(image, scene.GroundUnder(slabCentre + glm::dvec3(1.5, 0.0, 0.0))),
          glm::dvec3(1.0), 0.0, what + ", beside");
        // The slab itself, lit directly, is not in its own shadow.
        if (opacity > 0.0)
        {
          ExpectNear(scene.Measured(image, slabCentre), glm::dvec3(1.0), 1.0 / 255.0,
            what + ", the slab");
        }
      }
    }
  }
}

TEST(ShadowTranslucent, OverlappingSlabsMultiplyInEitherDrawOrder)
{
  const glm::dvec3 red(1.0, 0.2, 0.1), blue(0.1, 0.3, 1.0);
  const glm::dvec3 redCentre(-0.5, 0.0, 2.0), blueCentre(0.0, -0.5, 3.0);
  // Ground points under both (the sun carries (0.25, 0, 2) to (-0.75,
  // -0.5, 3)), under the red slab only and under the blue one only.
  const std::vector<std::pair<glm::dvec3, glm::dvec3>> probes = {
    { redCentre + glm::dvec3(0.75, 0.0, 0.0), Model(red, 0.5) * Model(blue, 0.4) },
    { redCentre + glm::dvec3(-0.7, 0.7, 0.0), Model(red, 0.5) },
    { blueCentre + glm::dvec3(0.7, -0.7, 0.0), Model(blue, 0.4) },
  };
  for (const auto& pass : Passes)
  {
    std::vector<glm::dvec3> firstOrder;
    for (bool redFirst : { true, false })
    {
      SlabScene scene;
      auto addRed = [&] { scene.AddSlab(redCentre, 2.0, red, 0.5); };
      auto addBlue = [&] { scene.AddSlab(blueCentre, 2.0, blue, 0.4); };
      redFirst ? (addRed(), addBlue()) : (addBlue(), addRed());
      vtkSmartPointer<vtkAbstractShadowMapPass> shadows = pass.second();
      auto image = scene.Render(shadows);
      for (std::size_t i = 0; i < probes.size(); ++i)
      {
        const std::string what = pass.first + (redFirst ? ", red first" : ", blue first") +
          ", probe " + std::to_string(i);
        const glm::dvec3 measured = scene.Measured(image, scene.GroundUnder(probes[i].first));
        ExpectNear(measured, probes[i].second, 0.03, what);
        // The products are kept in 16-bit floats: the order may change the
        // last bit of one.
        if (!redFirst)
        {
          ExpectNear(measured, firstOrder[i], 1.0 / 255.0, what + " against the other order");
        }
        firstOrder.push_back(measured);
      }
    }
  }
}

TEST(ShadowTranslucent, OpaqueCastersAndReceiversAboveKeepTheirLight)
{
  SlabScene scene;
  const glm::dvec3 slabCentre(0.0, 0.0, 2.0);
  scene.AddSlab(slabCentre, 4.0, { 1.0, 1.0, 1.0 }, 0.5);
  // A box above the slab: its top is lit, its shadow on the ground black
  // whatever the slab below it does.
  auto box = AddBox(scene.Renderer, { 0.0, 0.0, 3.5 }, { 0.6, 0.6, 0.6 });
  // A translucent caster opted out casts nothing.
  vtkActor* optedOut = scene.AddSlab({ -3.0, -3.0, 2.0 }, 1.0, { 1.0, 0.0, 0.0 }, 0.5);
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  optedOut->SetPropertyKeys(keys);
  vtkNew<vtkDepthShadowMapPass> pass;
  auto image = scene.Render(pass);
  ExpectNear(scene.Measured(image, { 0.0, 0.0, 3.8 }), glm::dvec3(1.0), 1.0 / 255.0, "box top");
  ExpectNear(scene.Measured(image, scene.GroundUnder({ 0.0, 0.0, 3.5 })), glm::dvec3(0.0), 1.0 / 255.0,
    "under the box");
  ExpectNear(scene.Measured(image, scene.GroundUnder({ 1.5, -1.5, 2.0 })), glm::dvec3(0.5), 0.02,
    "under the slab only");
  ExpectNear(scene.Measured(image, scene.GroundUnder({ -3.0, -3.0, 2.0 })), glm::dvec3(1.0), 0.0,
    "under the opted-out slab");
}

TEST(ShadowTranslucent, NoTranslucentCasterNoTransmittanceMapsNorCode)
{
  SlabScene scene;
  AddBox(scene.Renderer, { 0.0, 0.0, 1.0 }, { 1.0, 1.0, 1.0 });
  vtkNew<vtkDepthShadowMapPass> pass;
  const std::vector<unsigned char> opaqueOnly = RgbBytes(scene.Render(pass, false));
  const std::size_t opaqueMemory = pass->GetShadowMapMemory();
  const int builds = pass->GetNumberOfShaderBuilds();

  vtkActor* slab = scene.AddSlab({ 3.0, 3.0, 2.0 }, 2.0, { 0.2, 0.4, 1.0 }, 0.5);
  const std::vector<unsigned char> withSlab = RgbBytes(scene.Render(pass, false));
  EXPECT_GT(pass->GetShadowMapMemory(), opaqueMemory);
  EXPECT_GT(pass->GetNumberOfShaderBuilds(), builds);
  EXPECT_NE(withSlab, opaqueOnly);

  // The slab made opaque, then removed: the maps and code of an opaque scene.
  slab->GetProperty()->SetOpacity(1.0);
  scene.Render(pass, false);
  EXPECT_EQ(pass->GetShadowMapMemory(), opaqueMemory);
  scene.Renderer->RemoveActor(slab);
  EXPECT_EQ(RgbBytes(scene.Render(pass, false)), opaqueOnly);
  EXPECT_EQ(pass->GetShadowMapMemory(), opaqueMemory);
}

namespace
{
/// A closed isosurface (a sphere of radius 1.5 at height 2.5, contoured from
/// a sampled field) of `color` and `opacity` over the slab scene's ground.
vtkActor* AddIsosurface(SlabScene& scene, const glm::dvec3& color, double opacity)
{
  constexpr int Samples = 40;
  vtkNew<vtkImageData> field;
  field->SetDimensions(Samples, Samples, Samples);
  field->SetOrigin(-2.0, -2.0, 0.5);
  const double spacing = 4.0 / (Samples - 1);
  field->SetSpacing(spacing, spacing, spacing);
  vtkNew<vtkFloatArray> distance;
  distance->SetNumberOfTuples(field->GetNumberOfPoints());
  for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
  {
    double p[3];
    field->GetPoint(i, p);
    distance->SetValue(i, static_cast<float>(glm::length(glm::dvec3(p[0], p[1], p[2] - 2.5)) - 1.5));
  }
  field->GetPointData()->SetScalars(distance);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(field);
  contour->SetValue(0, 0.0);
  vtkActor* shell = AddSourceActor(scene.Renderer, contour);
  shell->GetMapper()->ScalarVisibilityOff();
  shell->GetProperty()->SetColor(color.x, color.y, color.z);
  shell->GetProperty()->SetOpacity(opacity);
  return shell;
}
} // namespace

TEST(ShadowTranslucent, IsosurfaceCastsATintedShadowThroughBothItsSides)
{
  const glm::dvec3 color(0.2, 0.6, 1.0);
  const double opacity = 0.3;
  SlabScene scene;
  AddIsosurface(scene, color, opacity);
  AddBox(scene.Renderer, { -3.5, 3.0, 0.75 }, { 1.5, 1.5, 1.5 });
  vtkNew<vtkDepthShadowMapPass> pass;
  // The light crosses the shell twice.
  const glm::dvec3 underCentre = scene.GroundUnder({ 0.0, 0.0, 2.5 });
  const glm::dvec3 expected = Model(color, opacity) * Model(color, opacity);
  ExpectNear(scene.Measured(scene.Render(pass), underCentre), expected, 0.03, "under the shell");

  auto shaded = scene.Render(pass, false);
  const std::string difference = CompareWithBaseline(shaded, "TranslucentIsosurface");
  EXPECT_TRUE(difference.empty()) << difference;
  // Shaded: the shell's shadow is lighter than the box's, darker than the open
  // ground, and blue (the shell's colour): blue above green above red.
  const glm::ivec3 tinted = ColorAt(scene.Renderer, shaded, underCentre);
  const glm::ivec3 open = ColorAt(scene.Renderer, shaded, { 4.0, -4.0, 0.0 });
  const glm::ivec3 opaque = ColorAt(scene.Renderer, shaded, scene.GroundUnder({ -3.5, 3.0, 1.5 }));
  std::cout << "[ measured ] shaded ground: open " << open.x << " " << open.y << " " << open.z
            << ", under the shell " << tinted.x << " " << tinted.y << " " << tinted.z
            << ", under the box " << opaque.x << " " << opaque.y << " " << opaque.z << "\n";
  EXPECT_GT(tinted.z, tinted.y);
  EXPECT_GT(tinted.y, tinted.x);
  EXPECT_LT(tinted.z, open.z);
  EXPECT_GT(tinted.x, opaque.x);

  // Depth peeling draws the shell itself differently, not its shadow.
  scene.Renderer->SetUseDepthPeeling(1);
  auto peeled = scene.Render(pass, false);
  EXPECT_EQ(ColorAt(scene.Renderer, peeled, underCentre), tinted);
  scene.Renderer->SetUseDepthPeeling(0);
}

TEST(ShadowTranslucent, CasterColourFromScalarsAndPBRMaterials)
{
  // A slab coloured by point scalars through a one-colour lookup table with
  // alpha (opacity 1 on the actor), and a PBR slab over a PBR ground.
  SlabScene scene;
  vtkActor* mapped = scene.AddSlab({ 0.0, 0.0, 2.0 }, 2.0, { 1.0, 1.0, 1.0 }, 1.0);
  ColorByOneTableEntry(mapped, 0.2, 0.8, 0.4, 0.6);
  vtkActor* pbr = scene.AddSlab({ -3.0, -3.0, 2.0 }, 2.0, { 0.9, 0.3, 0.2 }, 0.4);
  pbr->GetProperty()->SetInterpolationToPBR();
  scene.Ground->GetProperty()->SetInterpolationToPBR();
  vtkNew<vtkDepthShadowMapPass> pass;
  auto image = scene.Render(pass);
  // Bytes: the table's colour and alpha are quantised to 1/255.
  ExpectNear(scene.Measured(image, scene.GroundUnder({ 0.0, 0.0, 2.0 })),
    Model({ 51 / 255.0, 204 / 255.0, 102 / 255.0 }, 153 / 255.0), 0.02, "lookup table");
  ExpectNear(scene.Measured(image, scene.GroundUnder({ -3.0, -3.0, 2.0 })),
    Model({ 0.9, 0.3, 0.2 }, 0.4), 0.02, "PBR");
}

TEST(ShadowTranslucent, TexturedAndImpostorCastersCastNoTranslucentShadow)
{
  // Their alpha comes after the lighting (a texture's) or they cut their own
  // shapes (points as spheres): they cast no translucent shadow, as before.
  SlabScene scene;
  vtkActor* textured = scene.AddSlab({ 0.0, 0.0, 2.0 }, 2.0, { 1.0, 1.0, 1.0 }, 1.0);
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < 16; ++i)
  {
    texels[4 * i] = texels[4 * i + 1] = texels[4 * i + 2] = 255;
    texels[4 * i + 3] = 128;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  textured->SetTexture(texture);
  vtkActor* points = scene.AddSlab({ -3.0, -3.0, 2.0 }, 2.0, { 1.0, 0.0, 0.0 }, 0.5);
  points->GetProperty()->SetRepresentationToPoints();
  points->GetProperty()->RenderPointsAsSpheresOn();
  points->GetProperty()->SetPointSize(30.0f);
  vtkNew<vtkDepthShadowMapPass> pass;
  auto frame = scene.Render(pass);
  ExpectNear(scene.Measured(frame, scene.GroundUnder({ 0.0, 0.0, 2.0 })), glm::dvec3(1.0), 0.0,
    "under the textured slab");
  ExpectNear(scene.Measured(frame, scene.GroundUnder({ -3.0, -3.0, 2.0 })), glm::dvec3(1.0), 0.0,
    "under the translucent points");
}

TEST(ShadowTranslucent, AReceiverDividesOutOnlyAShareTheMapsHold)
{
  // Pane B (z = 2) lies in pane A's shadow (z = 4, offset along the sun); the
  // camera sees B where A does not cover it.
  const glm::dvec3 onB(1.0, 0.5, 2.0);
  const glm::dvec3 centreA = onB + (2.0 / SunDirection.z) * SunDirection; // toward the sun
  for (bool bCasts : { true, false })
  {
    SlabScene scene;
    scene.AddSlab(centreA, 2.0, { 1.0, 1.0, 1.0 }, 0.5);
    vtkActor* b = scene.AddSlab({ 1.0, 0.5, 2.0 }, 1.0, { 1.0, 1.0, 1.0 }, 0.5);
    if (!bCasts)
    {
      vtkNew<vtkInformation> keys;
      keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
      b->SetPropertyKeys(keys);
    }
    vtkNew<vtkDepthShadowMapPass> pass;
    auto frame = scene.Render(pass);
    ExpectNear(scene.Measured(frame, onB), glm::dvec3(0.5), 0.02,
      std::string("pane B in pane A's shadow, B ") + (bCasts ? "casting" : "opted out"));
  }
}
