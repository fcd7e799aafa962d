// Unit tests: The tiles of one map that hold a spot light in the cascades' layers (Plugin/Math/ShadowMapFocusing).
#include "FocusingTestHelpers.h"

using namespace focusingtest;

namespace
{
TEST(TileView, TilesPartitionTheMapAndKeepItsCoordinates)
{
  const Aabb scene{ glm::dvec3(-10.0, -10.0, 0.0), glm::dvec3(10.0, 10.0, 2.5) };
  const glm::dmat4 camera = glm::perspective(glm::radians(30.0), 1.0, 0.1, 40.0) *
    glm::lookAt(glm::dvec3(0, -9.5, 1.2), glm::dvec3(0, 0, 0.8), glm::dvec3(0, 0, 1));
  const LightView whole = shadowmaps::FitSpot(
    camera, scene, glm::dvec3(5.0, -2.0, 7.0), glm::dvec3(-0.3, 0.2, -1.0), 30.0, 512);
  constexpr int Columns = 3;
  constexpr int Rows = 2;
  constexpr double Margin = 2.0;
  const shadowmaps::TileGrid grid = shadowmaps::MakeTileGrid(Columns, Rows, 512, Margin);
  const auto tiles = shadowmaps::TileView(whole, grid);
  ASSERT_EQ(tiles.size(), static_cast<size_t>(Columns * Rows));
  const double inset = Margin / 512.0;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> ndc(-0.999, 0.999);
  for (int n = 0; n < 2000; ++n)
  {
    // A point of the whole map's frustum, from its NDC.
    const glm::dvec4 h = glm::inverse(whole.ViewProjection()) * glm::dvec4(ndc(random), ndc(random), ndc(random), 1.0);
    const glm::dvec3 p = glm::dvec3(h) / h.w;
    const glm::dvec4 w = whole.ViewProjection() * glm::dvec4(p, 1.0);
    int inCores = 0;
    for (size_t t = 0; t < tiles.size(); ++t)
    {
      const glm::dvec4 q = tiles[t].ViewProjection() * glm::dvec4(p, 1.0);
      const glm::dvec3 texture = glm::dvec3(q) / q.w * 0.5 + 0.5;
      EXPECT_NEAR(texture.z, (w.z / w.w) * 0.5 + 0.5, 1e-9);
      const bool inCore = texture.x >= inset && texture.x <= 1.0 - inset && texture.y >= inset &&
        texture.y <= 1.0 - inset;
      inCores += inCore;
      if (inCore)
      {
        // Tile (column, row) holds the whole map's window [column / Columns, ...),
        // which is where the receivers look for it, from the first tile.
        const glm::dvec2 u = glm::dvec2(w) / w.w * 0.5 + 0.5;
        EXPECT_EQ(static_cast<int>(t), static_cast<int>(u.y * Rows) * Columns + static_cast<int>(u.x * Columns));
        EXPECT_EQ(static_cast<int>(t), TileOf(grid, glm::dvec2(w) / w.w));
        const glm::dvec4 first =
          shadowmaps::ClipToTexture() * tiles[0].ViewProjection() * glm::dvec4(p, 1.0);
        EXPECT_EQ(static_cast<int>(t), TileFromFirstTile(grid, glm::dvec2(first) / first.w));
      }
    }
    EXPECT_EQ(inCores, 1) << "point " << n;
  }
  for (const LightView& tile : tiles)
  {
    EXPECT_TRUE(tile.Perspective);
    EXPECT_LT(tile.TexelPerUnitDistance, whole.TexelPerUnitDistance * 0.55);
    EXPECT_GT(tile.TexelPerUnitDistance, whole.TexelPerUnitDistance / 3.0);
  }
}

TEST(TileView, CountsAndMarginClamp)
{
  LightView whole;
  whole.Projection = glm::ortho(-4.0, 4.0, -2.0, 2.0, 1.0, 10.0);
  whole.TexelConstant = 8.0 / 256.0;
  const shadowmaps::TileGrid single = shadowmaps::MakeTileGrid(0, -3, 256, -5.0);
  EXPECT_EQ(single.Columns, 1);
  EXPECT_EQ(single.Rows, 1);
  EXPECT_EQ(single.WindowFraction, glm::dvec2(1.0));
  const auto one = shadowmaps::TileView(whole, single);
  ASSERT_EQ(one.size(), 1u);
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      EXPECT_NEAR(one[0].Projection[c][r], whole.Projection[c][r], 1e-12) << "a single tile without margin is the map";
    }
  }
  // The margin is clamped to a quarter of the tile: its core is then half its window.
  const shadowmaps::TileGrid clamped = shadowmaps::MakeTileGrid(2, 2, 256, 1000.0);
  EXPECT_DOUBLE_EQ(clamped.WindowFraction.x, 1.0);
  EXPECT_EQ(shadowmaps::TileView(whole, clamped).size(), 4u);
  // 2 x 2 tiles without margin: texels half the size.
  const auto halves = shadowmaps::TileView(whole, shadowmaps::MakeTileGrid(2, 2, 256, 0.0));
  EXPECT_DOUBLE_EQ(halves[3].TexelConstant, whole.TexelConstant / 2.0);

  // A warped map's projection has no window (here turned half a turn, so its
  // x and y scales are negative): tiles scale its per-distance texel by the
  // coarser window fraction.
  LightView warped = whole;
  warped.Projection = glm::rotate(glm::dmat4(1.0), glm::pi<double>(), glm::dvec3(0, 0, 1)) *
    glm::frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
  warped.Perspective = true;
  warped.TexelSizeFromGradient = true;
  warped.TexelConstant = 0.0;
  warped.TexelPerUnitDistance = 2.0 / 256.0;
  for (const auto& tile : shadowmaps::TileView(warped, shadowmaps::MakeTileGrid(3, 2, 256, 0.0)))
  {
    EXPECT_DOUBLE_EQ(tile.TexelPerUnitDistance, warped.TexelPerUnitDistance / 2.0);
    EXPECT_EQ(tile.TexelConstant, 0.0);
  }
}
} // namespace
