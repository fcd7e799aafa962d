// What a map layer was rendered from, and when a frame may keep it
// (Plugin/Passes/ShadowMapLayerContent).
#include "ShadowMapLayerContent.h"

#include <gtest/gtest.h>

using shadowmaps::CasterStamp;
using shadowmaps::LayerContent;
using shadowmaps::SortedByProp;

namespace
{
// Three props, by address.
const int Props[3] = { 0, 0, 0 };
const int& PropA = Props[0];
const int& PropB = Props[1];
const int& PropC = Props[2];
const std::vector<vtkMTimeType> View = { 1, 2, 3 };
} // namespace

TEST(ShadowMapLayerContent, ANewLayerHoldsNothing)
{
  EXPECT_FALSE(LayerContent().Holds(View, {}, {}));
  EXPECT_FALSE(LayerContent().Holds({}, {}, {}));
}

TEST(ShadowMapLayerContent, KeptForTheSameViewAndCasters)
{
  const std::vector<CasterStamp> casters = { { &PropB, 7 }, { &PropA, 5 } };
  const LayerContent layer(View, casters);
  EXPECT_TRUE(layer.Holds(View, casters, SortedByProp(casters)));
  EXPECT_FALSE(layer.Holds({ 1, 2, 4 }, casters, SortedByProp(casters))) << "another view";
}

// A caster the view no longer needs stays drawn: its depths are still right.
// One it needs and did not draw, or one whose data changed, re-renders.
TEST(ShadowMapLayerContent, CastersNeededMustBeDrawnAndDrawnOnesCurrent)
{
  const CasterStamp a{ &PropA, 5 };
  const CasterStamp b{ &PropB, 7 };
  const CasterStamp c{ &PropC, 9 };
  const LayerContent layer(View, { a, b });
  const std::vector<CasterStamp> all = SortedByProp({ a, b, c });
  EXPECT_TRUE(layer.Holds(View, { a }, all)) << "b no longer needed";
  EXPECT_TRUE(layer.Holds(View, {}, all)) << "nothing needed";
  EXPECT_FALSE(layer.Holds(View, { a, c }, all)) << "c needed, not drawn";
  EXPECT_FALSE(layer.Holds(View, { a, { &PropB, 8 } }, SortedByProp({ a, { &PropB, 8 }, c })))
    << "b's data changed";
  EXPECT_FALSE(layer.Holds(View, { a }, SortedByProp({ a, { &PropB, 8 }, c })))
    << "b, drawn, not needed, changed: its old depths may shadow what the view shades";
  EXPECT_FALSE(layer.Holds(View, { a }, SortedByProp({ a, c }))) << "b gone";
}
