// The exact shadow oracle (Measurement/ShadowOracle.h) against closed-form
// shadow areas and against VTK's own rasteriser. Run under xvfb-run.
//
// The expected areas are computed from the scene's geometry, never from a
// previous run; the tolerance on areas is 0.1% of the image's pixels.
#include "ShadowOracle.h"
#include "ShadowAreaLight.h"
#include "ShadowOracleVolumes.h"
#include "ColorByTable.h"

#include "vtkAbstractShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "ShadowMapVTKCompat.h"
#include "vtkCellData.h"
#include "vtkColor.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

using shadoworacle::Oracle;
using shadoworacle::Surface;
using shadoworacle::Truth;

static_assert(!std::is_copy_constructible_v<Oracle>, "the oracle owns Embree handles");
static_assert(std::is_nothrow_move_constructible_v<Oracle>, "the oracle is movable");

namespace
{
constexpr int ImageSize = 512;
constexpr double AreaTolerance = 0.001 * ImageSize * ImageSize; // 0.1% of the pixels
constexpr double Pi = 3.14159265358979323846;

void Report(const std::string& what, double measured, double expected)
{
  std::cout << "[ measured ] " << what << ": " << measured << " (expected " << expected
            << ", difference " << measured - expected << ")\n";
}

/// A window with one renderer, offscreen, without multisampling so that the
/// z-buffer holds exactly one depth per pixel centre.
struct View
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;

  explicit View(int width = ImageSize, int height = ImageSize)
  {
    this->Window->SetSize(width, height);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AutomaticLightCreationOff();
  }

  vtkActor* Add(vtkAlgorithm* source)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
    return actor;
  }

  vtkLight* SetLight(const glm::dvec3& position, const glm::dvec3& focalPoint, bool positional,
    double coneAngle = 180.0)
  {
    this->Renderer->RemoveAllLights();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(position.x, position.y, position.z);
    light->SetFocalPoint(focalPoint.x, focalPoint.y, focalPoint.z);
    light->SetPositional(positional);
    light->SetConeAngle(coneAngle);
    this->Renderer->AddLight(light);
    return light;
  }

  /// Directional light shining from `towardLight`.
  vtkLight* SetSun(const glm::dvec3& towardLight)
  {
    return this->SetLight(towardLight, glm::dvec3(0.0), false);
  }

  /// Parallel projection looking down -z at (centre.x, centre.y), from `height`.
  void LookDown(const glm::dvec2& centre, double halfHeight, double height = 50.0)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(centre.x, centre.y, height);
    camera->SetFocalPoint(centre.x, centre.y, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(halfHeight);
    this->Renderer->ResetCameraClippingRange();
  }

  /// Renders and returns the renderer's window depths, row 0 at the bottom.
  std::vector<float> RenderDepth()
  {
    this->Window->Render();
    const int* origin = this->Renderer->GetOrigin();
    const int* size = this->Renderer->GetSize();
    vtkNew<vtkFloatArray> depth;
    this->Window->GetZbufferData(
      origin[0], origin[1], origin[0] + size[0] - 1, origin[1] + size[1] - 1, depth);
    return std::vector<float>(depth->GetPointer(0), depth->GetPointer(0) + size[0] * size[1]);
  }

  /// Renders, builds the oracle, traces the renderer's pixels and drops the
  /// pixels where the rasteriser saw something else.
  Surface RenderAndTrace(Oracle& oracle, std::vector<float>* depthOut = nullptr)
  {
    const std::vector<float> depth = this->RenderDepth();
    std::string error;
    EXPECT_TRUE(oracle.Build(this->Renderer, error)) << error;
    const int* size = this->Renderer->GetSize();
    Surface surface = oracle.Trace(this->Renderer, size[0], size[1]);
    Oracle::MaskRasterMismatch(surface, this->Renderer, depth);
    if (depthOut)
    {
      *depthOut = depth;
    }
    return surface;
  }
};

vtkSmartPointer<vtkPlaneSource> Square(double side, int resolution = 1)
{
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(-0.5 * side, -0.5 * side, 0.0);
  plane->SetPoint1(0.5 * side, -0.5 * side, 0.0);
  plane->SetPoint2(-0.5 * side, 0.5 * side, 0.0);
  plane->SetResolution(resolution, resolution);
  return plane;
}

vtkActor* AddGround(View& view, double halfSide)
{
  return view.Add(Square(2.0 * halfSide, 4));
}

glm::dvec3 TowardLight(double azimuthDeg, double elevationDeg)
{
  const double a = glm::radians(azimuthDeg);
  const double e = glm::radians(elevationDeg);
  return { std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e) };
}

struct Tally
{
  int Lit = 0;
  int Shadowed = 0;
  int Ignored = 0;
  glm::dvec3 ShadowCentroid{ 0.0 };
};

Tally Count(const Surface& surface, const std::vector<Truth>& truth)
{
  Tally tally;
  for (std::size_t i = 0; i < truth.size(); ++i)
  {
    switch (truth[i])
    {
      case Truth::Lit:
        ++tally.Lit;
        break;
      case Truth::Shadowed:
        ++tally.Shadowed;
        tally.ShadowCentroid += surface.Position[i];
        break;
      default:
        ++tally.Ignored;
    }
  }
  if (tally.Shadowed > 0)
  {
    tally.ShadowCentroid /= tally.Shadowed;
  }
  return tally;
}

int CountValid(const Surface& surface)
{
  return static_cast<int>(std::count(surface.Valid.begin(), surface.Valid.end(), 1));
}

/// World (x, y) seen at pixel (x, y) by View::LookDown(centre, halfHeight)
/// in a square image.
glm::dvec2 GroundAtPixel(int x, int y, const glm::dvec2& centre, double halfHeight)
{
  const double pixel = 2.0 * halfHeight / ImageSize;
  return centre + glm::dvec2(-halfHeight + (x + 0.5) * pixel, -halfHeight + (y + 0.5) * pixel);
}

double Cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Whether `p` lies in the square of side `side` centred at `centre` and
/// turned counter-clockwise by `angleDeg`.
bool InSquare(const glm::dvec2& p, const glm::dvec2& centre, double side, double angleDeg)
{
  const double a = glm::radians(angleDeg);
  const glm::dvec2 d = p - centre;
  const glm::dvec2 local(
    d.x * std::cos(a) + d.y * std::sin(a), -d.x * std::sin(a) + d.y * std::cos(a));
  return std::abs(local.x) <= 0.5 * side && std::abs(local.y) <= 0.5 * side;
}

/// Area of the convex hull of `points` (Andrew's monotone chain).
double ConvexHullArea(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(), points.end(),
    [](const glm::dvec2& a, const glm::dvec2& b)
    { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
  {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  double twiceArea = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i)
  {
    twiceArea += hull[i].x * hull[i + 1].y - hull[i + 1].x * hull[i].y;
  }
  return 0.5 * std::abs(twiceArea);
}
/// World points the rasteriser drew at each pixel centre of the renderer,
/// unprojected from its z-buffer with VTK's own matrices.
std::vector<glm::dvec3> RasterPoints(vtkRenderer* renderer, const std::vector<float>& depth)
{
  const int* size = renderer->GetSize();
  vtkNew<vtkMatrix4x4> clipToWorld;
  vtkMatrix4x4::Invert(renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                         static_cast<double>(size[0]) / size[1], -1.0, 1.0),
    clipToWorld);
  std::vector<glm::dvec3> points(depth.size());
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * size[0] + x;
      const double ndc[4] = { 2.0 * (x + 0.5) / size[0] - 1.0, 2.0 * (y + 0.5) / size[1] - 1.0,
        2.0 * depth[i] - 1.0, 1.0 };
      double world[4];
      clipToWorld->MultiplyPoint(ndc, world);
      points[i] = glm::dvec3(world[0], world[1], world[2]) / world[3];
    }
  }
  return points;
}
} // namespace

//------------------------------------------------------------------------------
// Closed-form shadow areas

// A horizontal square over horizontal ground casts a congruent square under any
// directional light, shifted by h / tan(elevation). Seen straight down, that is
// side^2 / pixel^2 pixels, centred under the square minus the shift.
TEST(ShadowOracle, SquareShadowUnderObliqueSunHasTheSquaresArea)
{
  View view;
  AddGround(view, 15.0);
  const double side = 3.0, height = 5.0;
  const glm::dvec3 centre(2.0, 1.0, height);
  vtkActor* occluder = view.Add(Square(side));
  occluder->SetPosition(centre.x, centre.y, centre.z);
  occluder->RotateZ(30.0); // the transform must reach the oracle
  const double elevation = 45.0;
  vtkLight* sun = view.SetSun(TowardLight(0.0, elevation));
  const double halfHeight = 10.0;
  view.LookDown({ 0.0, 0.0 }, halfHeight);

  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const Tally tally = Count(surface, oracle.Classify(surface, sun));

  const double pixel = 2.0 * halfHeight / ImageSize;
  const double expected = side * side / (pixel * pixel);
  Report("square shadow, oblique sun (pixels)", tally.Shadowed, expected);
  EXPECT_NEAR(tally.Shadowed, expected, AreaTolerance);
  const glm::dvec2 shadowCentre(centre.x - height / std::tan(glm::radians(elevation)), centre.y);
  Report("square shadow centroid error (pixels)",
    glm::length(glm::dvec2(tally.ShadowCentroid) - shadowCentre) / pixel, 0.0);
  EXPECT_LT(glm::length(glm::dvec2(tally.ShadowCentroid) - shadowCentre), 0.5 * pixel);
  EXPECT_NEAR(tally.ShadowCentroid.z, 0.0, 1e-9) << "only the ground is shadowed";

  // Stricter than the area: the pixel centres that fall in the shadow square.
  int centresInShadow = 0;
  for (int y = 0; y < ImageSize; ++y)
  {
    for (int x = 0; x < ImageSize; ++x)
    {
      centresInShadow += InSquare(GroundAtPixel(x, y, { 0.0, 0.0 }, halfHeight), shadowCentre,
        side, 30.0);
    }
  }
  Report("square shadow vs pixel centres in the analytic shadow", tally.Shadowed,
    centresInShadow);
  EXPECT_NEAR(tally.Shadowed, centresInShadow, 2);
}

// Light straight down: the shadow lies right under the square. A camera looking
// straight down would see none of it (the square hides it), so this camera is
// tilted to elevation 60 degrees: parallel projection shrinks the ground's
// screen-vertical extent by sin(60), and the square floats high enough that
// its image does not overlap its shadow's.
TEST(ShadowOracle, SquareShadowUnderOverheadSunSeenObliquely)
{
  View view;
  AddGround(view, 15.0);
  const double side = 3.0, height = 8.0;
  vtkActor* occluder = view.Add(Square(side));
  occluder->SetPosition(2.0, 1.0, height);
  occluder->RotateZ(30.0);
  vtkLight* sun = view.SetSun({ 0.0, 0.0, 1.0 });
  const double elevation = glm::radians(60.0), halfHeight = 10.0;
  // Screen-vertical extent of the rotated square's shadow versus the square's
  // screen offset above it: they must not overlap.
  ASSERT_LT(side * (std::cos(glm::radians(30.0)) + std::sin(glm::radians(30.0))) *
      std::sin(elevation),
    height * std::cos(elevation));
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.0, 2.0, 0.0);
  camera->SetPosition(0.0, 2.0 - 40.0 * std::cos(elevation), 40.0 * std::sin(elevation));
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->OrthogonalizeViewUp();
  camera->SetParallelScale(halfHeight);
  view.Renderer->ResetCameraClippingRange();

  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const Tally tally = Count(surface, oracle.Classify(surface, sun));

  const double pixel = 2.0 * halfHeight / ImageSize;
  const double expected = side * side * std::sin(elevation) / (pixel * pixel);
  Report("square shadow, overhead sun, camera at 60 degrees (pixels)", tally.Shadowed, expected);
  EXPECT_NEAR(tally.Shadowed, expected, AreaTolerance);
  EXPECT_LT(glm::length(glm::dvec2(tally.ShadowCentroid) - glm::dvec2(2.0, 1.0)), 0.5 * pixel);
}

// A sphere's shadow under a sun at elevation e is an ellipse of area
// pi r^2 / sin(e). The tessellated sphere's shadow is the convex hull of its
// vertices projected along the light, which is what the expected area is
// computed from; the ellipse is only reported (and must be close).
TEST(ShadowOracle, SphereShadowUnderObliqueSunIsTheProjectedSilhouette)
{
  View view;
  AddGround(view, 15.0);
  const double radius = 1.5, elevationDeg = 50.0;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(3.0, 2.0, 5.0);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(96);
  view.Add(sphere);
  const glm::dvec3 towardLight = TowardLight(20.0, elevationDeg);
  vtkLight* sun = view.SetSun(towardLight);
  const double halfHeight = 10.0;
  view.LookDown({ 0.0, 0.0 }, halfHeight);

  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const Tally tally = Count(surface, oracle.Classify(surface, sun));

  sphere->Update();
  std::vector<glm::dvec2> projected;
  vtkPoints* points = sphere->GetOutput()->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const glm::dvec3 onGround = glm::dvec3(p[0], p[1], p[2]) - (p[2] / towardLight.z) * towardLight;
    projected.emplace_back(onGround.x, onGround.y);
  }
  const double pixel = 2.0 * halfHeight / ImageSize;
  const double expected = ConvexHullArea(projected) / (pixel * pixel);
  const double ellipse =
    Pi * radius * radius / std::sin(glm::radians(elevationDeg)) / (pixel * pixel);
  Report("sphere shadow (pixels) vs tessellated silhouette", tally.Shadowed, expected);
  Report("tessellated silhouette vs ellipse pi r^2 / sin(e) (pixels)", expected, ellipse);
  EXPECT_NEAR(tally.Shadowed, expected, AreaTolerance);
  EXPECT_NEAR(expected, ellipse, 0.01 * ellipse);
}

// A point light inside a closed 10 x 10 x 6 room, a horizontal square between
// it and the floor: the floor shadow is the square scaled about the light by
// k = light height / (light height - square height), by similar triangles.
// The camera looks down from just under the ceiling, which the near plane
// clips (it stays in the BVH as an occluder). The square's own image lies
// inside its shadow, so the visible shadow is (k^2 - 1) side^2.
TEST(ShadowOracle, PointLightInClosedRoomCastsSimilarTriangles)
{
  View view;
  vtkNew<vtkCubeSource> room;
  room->SetCenter(0.0, 0.0, 3.0);
  room->SetXLength(10.0);
  room->SetYLength(10.0);
  room->SetZLength(6.0);
  view.Add(room);
  const double side = 2.0, squareHeight = 3.0;
  const glm::dvec3 lightPosition(0.5, -0.3, 5.0);
  const glm::dvec3 squareCentre(0.8, -0.1, squareHeight);
  vtkActor* occluder = view.Add(Square(side));
  occluder->SetPosition(squareCentre.x, squareCentre.y, squareCentre.z);
  occluder->RotateZ(20.0); // edges off the pixel grid: counts converge to areas
  vtkLight* bulb = view.SetLight(lightPosition, glm::dvec3(0.0), true, 180.0);

  const double halfHeight = 5.2;
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0.0, 0.0, 5.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(halfHeight);
  camera->SetClippingRange(0.1, 6.0); // ceiling (depth -0.5) clipped, floor at 5.5 kept

  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const Tally tally = Count(surface, oracle.Classify(surface, bulb));

  const double k = lightPosition.z / (lightPosition.z - squareHeight);
  ASSERT_LE(glm::length(glm::dvec2(squareCentre - lightPosition)) * (k - 1.0) + 0.5 * side,
    0.5 * k * side)
    << "the square's image must lie inside its shadow";
  const double pixel = 2.0 * halfHeight / ImageSize;
  const double expected = (k * k - 1.0) * side * side / (pixel * pixel);
  Report("point light in a room (pixels)", tally.Shadowed, expected);
  EXPECT_NEAR(tally.Shadowed, expected, AreaTolerance);
  // Centroid of the visible part: the shadow's minus the square's image.
  const glm::dvec2 shadowCentre =
    glm::dvec2(lightPosition) + k * (glm::dvec2(squareCentre) - glm::dvec2(lightPosition));
  const glm::dvec2 visibleCentre =
    (k * k * shadowCentre - glm::dvec2(squareCentre)) / (k * k - 1.0);
  Report("point light in a room: centroid error (pixels)",
    glm::length(glm::dvec2(tally.ShadowCentroid) - visibleCentre) / pixel, 0.0);
  EXPECT_LT(glm::length(glm::dvec2(tally.ShadowCentroid) - visibleCentre), 0.5 * pixel);

  // The clipped ceiling still occludes: a light above it shadows the whole floor.
  vtkLight* above = view.SetLight({ 0.5, -0.3, 7.0 }, glm::dvec3(0.0), true, 180.0);
  const Tally outside = Count(surface, oracle.Classify(surface, above));
  EXPECT_EQ(outside.Lit, 0);
  EXPECT_GT(outside.Shadowed, ImageSize * ImageSize / 2);
}

//------------------------------------------------------------------------------
// Classification rules

TEST(ShadowOracle, SpotLightOutsideItsConeIsIgnored)
{
  View view;
  AddGround(view, 15.0);
  const glm::dvec3 spotPosition(1.0, 2.0, 6.0);
  const double cone = 20.0;
  vtkLight* spot = view.SetLight(spotPosition, { 1.0, 2.0, 0.0 }, true, cone);
  const double halfHeight = 10.0;
  view.LookDown({ 0.0, 0.0 }, halfHeight);

  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const std::vector<Truth> truth = oracle.Classify(surface, spot);
  const double pixel = 2.0 * halfHeight / ImageSize;
  const double coneRadius = spotPosition.z * std::tan(glm::radians(cone));
  int wrongInside = 0, wrongOutside = 0;
  for (std::size_t i = 0; i < truth.size(); ++i)
  {
    if (!surface.Valid[i])
    {
      continue;
    }
    const double distance = glm::length(glm::dvec2(surface.Position[i]) - glm::dvec2(1.0, 2.0));
    wrongInside += distance < coneRadius - pixel && truth[i] != Truth::Lit;
    wrongOutside += distance > coneRadius + pixel && truth[i] != Truth::Ignored;
  }
  EXPECT_EQ(wrongInside, 0);
  EXPECT_EQ(wrongOutside, 0);
  const Tally tally = Count(surface, truth);
  const double expected = Pi * coneRadius * coneRadius / (pixel * pixel);
  Report("spot cone footprint (pixels)", tally.Lit, expected);
  EXPECT_NEAR(tally.Lit, expected, AreaTolerance);
}

TEST(ShadowOracle, SurfacesTurnedFromTheLightAreIgnored)
{
  View view;
  AddGround(view, 15.0);
  view.LookDown({ 0.0, 0.0 }, 10.0);
  Oracle oracle;
  const Surface surface = view.RenderAndTrace(oracle);
  const int valid = CountValid(surface);
  ASSERT_EQ(valid, ImageSize * ImageSize);

  vtkLight* below = view.SetSun({ 0.3, 0.2, -1.0 });
  EXPECT_EQ(Count(surface, oracle.Classify(surface, below)).Ignored, valid)
    << "the camera sees the ground's upper side, the light its lower side";

  vtkLight* grazing = view.SetSun(TowardLight(10.0, glm::degrees(std::asin(0.05))));
  EXPECT_EQ(Count(surface, oracle.Classify(surface, grazing)).Ignored, valid)
    << "N.L = 0.05 is below the default minimum cosine 0.1";
  EXPECT_EQ(Count(surface, oracle.Classify(surface, grazing, 0.0)).Lit, valid)
    << "the same light with a minimum cosine of 0";

  vtkLight* low = view.SetSun(TowardLight(10.0, glm::degrees(std::asin(0.2))));
  EXPECT_EQ(Count(surface, oracle.Classify(surface, low)).Lit, valid);
}

//------------------------------------------------------------------------------
// Building

TEST(ShadowOracle, BuildFailsCleanlyWithoutGeometry)
{
  View view;
  Oracle oracle;
  std::string error;
  EXPECT_FALSE(oracle.Build(view.Renderer, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(oracle.GetNumberOfTriangles(), 0u);

  // Nothing the oracle may use: a non-caster, a translucent and a hidden actor.
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  view.Add(sphere)->SetPropertyKeys(keys);
  view.Add(sphere)->GetProperty()->SetOpacity(0.5);
  view.Add(sphere)->VisibilityOff();
  error.clear();
  EXPECT_FALSE(oracle.Build(view.Renderer, error));
  EXPECT_FALSE(error.empty());
  std::cout << "[ measured ] Build error: " << error << '\n';

  const Surface surface = oracle.Trace(view.Renderer, 64, 64);
  EXPECT_EQ(CountValid(surface), 0) << "a failed oracle traces nothing";
  EXPECT_EQ(surface.Valid.size(), 64u * 64u);
}

TEST(ShadowOracle, BuildTakesCompositeBlocksGlyphsAndTransformsOnly)
{
  View view;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-3.0, 0.0, 1.5);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  sphere->Update();
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  const vtkIdType sphereTriangles = sphere->GetOutput()->GetNumberOfPolys();

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, sphere->GetOutput());
  blocks->SetBlock(1, cube->GetOutput());
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockVisibility(cube->GetOutput(), false);
  vtkNew<vtkShadowCompositeMapper> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  compositeMapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(compositeMapper);
  view.Renderer->AddActor(compositeActor);

  // Three cubes, scaled by a scalar and turned by a direction array.
  vtkNew<vtkPolyData> glyphPoints;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> scale, direction;
  scale->SetName("scale");
  direction->SetName("direction");
  direction->SetNumberOfComponents(3);
  for (int i = 0; i < 3; ++i)
  {
    points->InsertNextPoint(2.0 + 1.5 * i, -1.0 + i, 1.0);
    scale->InsertNextValue(0.6 + 0.3 * i);
    direction->InsertNextTuple3(1.0, 0.5 * i, 0.3);
  }
  glyphPoints->SetPoints(points);
  glyphPoints->GetPointData()->AddArray(scale);
  glyphPoints->GetPointData()->AddArray(direction);
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputData(glyphPoints);
  glyphMapper->SetSourceConnection(cube->GetOutputPort());
  glyphMapper->SetScaleArray("scale");
  glyphMapper->SetScaleModeToScaleByMagnitude();
  glyphMapper->SetOrientationArray("direction");
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphMapper);
  glyphActor->SetPosition(0.0, 1.0, 0.5);
  glyphActor->RotateZ(15.0);
  view.Renderer->AddActor(glyphActor);

  vtkActor* ground = AddGround(view, 8.0);
  vtkActor* nonCaster = view.Add(sphere);
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  nonCaster->SetPropertyKeys(keys);
  nonCaster->SetPosition(0.0, 5.0, 0.0);

  Oracle oracle;
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;
  // Sphere block (the cube block is hidden), three glyph cubes of 12
  // triangles, the 4 x 4 ground of 32 triangles; not the non-caster.
  EXPECT_EQ(oracle.GetNumberOfTriangles(),
    static_cast<std::size_t>(sphereTriangles + 3 * 12 + 32));

  // The same geometry as the rasteriser: a perspective view of it all, where
  // the oracle and the z-buffer must agree everywhere but on silhouettes and
  // on the non-caster.
  nonCaster->VisibilityOff();
  ground->VisibilityOff(); // only the objects, so that silhouettes are few
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->SetPosition(4.0, -14.0, 9.0);
  camera->SetFocalPoint(0.5, 0.0, 1.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  view.Renderer->ResetCameraClippingRange();
  const std::vector<float> depth = view.RenderDepth();
  const int* size = view.Renderer->GetSize();
  Surface surface = oracle.Trace(view.Renderer, size[0], size[1]);
  const int rasterised =
    static_cast<int>(std::count_if(depth.begin(), depth.end(), [](float z) { return z < 1.0f; }));
  const int traced = CountValid(surface);
  Oracle::MaskRasterMismatch(surface, view.Renderer, depth);
  const int kept = CountValid(surface);
  Report("objects: traced pixels vs rasterised pixels", traced, rasterised);
  Report("objects: pixels kept by MaskRasterMismatch vs rasterised", kept, rasterised);
  EXPECT_NEAR(traced, rasterised, 0.01 * rasterised);
  EXPECT_GT(kept, 0.98 * rasterised);
}

TEST(ShadowOracle, GlyphSettingsVtkGlyph3DCannotReproduceAreSkippedWithAWarning)
{
  View view;
  AddGround(view, 8.0);
  vtkNew<vtkPolyData> glyphPoints;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 1.0);
  vtkNew<vtkDoubleArray> rotation;
  rotation->SetName("rotation");
  rotation->SetNumberOfComponents(4);
  rotation->InsertNextTuple4(0.9, 0.1, 0.3, 0.2);
  glyphPoints->SetPoints(points);
  glyphPoints->GetPointData()->AddArray(rotation);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputData(glyphPoints);
  glyphMapper->SetSourceConnection(cube->GetOutputPort());
  glyphMapper->SetOrientationArray("rotation");
  glyphMapper->SetOrientationModeToQuaternion();
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphMapper);
  view.Renderer->AddActor(glyphActor);

  Oracle oracle;
  std::string error;
  testing::internal::CaptureStderr();
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(oracle.GetNumberOfTriangles(), 32u) << "the ground only";
  EXPECT_NE(warnings.find("vtkGlyph3DMapper"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("skipped"), std::string::npos) << warnings;
}

//------------------------------------------------------------------------------
// Agreement with the rasteriser

// Built with a box the render does not show, rendered with a sphere the oracle
// does not have: both must be dropped, the plain ground kept.
TEST(ShadowOracle, MaskRasterMismatchKeepsInteriorAndDropsWhatTheRasterDidNotDraw)
{
  View view;
  AddGround(view, 7.0);
  vtkNew<vtkCubeSource> box;
  box->SetCenter(8.5, 0.0, 0.5);
  box->SetXLength(2.0);
  box->SetYLength(2.0);
  box->SetZLength(1.0);
  vtkActor* boxActor = view.Add(box);
  const double halfHeight = 10.0;
  view.LookDown({ 0.0, 0.0 }, halfHeight);
  Oracle oracle;
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;

  boxActor->VisibilityOff();
  vtkNew<vtkSphereSource> sphere;
  const glm::dvec2 sphereCentre(-3.0, 0.0);
  const double sphereRadius = 1.5;
  sphere->SetCenter(sphereCentre.x, sphereCentre.y, 2.0);
  sphere->SetRadius(sphereRadius);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  view.Add(sphere);
  const std::vector<float> depth = view.RenderDepth();
  Surface surface = oracle.Trace(view.Renderer, ImageSize, ImageSize);
  const Surface traced = surface;
  Oracle::MaskRasterMismatch(surface, view.Renderer, depth);

  const double margin = 2.0 * 2.0 * halfHeight / ImageSize;
  int ground = 0, groundKept = 0, boxSeen = 0, boxDropped = 0, sphereSeen = 0, sphereDropped = 0;
  for (int y = 0; y < ImageSize; ++y)
  {
    for (int x = 0; x < ImageSize; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * ImageSize + x;
      const glm::dvec2 p = GroundAtPixel(x, y, { 0.0, 0.0 }, halfHeight);
      const double toSphere = glm::length(p - sphereCentre);
      if (toSphere < sphereRadius - margin)
      {
        ++sphereSeen;
        sphereDropped += !surface.Valid[i];
      }
      else if (toSphere > sphereRadius + margin && std::abs(p.x) < 7.0 - margin &&
        std::abs(p.y) < 7.0 - margin)
      {
        ++ground;
        groundKept += surface.Valid[i];
      }
      else if (std::abs(p.x - 8.5) < 1.0 - margin && std::abs(p.y) < 1.0 - margin)
      {
        ++boxSeen;
        boxDropped += traced.Valid[i] && !surface.Valid[i];
      }
    }
  }
  Report("interior ground pixels kept", groundKept, ground);
  EXPECT_EQ(groundKept, ground);
  EXPECT_EQ(sphereDropped, sphereSeen) << "the oracle lacks the sphere";
  EXPECT_EQ(boxDropped, boxSeen) << "the rasteriser drew no box: background";
  EXPECT_GT(boxSeen, 1000);
  EXPECT_GT(sphereSeen, 3000);
}

// Rays must hit the points the rasteriser drew at the same pixel centres, in a
// renderer that covers the right half of a non-square window. The error is
// also expressed in pixels: the depth error over the depth change per pixel on
// sloped surfaces (the oblique ground, the sphere, the box sides).
void ExpectRaysHitTheRasterisedPoints(bool parallel)
{
  const std::string name = parallel ? "parallel" : "perspective";
  View view(1024, 384);
  view.Renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
  AddGround(view, 15.0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.0, 2.5);
  sphere->SetRadius(1.5);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  view.Add(sphere);
  vtkNew<vtkCubeSource> box;
  box->SetXLength(2.0);
  box->SetYLength(3.0);
  box->SetZLength(1.5);
  vtkActor* boxActor = view.Add(box);
  boxActor->SetPosition(4.0, -2.0, 0.75);
  boxActor->RotateZ(25.0);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->SetPosition(14.0, -18.0, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 1.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(7.0);
  view.Renderer->ResetCameraClippingRange();

  std::vector<float> depth;
  Oracle oracle;
  Surface surface = view.RenderAndTrace(oracle, &depth);
  const int* size = view.Renderer->GetSize();
  ASSERT_EQ(size[0], 512);
  ASSERT_EQ(size[1], 384);

  // Interior pixels: kept, with all eight neighbours kept.
  auto kept = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < size[0] && y < size[1] &&
      surface.Valid[static_cast<std::size_t>(y) * size[0] + x];
  };
  auto interiorPixel = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        if (!kept(x + dx, y + dy))
        {
          return false;
        }
      }
    }
    return true;
  };
  const std::vector<glm::dvec3> rasterPoints = RasterPoints(view.Renderer, depth);
  const double* position = camera->GetPosition();
  const double* projection = camera->GetDirectionOfProjection();
  const glm::dvec3 eye(position[0], position[1], position[2]);
  const glm::dvec3 forward =
    glm::normalize(glm::dvec3(projection[0], projection[1], projection[2]));
  auto rasterDepth = [&](int x, int y) {
    return glm::dot(rasterPoints[static_cast<std::size_t>(y) * size[0] + x] - eye, forward);
  };
  int interior = 0, sloped = 0;
  double worstRelative = 0.0, sumRelative = 0.0, worstShift = 0.0, sumShift = 0.0;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      if (!interiorPixel(x, y))
      {
        continue;
      }
      const std::size_t i = static_cast<std::size_t>(y) * size[0] + x;
      const double relative =
        glm::length(rasterPoints[i] - surface.Position[i]) / surface.ViewDepth[i];
      worstRelative = std::max(worstRelative, relative);
      sumRelative += relative;
      ++interior;
      // The same error in pixels: depth error over the depth change per pixel,
      // where the surface is sloped enough for that to be meaningful.
      const double perPixel = 0.5 *
        std::max(std::abs(rasterDepth(x + 1, y) - rasterDepth(x - 1, y)),
          std::abs(rasterDepth(x, y + 1) - rasterDepth(x, y - 1)));
      if (perPixel > 1e-3 * surface.ViewDepth[i])
      {
        const double shift = std::abs(rasterDepth(x, y) - surface.ViewDepth[i]) / perPixel;
        worstShift = std::max(worstShift, shift);
        sumShift += shift;
        ++sloped;
      }
    }
  }
  const int rasterised =
    static_cast<int>(std::count_if(depth.begin(), depth.end(), [](float z) { return z < 1.0f; }));
  Report(name + ": interior pixels vs rasterised pixels", interior, rasterised);
  Report(name + ": worst |ray hit - z-buffer point| / depth", worstRelative, 0.0);
  Report(name + ": mean |ray hit - z-buffer point| / depth", sumRelative / interior, 0.0);
  Report(name + ": sloped pixels", sloped, 0.0);
  Report(name + ": worst error in pixels on sloped surfaces", worstShift, 0.0);
  Report(name + ": mean error in pixels on sloped surfaces", sumShift / sloped, 0.0);
  EXPECT_GT(interior, 0.95 * rasterised);
  EXPECT_LT(worstRelative, 1e-4);
  EXPECT_GT(sloped, 0.5 * interior);
  EXPECT_LT(worstShift, 0.1);
}

TEST(ShadowOracle, PerspectiveRaysHitTheRasterisedPoints)
{
  ExpectRaysHitTheRasterisedPoints(false);
}

TEST(ShadowOracle, ParallelRaysHitTheRasterisedPoints)
{
  ExpectRaysHitTheRasterisedPoints(true);
}

TEST(ShadowOracle, MovedOracleStillTraces)
{
  View view;
  AddGround(view, 15.0);
  view.LookDown({ 0.0, 0.0 }, 10.0);
  view.RenderDepth();
  Oracle built;
  std::string error;
  ASSERT_TRUE(built.Build(view.Renderer, error)) << error;
  Oracle moved(std::move(built));
  EXPECT_EQ(CountValid(moved.Trace(view.Renderer, 32, 32)), 32 * 32);
  Oracle assigned;
  assigned = std::move(moved);
  EXPECT_EQ(CountValid(assigned.Trace(view.Renderer, 32, 32)), 32 * 32);
}

// Occluders counted along shadow rays: two stacked squares over the ground
// under an overhead sun, the surface a grid of ground points (the squares hide
// what is under them from any camera above). Under the small high square both
// are met; under the large low one alone one is; lit ground none.
TEST(ShadowOracle, CountOccludersAlongShadowRays)
{
  View view;
  AddGround(view, 15.0);
  vtkActor* high = view.Add(Square(2.0));
  high->SetPosition(0.0, 0.0, 0.6);
  vtkActor* low = view.Add(Square(6.0));
  low->SetPosition(0.0, 0.0, 0.3);
  vtkLight* sun = view.SetSun({ 0.0, 0.0, 1.0 });
  view.LookDown({ 0.0, 0.0 }, 5.0);
  view.Window->Render();
  Oracle oracle;
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;

  Surface surface;
  surface.Width = 41;
  surface.Height = 41;
  for (int y = 0; y < surface.Height; ++y)
  {
    for (int x = 0; x < surface.Width; ++x)
    {
      surface.Valid.push_back(1);
      surface.Position.emplace_back(-5.0 + 0.25 * x + 0.01, -5.0 + 0.25 * y + 0.01, 0.0);
      surface.Normal.emplace_back(0.0, 0.0, 1.0);
      surface.ViewDepth.push_back(1.0);
    }
  }
  const std::vector<Truth> truth = oracle.Classify(surface, sun);
  const std::vector<unsigned char> counts = oracle.CountOccluders(surface, sun, truth);
  ASSERT_EQ(counts.size(), truth.size());
  int none = 0;
  int one = 0;
  int two = 0;
  for (size_t i = 0; i < counts.size(); ++i)
  {
    const double x = std::abs(surface.Position[i].x);
    const double y = std::abs(surface.Position[i].y);
    const int expected = std::max(x, y) < 1.0 ? 2 : std::max(x, y) < 3.0 ? 1 : 0;
    EXPECT_EQ(counts[i], expected) << surface.Position[i].x << ", " << surface.Position[i].y;
    EXPECT_EQ(truth[i], expected > 0 ? Truth::Shadowed : Truth::Lit);
    none += expected == 0 ? 1 : 0;
    one += expected == 1 ? 1 : 0;
    two += expected == 2 ? 1 : 0;
  }
  EXPECT_GT(two, 20);
  EXPECT_GT(one, 20);
  EXPECT_GT(none, 20);
  // Capped at `most`.
  const std::vector<unsigned char> capped = oracle.CountOccluders(surface, sun, truth, 1);
  EXPECT_EQ(*std::max_element(capped.begin(), capped.end()), 1);
}

// --- sized lights ----------------------------------------------------------------

namespace
{
/// The fraction of a uniform unit disc on the side u < c of a line (c in
/// units of the disc's radius).
double DiscFractionBelow(double c)
{
  c = std::max(-1.0, std::min(1.0, c));
  return 0.5 + (c * std::sqrt(1.0 - c * c) + std::asin(c)) / Pi;
}

/// Ground points (z = 0, normal +z) along x from x0 to x1 at y = 0.1.
Surface GroundLine(double x0, double x1, int count)
{
  Surface surface;
  surface.Width = count;
  surface.Height = 1;
  for (int i = 0; i < count; ++i)
  {
    surface.Valid.push_back(1);
    surface.Position.emplace_back(x0 + (x1 - x0) * i / (count - 1.0), 0.1, 0.0);
    surface.Normal.emplace_back(0.0, 0.0, 1.0);
    surface.ViewDepth.push_back(1.0);
  }
  return surface;
}

void SetLightSize(vtkLight* light, double size)
{
  light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), size);
}

/// A half-plane occluder, x < 0 at height `height`, over a ground.
vtkActor* AddEdgeOverGround(View& view, double height)
{
  AddGround(view, 30.0);
  vtkNew<vtkPlaneSource> half;
  half->SetOrigin(-30.0, -30.0, height);
  half->SetPoint1(0.0, -30.0, height);
  half->SetPoint2(-30.0, 30.0, height);
  return view.Add(half);
}

/// Under an overhead sun of `diameter` degrees, the camera looking down,
/// rendered once: the oracle of the view's casters.
Oracle BuildUnderOverheadSun(View& view, vtkLight*& sun, double diameter = 0.0)
{
  sun = view.SetSun({ 0.0, 0.0, 1.0 });
  SetLightSize(sun, diameter);
  view.LookDown({ 0.0, 0.0 }, 5.0);
  view.Window->Render();
  Oracle oracle;
  std::string error;
  EXPECT_TRUE(oracle.Build(view.Renderer, error)) << error;
  return oracle;
}

/// The x (by linear interpolation) where the visibility along a GroundLine
/// first reaches `level`.
double WhereVisibilityReaches(const Surface& surface, const std::vector<float>& visibility, float level)
{
  for (std::size_t i = 1; i < visibility.size(); ++i)
  {
    if (visibility[i - 1] < level && visibility[i] >= level)
    {
      const double t = (level - visibility[i - 1]) / (visibility[i] - visibility[i - 1]);
      return surface.Position[i - 1].x + t * (surface.Position[i].x - surface.Position[i - 1].x);
    }
  }
  return std::nan("");
}
} // namespace

TEST(ShadowAreaLight, ConeSamplesAreUniformOverTheSolidAngleAndEndOnTheSphere)
{
  const glm::dvec3 point(0.3, -0.2, 0.1);
  const glm::dvec3 centre(1.0, 2.0, 6.0);
  const double radius = 1.5;
  const auto cone = shadowarealight::SphereCone(point, centre, radius);
  ASSERT_FALSE(cone.Inside);
  const double halfAngle = std::acos(cone.CosHalfAngle);
  EXPECT_NEAR(std::sin(halfAngle), radius / glm::length(centre - point), 1e-12);
  // Stratified: the fraction within half the cone's solid angle is close to
  // one half, far closer than independent samples would give.
  const double cosHalfSolidAngle = 1.0 - 0.5 * (1.0 - cone.CosHalfAngle);
  int inner = 0;
  for (int i = 0; i < 256; ++i)
  {
    const auto ray = shadowarealight::SampleCone(cone, point, i, 16, 77);
    const double cosine = glm::dot(ray.Direction, cone.Axis);
    EXPECT_GE(cosine, cone.CosHalfAngle - 1e-12);
    inner += cosine >= cosHalfSolidAngle;
    EXPECT_NEAR(glm::length(point + ray.Length * ray.Direction - centre), radius, 1e-9);
  }
  EXPECT_NEAR(inner, 128, 8);
  // The sun: the half angle is half the diameter; rays do not end.
  const auto sun = shadowarealight::SunCone({ 0.0, 0.0, 2.0 }, 2.0);
  EXPECT_NEAR(std::acos(sun.CosHalfAngle), glm::radians(1.0), 1e-12);
  EXPECT_TRUE(std::isinf(shadowarealight::SampleCone(sun, point, 3, 16, 1).Length));
  // Inside a sphere light.
  EXPECT_TRUE(shadowarealight::SphereCone(centre, centre + 0.5, radius).Inside);
}

TEST(ShadowOracle, SunPenumbraOfAnEdgeIsTheDiscSegment)
{
  View view;
  const double height = 4.0;
  AddEdgeOverGround(view, height);
  const double diameter = 3.0; // degrees
  vtkLight* sun = nullptr;
  const Oracle oracle = BuildUnderOverheadSun(view, sun, diameter);

  const double penumbraHalf = height * std::tan(glm::radians(0.5 * diameter));
  const Surface surface = GroundLine(-2.0 * penumbraHalf, 2.0 * penumbraHalf, 201);
  shadoworacle::VisibilityRays rays;
  const std::vector<float> visibility = oracle.Visibility(surface, sun, 0.1, &rays);
  double worst = 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    // From x, the edge is at angle atan(x / height) off the sun's centre;
    // the light beyond it (toward +x) is what reaches the ground.
    const double c = std::atan(surface.Position[i].x / height) / glm::radians(0.5 * diameter);
    const double expected = DiscFractionBelow(c);
    worst = std::max(worst, std::abs(visibility[i] - expected));
    sum += std::abs(visibility[i] - expected);
  }
  Report("sun penumbra: worst |visibility - disc segment|", worst, 0.0);
  Report("sun penumbra: mean |visibility - disc segment|", sum / visibility.size(), 0.0);
  EXPECT_LT(worst, 0.025);
  EXPECT_LT(sum / visibility.size(), 0.005);
  EXPECT_EQ(visibility.front(), 0.0f);
  EXPECT_EQ(visibility.back(), 1.0f);
  // 10-90% width: the segment's, where the disc fraction is 0.1 and 0.9:
  // 2 * 0.68705 of the penumbra's half width.
  const double width =
    WhereVisibilityReaches(surface, visibility, 0.9f) - WhereVisibilityReaches(surface, visibility, 0.1f);
  EXPECT_NEAR(DiscFractionBelow(0.68705), 0.9, 1e-5);
  Report("sun penumbra 10-90% width", width, 2.0 * 0.68705 * penumbraHalf);
  EXPECT_NEAR(width, 2.0 * 0.68705 * penumbraHalf, 0.03 * penumbraHalf);
  EXPECT_EQ(rays.Counted, 201);
  EXPECT_EQ(rays.FewestAtPartial, Oracle::RefinedRays);
  EXPECT_GT(rays.Refined, 90);
  EXPECT_LT(rays.Refined, 201);
}

TEST(ShadowOracle, SphereLightPenumbraOfAnEdgeIsTheDiscSegment)
{
  View view;
  const double edgeHeight = 2.0;
  const double lightHeight = 20.0;
  const double radius = 0.5;
  AddEdgeOverGround(view, edgeHeight);
  vtkLight* lamp = view.SetLight({ 0.0, 0.0, lightHeight }, { 0.0, 0.0, 0.0 }, true);
  SetLightSize(lamp, radius);
  view.LookDown({ 0.0, 0.0 }, 5.0);
  view.Window->Render();
  Oracle oracle;
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;

  // The lamp seen from the ground is nearly a disc of the radius at its
  // height: the edge hides the part of it beyond x = -x (H - h) / h.
  const double scale = edgeHeight / (lightHeight - edgeHeight);
  const double penumbraHalf = radius * scale;
  const Surface surface = GroundLine(-2.0 * penumbraHalf, 2.0 * penumbraHalf, 161);
  const std::vector<float> visibility = oracle.Visibility(surface, lamp);
  double worst = 0.0;
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    const double expected = DiscFractionBelow(surface.Position[i].x / penumbraHalf);
    worst = std::max(worst, std::abs(visibility[i] - expected));
  }
  Report("sphere light penumbra: worst |visibility - disc segment|", worst, 0.0);
  EXPECT_LT(worst, 0.03);
  // Repeatable, and a point inside the lamp sees all of it.
  EXPECT_EQ(oracle.Visibility(surface, lamp), visibility);
  SetLightSize(lamp, lightHeight + 1.0);
  const std::vector<float> inside = oracle.Visibility(surface, lamp);
  EXPECT_TRUE(std::all_of(inside.begin(), inside.end(), [](float v) { return v == 1.0f; }));
}

TEST(ShadowOracle, LightsWithoutASizeGetTheClassification)
{
  View view;
  AddEdgeOverGround(view, 2.0);
  vtkLight* sun = view.SetSun(TowardLight(30.0, 50.0));
  view.LookDown({ 0.0, 0.0 }, 5.0);
  view.Window->Render();
  Oracle oracle;
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;
  Surface surface = GroundLine(-3.0, 3.0, 121);
  surface.Normal[5] = glm::dvec3(0.0, 0.0, -1.0); // turned away: not counted
  for (double size : { 0.0, -2.0, std::nan("") })
  {
    SetLightSize(sun, size);
    EXPECT_EQ(vtkAbstractShadowMapPass::GetLightSize(sun), 0.0);
    shadoworacle::VisibilityRays rays;
    const std::vector<float> visibility = oracle.Visibility(surface, sun, 0.1, &rays);
    const std::vector<Truth> truth = oracle.Classify(surface, sun);
    for (std::size_t i = 0; i < truth.size(); ++i)
    {
      const float expected = truth[i] == Truth::Lit ? 1.0f
        : truth[i] == Truth::Shadowed               ? 0.0f
                                                    : shadoworacle::NotCounted;
      EXPECT_EQ(visibility[i], expected) << i;
    }
    EXPECT_EQ(visibility[5], shadoworacle::NotCounted);
    EXPECT_EQ(rays.Rays, 120);
  }
  bool clamped = false;
  SetLightSize(sun, 45.0);
  EXPECT_EQ(vtkAbstractShadowMapPass::GetLightSize(sun, &clamped), 30.0);
  EXPECT_TRUE(clamped);
  SetLightSize(sun, 0.53);
  EXPECT_EQ(vtkAbstractShadowMapPass::GetLightSize(sun, &clamped), 0.53);
  EXPECT_FALSE(clamped);
}

//------------------------------------------------------------------------------
// Transmittance through translucent casters

namespace
{
/// A horizontal square of `side` centred on (centre, height).
vtkActor* AddSlab(View& view, const glm::dvec2& centre, double side, double height,
  const glm::dvec3& color, double opacity)
{
  vtkActor* slab = view.Add(Square(side, 2));
  slab->SetPosition(centre.x, centre.y, height);
  slab->GetProperty()->SetDiffuseColor(color.x, color.y, color.z);
  slab->GetProperty()->SetOpacity(opacity);
  return slab;
}

/// The ground point at x of a GroundLine(-3, 3, 61): x = -3 + 0.1 i.
std::size_t GroundIndex(double x)
{
  return static_cast<std::size_t>(std::lround((x + 3.0) / 0.1));
}

void ExpectTransmittance(const glm::vec3& measured, const glm::dvec3& expected, double tolerance,
  const std::string& where)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(measured[c], expected[c], tolerance) << where << ", channel " << c;
  }
}
} // namespace

TEST(ShadowOracle, SurfaceTransmittanceIsTheDocumentedModel)
{
  using shadoworacle::SurfaceTransmittance;
  const glm::dvec3 white(1.0);
  for (double a : { 0.0, 0.25, 0.5, 0.75, 1.0 })
  {
    EXPECT_EQ(SurfaceTransmittance(white, a), glm::dvec3(1.0 - a)) << a;
  }
  EXPECT_EQ(SurfaceTransmittance({ 1.0, 0.0, 0.5 }, 0.5), glm::dvec3(0.5, 0.25, 0.375));
  EXPECT_EQ(SurfaceTransmittance({ 0.3, 0.2, 0.1 }, 1.0), glm::dvec3(0.0));
  EXPECT_EQ(SurfaceTransmittance({ 0.3, 0.2, 0.1 }, 0.0), glm::dvec3(1.0));
  // Out of range: clamped.
  EXPECT_EQ(SurfaceTransmittance(white, 2.0), glm::dvec3(0.0));
  EXPECT_EQ(SurfaceTransmittance(white, -1.0), glm::dvec3(1.0));
  EXPECT_EQ(SurfaceTransmittance({ 2.0, -1.0, 1.0 }, 0.5), glm::dvec3(0.5, 0.25, 0.5));
}

TEST(ShadowOracle, TranslucentSlabLetsThroughTheModelsShare)
{
  const glm::dvec3 color(0.9, 0.6, 0.3);
  for (double opacity : { 0.0, 0.25, 0.5, 0.75, 1.0 })
  {
    View view;
    AddGround(view, 8.0);
    AddSlab(view, { 0.0, 0.0 }, 2.0, 1.0, color, opacity);
    vtkLight* sun = nullptr;
    Oracle oracle = BuildUnderOverheadSun(view, sun);
    const Surface surface = GroundLine(-3.0, 3.0, 61);
    const std::vector<glm::vec3> transmittance = oracle.Transmittance(surface, sun);
    const glm::dvec3 expected = shadoworacle::SurfaceTransmittance(color, opacity);
    const std::string what = "opacity " + std::to_string(opacity);
    ExpectTransmittance(transmittance[GroundIndex(0.0)], expected, 1e-6, what + ", under the slab");
    ExpectTransmittance(transmittance[GroundIndex(-0.9)], expected, 1e-6, what + ", under its edge");
    ExpectTransmittance(transmittance[GroundIndex(-1.1)], glm::dvec3(1.0), 0.0, what + ", beside it");
    ExpectTransmittance(transmittance[GroundIndex(2.5)], glm::dvec3(1.0), 0.0, what + ", far off");
    // Opacity 1 is an opaque caster, opacity 0 none; translucent casters
    // never change the classification.
    EXPECT_EQ(oracle.GetNumberOfTranslucentTriangles(), opacity > 0.0 && opacity < 1.0 ? 8u : 0u);
    const std::vector<float> visibility = oracle.Visibility(surface, sun);
    const std::vector<Truth> truth = oracle.Classify(surface, sun);
    for (std::size_t i = 0; i < surface.Valid.size(); ++i)
    {
      const double x = std::abs(surface.Position[i].x);
      if (std::abs(x - 1.0) > 0.05)
      {
        EXPECT_EQ(truth[i] == Truth::Shadowed, opacity == 1.0 && x < 1.0) << what << ", x " << x;
      }
      if (opacity == 1.0)
      {
        EXPECT_EQ(transmittance[i], glm::vec3(visibility[i])) << i;
      }
    }
  }
}

TEST(ShadowOracle, TranslucentLayersMultiplyInEitherOrder)
{
  const glm::dvec3 red(1.0, 0.1, 0.1), blue(0.2, 0.3, 1.0);
  std::vector<std::vector<glm::vec3>> results;
  for (bool redFirst : { true, false })
  {
    View view;
    AddGround(view, 8.0);
    auto addRed = [&] { AddSlab(view, { -0.5, 0.0 }, 2.0, 1.0, red, 0.5); };
    auto addBlue = [&] { AddSlab(view, { 0.5, 0.0 }, 2.0, 2.0, blue, 0.3); };
    redFirst ? (addRed(), addBlue()) : (addBlue(), addRed());
    vtkLight* sun = nullptr;
    Oracle oracle = BuildUnderOverheadSun(view, sun);
    results.push_back(oracle.Transmittance(GroundLine(-3.0, 3.0, 61), sun));
  }
  EXPECT_EQ(results[0], results[1]);
  const glm::dvec3 redShare = shadoworacle::SurfaceTransmittance(red, 0.5);
  const glm::dvec3 blueShare = shadoworacle::SurfaceTransmittance(blue, 0.3);
  const std::vector<glm::vec3>& transmittance = results[0];
  ExpectTransmittance(transmittance[GroundIndex(-1.0)], redShare, 1e-6, "red alone");
  ExpectTransmittance(transmittance[GroundIndex(1.0)], blueShare, 1e-6, "blue alone");
  ExpectTransmittance(transmittance[GroundIndex(0.0)], redShare * blueShare, 1e-6, "both");
  ExpectTransmittance(transmittance[GroundIndex(2.0)], glm::dvec3(1.0), 0.0, "neither");
}

TEST(ShadowOracle, TranslucentColoursComeFromScalarsLookupTablesAndBlocks)
{
  View view;
  AddGround(view, 8.0);
  // Left: point scalars through a one-colour lookup table with alpha, times
  // the actor's opacity. Values in 1/255 steps, as VTK's colours are bytes.
  vtkActor* mapped = AddSlab(view, { -1.5, 0.0 }, 1.0, 1.0, glm::dvec3(1.0), 0.5);
  ColorByOneTableEntry(mapped, 51 / 255.0, 204 / 255.0, 102 / 255.0, 153 / 255.0);

  // Middle: direct RGBA cell colours, one per half; the actor is opaque.
  vtkActor* direct = AddSlab(view, { 0.0, 0.0 }, 1.0, 1.0, glm::dvec3(1.0), 1.0);
  auto* directMapper = vtkPolyDataMapper::SafeDownCast(direct->GetMapper());
  vtkNew<vtkPlaneSource> halves;
  halves->SetOrigin(-0.5, -0.5, 0.0);
  halves->SetPoint1(0.5, -0.5, 0.0);
  halves->SetPoint2(-0.5, 0.5, 0.0);
  halves->SetResolution(2, 1);
  halves->Update();
  vtkNew<vtkPolyData> withCellColors;
  withCellColors->DeepCopy(halves->GetOutput());
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetNumberOfComponents(4);
  rgba->InsertNextTuple4(255, 0, 0, 102);
  rgba->InsertNextTuple4(0, 0, 255, 204);
  withCellColors->GetCellData()->SetScalars(rgba);
  directMapper->SetInputData(withCellColors);
  directMapper->SetColorModeToDirectScalars();
  directMapper->SetScalarVisibility(1);

  // Right: a composite block's opacity and colour.
  vtkNew<vtkPlaneSource> blockSquare;
  blockSquare->SetOrigin(1.0, -0.5, 1.0);
  blockSquare->SetPoint1(2.0, -0.5, 1.0);
  blockSquare->SetPoint2(1.0, 0.5, 1.0);
  blockSquare->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, blockSquare->GetOutput());
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockOpacity(blockSquare->GetOutput(), 0.4);
  attributes->SetBlockColor(blockSquare->GetOutput(), vtkColor3d(0.0, 1.0, 0.0).GetData());
  vtkNew<vtkShadowCompositeMapper> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  compositeMapper->SetCompositeDataDisplayAttributes(attributes);
  compositeMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> compositeActor;
  compositeActor->SetMapper(compositeMapper);
  view.Renderer->AddActor(compositeActor);

  vtkLight* sun = nullptr;
  Oracle oracle = BuildUnderOverheadSun(view, sun);
  const std::vector<glm::vec3> transmittance = oracle.Transmittance(GroundLine(-3.0, 3.0, 61), sun);
  using shadoworacle::SurfaceTransmittance;
  ExpectTransmittance(transmittance[GroundIndex(-1.5)],
    SurfaceTransmittance({ 0.2, 0.8, 0.4 }, 0.3), 1e-6, "lookup table");
  ExpectTransmittance(transmittance[GroundIndex(-0.3)], SurfaceTransmittance({ 1.0, 0.0, 0.0 }, 0.4),
    1e-6, "first cell");
  ExpectTransmittance(transmittance[GroundIndex(0.3)], SurfaceTransmittance({ 0.0, 0.0, 1.0 }, 0.8),
    1e-6, "second cell");
  ExpectTransmittance(transmittance[GroundIndex(1.5)], SurfaceTransmittance({ 0.0, 1.0, 0.0 }, 0.4),
    1e-6, "block");
}

TEST(ShadowOracle, OpaqueCastersBlockWhateverTranslucentOnesAreAbove)
{
  View view;
  AddGround(view, 8.0);
  AddSlab(view, { 0.0, 0.0 }, 4.0, 3.0, { 1.0, 1.0, 1.0 }, 0.5);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(1.0, 0.0, 1.0);
  view.Add(cube);
  vtkActor* optedOut = AddSlab(view, { -1.0, 0.0 }, 1.0, 2.0, { 1.0, 0.0, 0.0 }, 0.5);
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  optedOut->SetPropertyKeys(keys);
  vtkLight* sun = nullptr;
  Oracle oracle = BuildUnderOverheadSun(view, sun);
  const std::vector<glm::vec3> transmittance = oracle.Transmittance(GroundLine(-3.0, 3.0, 61), sun);
  ExpectTransmittance(transmittance[GroundIndex(1.0)], glm::dvec3(0.0), 0.0, "under the cube");
  ExpectTransmittance(transmittance[GroundIndex(-1.0)], glm::dvec3(0.5), 1e-6, "opted-out slab");
  ExpectTransmittance(transmittance[GroundIndex(2.5)], glm::dvec3(1.0), 0.0, "beside the slab");
}

TEST(ShadowOracle, SizedLightsTransmittanceAveragesItsRays)
{
  const double height = 4.0;
  const double diameter = 3.0;
  const double penumbraHalf = height * std::tan(glm::radians(0.5 * diameter));
  const Surface surface = GroundLine(-2.0 * penumbraHalf, 2.0 * penumbraHalf, 201);
  for (double opacity : { 1.0, 0.5 })
  {
    View view;
    AddEdgeOverGround(view, height)->GetProperty()->SetOpacity(opacity);
    vtkLight* sun = nullptr;
    const Oracle oracle = BuildUnderOverheadSun(view, sun, diameter);
    shadoworacle::VisibilityRays rays;
    const std::vector<glm::vec3> transmittance = oracle.Transmittance(surface, sun, 0.1, &rays);
    EXPECT_EQ(rays.FewestAtPartial, Oracle::RefinedRays);
    if (opacity == 1.0)
    {
      // Without translucent casters, every channel is the visibility.
      const std::vector<float> visibility = oracle.Visibility(surface, sun);
      for (std::size_t i = 0; i < surface.Valid.size(); ++i)
      {
        EXPECT_EQ(transmittance[i], glm::vec3(visibility[i])) << i;
      }
      continue;
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < surface.Valid.size(); ++i)
    {
      const double c = std::atan(surface.Position[i].x / height) / glm::radians(0.5 * diameter);
      const double slab = shadoworacle::SurfaceTransmittance(glm::dvec3(1.0), opacity).x;
      const double expected = 1.0 - (1.0 - slab) * (1.0 - DiscFractionBelow(c));
      worst = std::max(worst, std::abs(transmittance[i].x - expected));
      EXPECT_EQ(transmittance[i].x, transmittance[i].y);
    }
    Report("translucent edge under a sun: worst |transmittance - expected|", worst, 0.0);
    EXPECT_LT(worst, 0.02);
  }
}

namespace
{
/// A box of constant scalar 1 filling [-1, 1] x [-1, 1] x [bottom, bottom + 2]
/// (11 samples a side), of constant scalar opacity per `unitDistance` and colour.
vtkSmartPointer<vtkVolume> AddUniformVolume(View& view, double bottom, double opacity,
  double unitDistance, const glm::dvec3& color)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(11, 11, 11);
  image->SetOrigin(-1.0, -1.0, bottom);
  image->SetSpacing(0.2, 0.2, 0.2);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* scalars = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  scalars->FillValue(1.0f);
  vtkNew<vtkPiecewiseFunction> opacities;
  opacities->AddPoint(0.0, opacity);
  opacities->AddPoint(2.0, opacity);
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, color.x, color.y, color.z);
  colors->AddRGBPoint(2.0, color.x, color.y, color.z);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacities);
  property->SetColor(colors);
  property->SetScalarOpacityUnitDistance(unitDistance);
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(image);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  view.Renderer->AddVolume(volume);
  return volume;
}
} // namespace

TEST(ShadowOracle, VolumeOfUniformOpacityLetsThroughItsOpticalDepth)
{
  const double opacity = 0.2;
  const double unitDistance = 0.5;
  const glm::dvec3 color(1.0, 0.5, 0.0);
  View view;
  AddGround(view, 8.0);
  AddUniformVolume(view, 2.0, opacity, unitDistance, color);
  vtkLight* sun = nullptr;
  Oracle oracle = BuildUnderOverheadSun(view, sun);
  ASSERT_EQ(oracle.GetNumberOfVolumes(), 1u);
  const Surface surface = GroundLine(-3.0, 3.0, 61);
  const std::vector<glm::vec3> transmittance = oracle.Transmittance(surface, sun);
  // Two units of the box: the continuous model exp(-sigma L (2 - c)), sigma =
  // -ln(1 - a) / u; white is (1 - a)^(L / u), VTK's compositing.
  const double sigma = -std::log(1.0 - opacity) / unitDistance;
  glm::dvec3 expected;
  for (int c = 0; c < 3; ++c)
  {
    expected[c] = std::exp(-sigma * 2.0 * (2.0 - color[c]));
  }
  EXPECT_NEAR(std::exp(-sigma * 2.0), std::pow(1.0 - opacity, 2.0 / unitDistance), 1e-12);
  ExpectTransmittance(transmittance[GroundIndex(0.0)], expected, 0.005, "under the volume");
  ExpectTransmittance(transmittance[GroundIndex(-0.9)], expected, 0.005, "under its edge");
  ExpectTransmittance(transmittance[GroundIndex(1.5)], glm::dvec3(1.0), 0.0, "beside it");
  // Opted out of casting: nothing.
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  vtkVolume::SafeDownCast(view.Renderer->GetVolumes()->GetLastProp())->SetPropertyKeys(keys);
  std::string error;
  ASSERT_TRUE(oracle.Build(view.Renderer, error)) << error;
  EXPECT_EQ(oracle.GetNumberOfVolumes(), 0u);
}

TEST(ShadowOracle, VolumeClippingPlanesCutWhatItAbsorbs)
{
  const double opacity = 0.2;
  const double unitDistance = 0.5;
  View view;
  AddGround(view, 8.0);
  vtkSmartPointer<vtkVolume> volume = AddUniformVolume(view, 2.0, opacity, unitDistance, glm::dvec3(1.0));
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(1.0, 0.0, 0.0); // keeps x >= 0
  volume->GetMapper()->AddClippingPlane(plane);
  vtkLight* sun = nullptr;
  Oracle oracle = BuildUnderOverheadSun(view, sun);
  const std::vector<glm::vec3> transmittance = oracle.Transmittance(GroundLine(-3.0, 3.0, 61), sun);
  const double expected = std::pow(1.0 - opacity, 2.0 / unitDistance);
  ExpectTransmittance(transmittance[GroundIndex(0.5)], glm::dvec3(expected), 0.005, "kept half");
  ExpectTransmittance(transmittance[GroundIndex(-0.5)], glm::dvec3(1.0), 0.0, "half cut away");
}

TEST(ShadowOracle, SliceTransmittanceIsTheSurfaceModelOfTheCorrectedOpacity)
{
  // A slice one unit distance thick is a surface of the scalar opacity.
  const glm::dvec3 color(0.3, 0.6, 0.9);
  EXPECT_EQ(shadoworacle::SliceTransmittance(color, 0.4, 2.0, 2.0),
    shadoworacle::SurfaceTransmittance(color, 0.4));
  // Two half slices of white make one: (1 - a)^(1/2) twice.
  const glm::dvec3 half = shadoworacle::SliceTransmittance(glm::dvec3(1.0), 0.4, 1.0, 2.0);
  EXPECT_NEAR(half.x * half.x, 0.6, 1e-12);
  EXPECT_EQ(shadoworacle::SliceTransmittance(color, 1.0, 0.01, 2.0), glm::dvec3(0.0));
  EXPECT_EQ(shadoworacle::SliceTransmittance(color, 0.0, 5.0, 2.0), glm::dvec3(1.0));
}
