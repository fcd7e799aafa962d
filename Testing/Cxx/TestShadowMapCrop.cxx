// Unit tests of Plugin/Math/ShadowMapCrop: which views of a light are crops of
// its first. The receivers' shader relies on it for the lights whose views
// strategy promises it (ReceiverFeature CroppedViews: unwarped cascades and a
// spot's tiles), so the fits those strategies use are checked here.
#include "ShadowMapCascades.h"
#include "ShadowMapCrop.h"
#include "ShadowMapFocusing.h"
#include "ShadowMapWarping.h"

#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace
{
using shadowmaps::Aabb;
using shadowmaps::LightView;

constexpr int Resolution = 1024;
// A crop's stray elements are rounding: relative 1e-16 for exact crops.
constexpr double CropTolerance = 1e-9;

glm::dmat4 Texture(const LightView& view)
{
  return shadowmaps::ClipToTexture() * view.ViewProjection();
}

Aabb Street()
{
  return { glm::dvec3(-120.0, -80.0, 0.0), glm::dvec3(150.0, 90.0, 35.0) };
}

// A crop read off two views takes the first view's coordinates of any point to
// the second's, as the shader applies it.
void ExpectCropMapsPoints(const glm::dmat4& first, const glm::dmat4& view, std::mt19937& random)
{
  const shadowmaps::MapCrop crop = shadowmaps::CropBetween(first, view);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
  for (int n = 0; n < 50; ++n)
  {
    const glm::dvec4 p(coordinate(random), coordinate(random), coordinate(random) * 0.2, 1.0);
    const glm::dvec4 q = first * p;
    const glm::dvec4 cropped(glm::dvec3(q) * crop.Scale + q.w * crop.Offset, q.w);
    const glm::dvec4 expected = view * p;
    for (int axis = 0; axis < 4; ++axis)
    {
      EXPECT_NEAR(cropped[axis], expected[axis], 1e-9 * (1.0 + std::abs(expected[axis])));
    }
  }
}

std::vector<glm::dmat4> Cameras()
{
  return { glm::lookAt(glm::dvec3(0.0, -60.0, 12.0), glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0, 0, 1)),
    glm::lookAt(glm::dvec3(40.0, 30.0, 80.0), glm::dvec3(-10.0, 5.0, 0.0), glm::dvec3(0, 0, 1)),
    glm::lookAt(glm::dvec3(-90.0, 10.0, 2.0), glm::dvec3(100.0, -5.0, 3.0), glm::dvec3(0, 0, 1)) };
}

TEST(MapCrop, RecoversACropAndItsMatrix)
{
  const glm::dmat4 first = glm::perspective(glm::radians(50.0), 1.0, 0.5, 90.0) *
    glm::lookAt(glm::dvec3(3.0, -4.0, 20.0), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
  shadowmaps::MapCrop made;
  made.Scale = glm::dvec3(2.5, 0.75, 1.0);
  made.Offset = glm::dvec3(-0.3, 0.4, 0.0);
  const glm::dmat4 view = made.Matrix() * first;
  const shadowmaps::MapCrop read = shadowmaps::CropBetween(first, view);
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_NEAR(read.Scale[axis], made.Scale[axis], 1e-12);
    EXPECT_NEAR(read.Offset[axis], made.Offset[axis], 1e-12);
  }
  EXPECT_LT(shadowmaps::CropError(first, view), CropTolerance);
  EXPECT_LT(shadowmaps::CropError(first, first), CropTolerance);
}

TEST(MapCrop, ReportsWhatIsNotACrop)
{
  const glm::dmat4 first = glm::ortho(-10.0, 10.0, -10.0, 10.0, 0.0, 50.0);
  const glm::dmat4 turned = first * glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 0, 1));
  EXPECT_GT(shadowmaps::CropError(first, turned), 0.1);
  const glm::dmat4 perspective = glm::perspective(glm::radians(40.0), 1.0, 1.0, 50.0);
  EXPECT_GT(shadowmaps::CropError(first, perspective), 0.1);
  glm::dmat4 singular = first;
  singular[2] = glm::dvec4(0.0);
  EXPECT_TRUE(std::isinf(shadowmaps::CropError(singular, first)));
  EXPECT_TRUE(std::isinf(shadowmaps::CropError(first, glm::dmat4(std::nan("")))));
  glm::dmat4 partlyNaN = first;
  partlyNaN[1][0] = std::nan("");
  EXPECT_TRUE(std::isinf(shadowmaps::CropError(first, partlyNaN)));
}

// Stable and tight cascades of a sun: one light rotation, a box each.
TEST(MapCrop, UnwarpedCascadesAreCropsOfTheFirst)
{
  std::mt19937 random(3);
  const glm::dmat4 projection = glm::perspective(glm::radians(60.0), 16.0 / 9.0, 0.5, 400.0);
  const std::vector<double> splits = shadowmaps::PracticalSplits(0.5, 400.0, 4, 0.75);
  for (const glm::dvec3& light : { glm::dvec3(0.3, 0.2, -1.0), glm::dvec3(-0.9, 0.1, -0.2),
         glm::dvec3(0.0, 0.0, -1.0) })
  {
    for (const glm::dmat4& camera : Cameras())
    {
      for (bool stable : { true, false })
      {
        std::vector<glm::dmat4> maps;
        for (size_t c = 0; c + 1 < splits.size(); ++c)
        {
          const glm::dmat4 sub = shadowmaps::SubFrustumProjection(projection, splits[c], splits[c + 1]);
          maps.push_back(Texture(stable
              ? shadowmaps::FitCascadeStable(camera, sub, Street(), light, Resolution)
              : shadowmaps::FitCascadeTight(camera, sub, Street(), light, Resolution)));
        }
        for (const glm::dmat4& map : maps)
        {
          EXPECT_LT(shadowmaps::CropError(maps.front(), map), CropTolerance) << "stable " << stable;
          ExpectCropMapsPoints(maps.front(), map, random);
        }
      }
    }
  }
}

TEST(MapCrop, TilesOfASpotMapAreCropsOfTheFirst)
{
  std::mt19937 random(5);
  const glm::dmat4 camera = glm::perspective(glm::radians(45.0), 1.5, 0.5, 300.0) * Cameras()[0];
  const LightView whole = shadowmaps::FitSpot(
    camera, Street(), glm::dvec3(10.0, -20.0, 40.0), glm::dvec3(-0.2, 0.3, -1.0), 40.0, Resolution);
  const auto tiles =
    shadowmaps::TileView(whole, shadowmaps::MakeTileGrid(2, 2, Resolution, 2.0));
  ASSERT_EQ(tiles.size(), 4u);
  for (const LightView& tile : tiles)
  {
    EXPECT_LT(shadowmaps::CropError(Texture(tiles.front()), Texture(tile)), CropTolerance);
    ExpectCropMapsPoints(Texture(tiles.front()), Texture(tile), random);
  }
}

// Why warped cascades do not promise crops: each warps its own slice.
TEST(MapCrop, WarpedCascadesAreNotCrops)
{
  const glm::dmat4 projection = glm::perspective(glm::radians(60.0), 16.0 / 9.0, 0.5, 400.0);
  const glm::dmat4 camera = Cameras()[0];
  const glm::dvec3 light(0.3, 0.2, -1.0);
  const LightView near = shadowmaps::FitDirectionalWarped(camera,
    shadowmaps::SubFrustumProjection(projection, 0.5, 20.0), Street(), light, Resolution,
    shadowmaps::DirectionalWarp::LiSPSM);
  const LightView far = shadowmaps::FitDirectionalWarped(camera,
    shadowmaps::SubFrustumProjection(projection, 20.0, 400.0), Street(), light, Resolution,
    shadowmaps::DirectionalWarp::LiSPSM);
  EXPECT_GT(shadowmaps::CropError(Texture(near), Texture(far)), 1e-3);
}
} // namespace
