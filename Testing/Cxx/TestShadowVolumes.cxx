// Volumes cast (docs/TRANSLUCENT.md): a box of constant opacity per unit
// length over a ground lets through what the slice model gives its optical
// depth, under every pass and light; what it lets through follows its
// transfer functions; volumes that cannot be marched cast nothing, with a
// warning.
#include "ShadowTestUtilities.h"
#include "TranslucentScene.h"

#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "ShadowMapVTKCompat.h" // For the GL functions

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>

using namespace shadowtest;
using namespace translucenttest;

namespace
{
/// A volume of image data, its transfer functions and mapper, shown in a
/// renderer once its image and functions are filled.
struct TestVolume
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkPiecewiseFunction> Opacities;
  vtkNew<vtkColorTransferFunction> Colors;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkSmartVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;

  void Show(vtkRenderer* renderer, double unitDistance)
  {
    this->Property->SetScalarOpacity(this->Opacities);
    this->Property->SetColor(this->Colors);
    this->Property->SetScalarOpacityUnitDistance(unitDistance);
    this->Mapper->SetInputData(this->Image);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    renderer->AddVolume(this->Volume);
  }
};

/// A volume of constant scalar filling [-2, 2] x [-2, 2] x [2, 3], of
/// constant opacity per `unitDistance` and colour.
struct UniformVolume : TestVolume
{
  glm::dvec3 Centre{ 0.0, 0.0, 2.5 };
  double Thickness = 1.0;

  UniformVolume(vtkRenderer* renderer, double opacity, double unitDistance, const glm::dvec3& color)
  {
    this->Image->SetDimensions(21, 21, 6);
    this->Image->SetOrigin(-2.0, -2.0, 2.0);
    this->Image->SetSpacing(0.2, 0.2, 0.2);
    this->Image->AllocateScalars(VTK_FLOAT, 1);
    vtkFloatArray::SafeDownCast(this->Image->GetPointData()->GetScalars())->FillValue(1.0f);
    this->Opacities->AddPoint(0.0, opacity);
    this->Opacities->AddPoint(2.0, opacity);
    this->Colors->AddRGBPoint(0.0, color.x, color.y, color.z);
    this->Colors->AddRGBPoint(2.0, color.x, color.y, color.z);
    this->Show(renderer, unitDistance);
  }
};

/// A Gaussian blob of density (32 samples a side over [-2, 2]^2 x [1.5, 4.5],
/// peak 1 at its centre) whose opacity rises from 0 at density 0.1 to
/// `peakOpacity` at 1, coloured orange.
struct BlobVolume : TestVolume
{
  glm::dvec3 Centre{ 0.0, 0.0, 3.0 };

  BlobVolume(vtkRenderer* renderer, double peakOpacity)
  {
    constexpr int Samples = 32;
    const double spacing = 4.0 / (Samples - 1);
    this->Image->SetDimensions(Samples, Samples, 24);
    this->Image->SetOrigin(-2.0, -2.0, 1.5);
    this->Image->SetSpacing(spacing, spacing, 3.0 / 23.0);
    vtkNew<vtkFloatArray> density;
    density->SetName("density");
    density->SetNumberOfTuples(this->Image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < this->Image->GetNumberOfPoints(); ++i)
    {
      double p[3];
      this->Image->GetPoint(i, p);
      const double r = glm::length(glm::dvec3(p[0], p[1], p[2]) - this->Centre);
      density->SetValue(i, static_cast<float>(std::exp(-r * r / 0.8)));
    }
    this->Image->GetPointData()->SetScalars(density);
    this->Opacities->AddPoint(0.0, 0.0);
    this->Opacities->AddPoint(0.1, 0.0);
    this->Opacities->AddPoint(1.0, peakOpacity);
    this->Colors->AddRGBPoint(0.0, 1.0, 0.5, 0.0);
    this->Colors->AddRGBPoint(1.0, 1.0, 0.5, 0.0);
    this->Show(renderer, 0.5);
  }
};

/// What the slice model gives a path of `length` through a uniform volume in
/// the limit of thin slices: exp(-sigma length (2 - c)), sigma = -ln(1 - a) / u.
glm::dvec3 OpticalDepthModel(double opacity, double unitDistance, const glm::dvec3& color, double length)
{
  const double sigma = -std::log(1.0 - opacity) / unitDistance;
  return glm::exp(-sigma * length * (glm::dvec3(2.0) - color));
}

/// The length of the light's path through the volume's centre.
double PathLength(const SlabScene& scene, const UniformVolume& volume)
{
  const glm::dvec3 direction = scene.Kind == LightKind::Sun
    ? SunDirection
    : glm::normalize(volume.Centre - LampPosition);
  return volume.Thickness / std::abs(direction.z);
}
} // namespace

TEST(ShadowVolumes, UniformVolumeLetsThroughItsOpticalDepthUnderEveryPassAndLight)
{
  const double opacity = 0.2;
  const double unitDistance = 0.5;
  const glm::dvec3 color(1.0, 0.5, 0.0);
  for (const auto& pass : Passes)
  {
    for (LightKind kind : { LightKind::Sun, LightKind::Spot, LightKind::Point })
    {
      SlabScene scene(kind);
      UniformVolume volume(scene.Renderer, opacity, unitDistance, color);
      vtkSmartPointer<vtkAbstractShadowMapPass> shadows = pass.second();
      auto image = scene.Render(shadows);
      const std::string what = pass.first + ", " + KindName(kind);
      const glm::dvec3 expected =
        OpticalDepthModel(opacity, unitDistance, color, PathLength(scene, volume));
      ExpectNear(scene.Measured(image, scene.GroundUnder(volume.Centre)), expected, 0.03,
        what + ", under");
      for (const glm::dvec3& open : { glm::dvec3(-4.0, -4.0, 0.0), glm::dvec3(4.0, -4.0, 0.0) })
      {
        ExpectNear(scene.Measured(image, open), glm::dvec3(1.0), 0.0, what + ", beside");
      }
    }
  }
}

TEST(ShadowVolumes, BlobCastsATintedShadowThatFollowsItsTransferFunction)
{
  SlabScene scene;
  BlobVolume blob(scene.Renderer, 0.5);
  AddBox(scene.Renderer, { -3.5, 3.0, 0.75 }, { 1.5, 1.5, 1.5 });
  vtkNew<vtkDepthShadowMapPass> pass;
  const glm::dvec3 underCentre = scene.GroundUnder(blob.Centre);
  const glm::dvec3 factor = scene.Measured(scene.Render(pass), underCentre);
  std::cout << "[ measured ] under the blob's centre: " << Text(factor) << "\n";
  // Orange absorbs blue most and red least; the core lets some light through.
  EXPECT_GT(factor.x, factor.y);
  EXPECT_GT(factor.y, factor.z);
  EXPECT_GT(factor.x, 0.05);
  EXPECT_LT(factor.x, 0.9);

  auto shaded = scene.Render(pass, false);
  const std::string difference = CompareWithBaseline(shaded, "VolumeShadow");
  EXPECT_TRUE(difference.empty()) << difference;
  const glm::ivec3 tinted = ColorAt(scene.Renderer, shaded, underCentre);
  const glm::ivec3 open = ColorAt(scene.Renderer, shaded, { 4.0, -4.0, 0.0 });
  const glm::ivec3 opaque = ColorAt(scene.Renderer, shaded, scene.GroundUnder({ -3.5, 3.0, 1.5 }));
  std::cout << "[ measured ] shaded ground: open " << open.x << " " << open.y << " " << open.z
            << ", under the blob " << tinted.x << " " << tinted.y << " " << tinted.z
            << ", under the box " << opaque.x << " " << opaque.y << " " << opaque.z << "\n";
  EXPECT_LT(tinted.z, open.z);
  EXPECT_GT(tinted.x, tinted.z);
  EXPECT_GT(tinted.x, opaque.x);

  // A thinner transfer function lets more through; the maps follow its edit.
  blob.Opacities->RemoveAllPoints();
  blob.Opacities->AddPoint(0.0, 0.0);
  blob.Opacities->AddPoint(1.0, 0.1);
  const glm::dvec3 thinner = scene.Measured(scene.Render(pass), underCentre);
  std::cout << "[ measured ] thinner transfer function: " << Text(thinner) << "\n";
  EXPECT_GT(thinner.z, factor.z + 0.1);
}

TEST(ShadowVolumes, OptedOutOrUnmarchableVolumesCastNothingAndFreeTheirData)
{
  SlabScene scene;
  UniformVolume volume(scene.Renderer, 0.2, 0.5, { 1.0, 1.0, 1.0 });
  vtkNew<vtkDepthShadowMapPass> pass;
  const glm::dvec3 under = scene.GroundUnder(volume.Centre);
  const glm::dvec3 shadowed = scene.Measured(scene.Render(pass), under);
  EXPECT_LT(shadowed.x, 0.9);
  const std::size_t withVolume = pass->GetShadowMapMemory();

  // Opted out: no shadow, and no transmittance maps nor volume data.
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  volume.Volume->SetPropertyKeys(keys);
  ExpectNear(scene.Measured(scene.Render(pass), under), glm::dvec3(1.0), 0.0, "opted out");
  EXPECT_LT(pass->GetShadowMapMemory(), withVolume);
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 1);
  ExpectNear(scene.Measured(scene.Render(pass), under), shadowed, 0.0, "opted in again");

  // Colours per point (four components): not marched, said once.
  volume.Image->AllocateScalars(VTK_FLOAT, 4);
  vtkFloatArray::SafeDownCast(volume.Image->GetPointData()->GetScalars())->FillValue(0.5f);
  volume.Property->IndependentComponentsOff();
  pass->SetAnalysisViewToShadowFactor();
  scene.Renderer->SetPass(pass);
  {
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
    EXPECT_NE(errors.Text().find("one component per point"), std::string::npos) << errors.Text();
    ExpectNear(scene.Measured(image, under), glm::dvec3(1.0), 0.0, "four components");
    RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
  }
  EXPECT_LT(pass->GetShadowMapMemory(), withVolume);
}

TEST(ShadowVolumes, VolumesReceiveTheOpaqueCastersShadowsUnderEveryPass)
{
  // A nearly opaque white slab of volume under a box: the box's shadow
  // darkens the volume's samples where it falls on them.
  const glm::dvec3 shadowedTop(0.5, 0.25, 2.0);
  const glm::dvec3 litTop(-1.0, 1.0, 2.0);
  for (const auto& pass : Passes)
  {
    SlabScene scene;
    UniformVolume volume(scene.Renderer, 0.9, 0.2, { 1.0, 1.0, 1.0 });
    volume.Image->SetOrigin(-2.0, -2.0, 1.0);
    AddBox(scene.Renderer, { -1.5, -0.75, 4.0 }, { 1.5, 1.5, 0.2 });
    vtkSmartPointer<vtkAbstractShadowMapPass> shadows = pass.second();
    auto image = scene.Render(shadows, false);
    const double shadowed = LuminanceAt(scene.Renderer, image, shadowedTop);
    const double lit = LuminanceAt(scene.Renderer, image, litTop);
    std::cout << "[ measured ] " << pass.first << ": the volume in the box's shadow " << shadowed
              << ", lit " << lit << "\n";
    EXPECT_GT(lit, 100.0);
    EXPECT_LT(shadowed, 0.5 * lit) << pass.first;

    // Opted out of receiving: the same everywhere.
    vtkNew<vtkInformation> keys;
    keys->Set(vtkAbstractShadowMapPass::RECEIVES_SHADOWS(), 0);
    volume.Volume->SetPropertyKeys(keys);
    image = scene.Render(shadows, false);
    EXPECT_NEAR(LuminanceAt(scene.Renderer, image, shadowedTop),
      LuminanceAt(scene.Renderer, image, litTop), 3.0)
      << pass.first << ", opted out";
  }
}

TEST(ShadowVolumes, OpacityIsPerDataLengthAsVTKDrawsIt)
{
  // Stretched twice along z by its matrix, the volume is twice as thick in
  // the world but not in its data: VTK's ray caster corrects the opacity by
  // data lengths, and so does its shadow.
  const double opacity = 0.2;
  const double unitDistance = 0.5;
  const glm::dvec3 color(1.0, 0.5, 0.0);
  SlabScene scene;
  UniformVolume volume(scene.Renderer, opacity, unitDistance, color);
  volume.Volume->SetScale(1.0, 1.0, 2.0);
  const glm::dvec3 centre(0.0, 0.0, 5.0);
  const double worldLength = 2.0 / std::abs(SunDirection.z);
  const double dataLength =
    glm::length(glm::dvec3(SunDirection.x, SunDirection.y, 0.5 * SunDirection.z)) * worldLength;
  vtkNew<vtkDepthShadowMapPass> pass;
  ExpectNear(scene.Measured(scene.Render(pass), scene.GroundUnder(centre)),
    OpticalDepthModel(opacity, unitDistance, color, dataLength), 0.03, "stretched volume");
}

TEST(ShadowVolumes, ClippingPlanesCutTheShadowAndFollowAPlaneMovedInPlace)
{
  SlabScene scene;
  UniformVolume volume(scene.Renderer, 0.5, 0.5, { 1.0, 1.0, 1.0 });
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(1.0, 0.0, 0.0); // keeps x >= 0
  volume.Mapper->AddClippingPlane(plane);
  vtkNew<vtkDepthShadowMapPass> pass;
  const glm::dvec3 keptHalf = scene.GroundUnder({ 1.0, 0.0, 2.5 });
  const glm::dvec3 cutHalf = scene.GroundUnder({ -1.0, 0.0, 2.5 });
  auto image = scene.Render(pass);
  EXPECT_LT(scene.Measured(image, keptHalf).x, 0.5) << "the half kept casts";
  ExpectNear(scene.Measured(image, cutHalf), glm::dvec3(1.0), 0.0, "the half cut away");
  // The plane moved in place (as a widget does): the shadow follows.
  plane->SetNormal(-1.0, 0.0, 0.0);
  image = scene.Render(pass);
  EXPECT_LT(scene.Measured(image, cutHalf).x, 0.5) << "the other half now casts";
  ExpectNear(scene.Measured(image, keptHalf), glm::dvec3(1.0), 0.0, "and this one no more");
}

TEST(ShadowVolumes, OtherBlendModesAndOversizedVolumesCastNothingAndSaySo)
{
  SlabScene scene;
  UniformVolume volume(scene.Renderer, 0.5, 0.5, { 1.0, 1.0, 1.0 });
  vtkNew<vtkDepthShadowMapPass> pass;
  pass->SetAnalysisViewToShadowFactor();
  scene.Renderer->SetPass(pass);
  const glm::dvec3 under = scene.GroundUnder(volume.Centre);
  volume.Mapper->SetBlendModeToMaximumIntensity();
  {
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_EQ(errors.Warnings(), 1) << errors.Text();
    EXPECT_NE(errors.Text().find("blend mode"), std::string::npos) << errors.Text();
    ExpectNear(scene.Measured(image, under), glm::dvec3(1.0), 0.0, "maximum intensity");
  }
  volume.Mapper->SetBlendModeToComposite();
  EXPECT_LT(scene.Measured(RenderAndCapture(scene.Window), under).x, 0.9) << "composite again";
  // More samples a side than this GL's 3D textures hold.
  int largest = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
  volume.Image->SetDimensions(largest + 1, 2, 2);
  volume.Image->SetSpacing(4.0 / largest, 4.0, 1.0);
  volume.Image->AllocateScalars(VTK_FLOAT, 1);
  vtkFloatArray::SafeDownCast(volume.Image->GetPointData()->GetScalars())->FillValue(1.0f);
  {
    ErrorCounter errors;
    auto image = RenderAndCapture(scene.Window);
    EXPECT_NE(errors.Text().find("exceed this GL's 3D textures"), std::string::npos)
      << errors.Text();
    ExpectNear(scene.Measured(image, under), glm::dvec3(1.0), 0.0, "oversized");
  }
}

TEST(ShadowVolumes, ImageSampledVolumesDrawWithTheShadowsAndAfterThem)
{
  // VTK's ray caster, drawing at a coarser image sample distance (as its
  // automatic adjustment does while the user drags), asks the last render pass
  // on the volume how many draw buffers it draws into; once the pass is gone,
  // a key left empty made VTK 9.1 read past its end.
  SlabScene scene;
  UniformVolume volume(scene.Renderer, 0.5, 0.5, { 1.0, 0.5, 0.0 });
  vtkNew<vtkGPUVolumeRayCastMapper> gpu;
  gpu->SetInputData(volume.Image);
  gpu->SetAutoAdjustSampleDistances(0);
  volume.Volume->SetMapper(gpu);
  vtkNew<vtkDepthShadowMapPass> pass;
  const glm::dvec3 top = volume.Centre + glm::dvec3(0.0, 0.0, 0.5);
  const glm::ivec3 plain = ColorAt(scene.Renderer, RenderAndCapture(scene.Window), top);
  for (const double sampleDistance : { 1.0, 2.0 })
  {
    gpu->SetImageSampleDistance(static_cast<float>(sampleDistance));
    const glm::ivec3 shadowed = ColorAt(scene.Renderer, scene.Render(pass, false), top);
    scene.Renderer->SetPass(nullptr);
    const glm::ivec3 after = ColorAt(scene.Renderer, RenderAndCapture(scene.Window), top);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(shadowed[c], plain[c], 6) << "with the pass, sample distance " << sampleDistance;
      EXPECT_NEAR(after[c], plain[c], 6) << "after it, sample distance " << sampleDistance;
    }
  }
}
