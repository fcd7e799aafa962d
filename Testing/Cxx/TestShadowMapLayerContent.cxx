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
// A layer drawn at generation Then, compared at Now: the casters are compared.
constexpr unsigned long long Then = 1;
constexpr unsigned long long Now = 2;
} // namespace

TEST(ShadowMapLayerContent, ANewLayerHoldsNothing)
{
  EXPECT_FALSE(LayerContent().Holds(View, {}, {}, 0));
  EXPECT_FALSE(LayerContent().Holds({}, {}, {}, 0));
  EXPECT_FALSE(LayerContent().HoldsEveryCasterInView(View, 0));
  EXPECT_FALSE(LayerContent().HoldsEveryCasterInView({}, 0));
}

TEST(ShadowMapLayerContent, KeptForTheSameViewAndCasters)
{
  const std::vector<CasterStamp> casters = { { &PropB, 7 }, { &PropA, 5 } };
  const LayerContent layer(View, casters, Then, false);
  EXPECT_TRUE(layer.Holds(View, casters, SortedByProp(casters), Now));
  EXPECT_FALSE(layer.Holds({ 1, 2, 4 }, casters, SortedByProp(casters), Now)) << "another view";
  EXPECT_FALSE(layer.HoldsEveryCasterInView(View, Then)) << "drawn with the needed casters only";
}

// A caster the view no longer needs stays drawn: its depths are still right.
// One it needs and did not draw, or one whose data changed, re-renders.
TEST(ShadowMapLayerContent, CastersNeededMustBeDrawnAndDrawnOnesCurrent)
{
  const CasterStamp a{ &PropA, 5 };
  const CasterStamp b{ &PropB, 7 };
  const CasterStamp c{ &PropC, 9 };
  const LayerContent layer(View, { a, b }, Then, false);
  const std::vector<CasterStamp> all = SortedByProp({ a, b, c });
  EXPECT_TRUE(layer.Holds(View, { a }, all, Now)) << "b no longer needed";
  EXPECT_TRUE(layer.Holds(View, {}, all, Now)) << "nothing needed";
  EXPECT_FALSE(layer.Holds(View, { a, c }, all, Now)) << "c needed, not drawn";
  EXPECT_FALSE(layer.Holds(View, { a, { &PropB, 8 } }, SortedByProp({ a, { &PropB, 8 }, c }), Now))
    << "b's data changed";
  EXPECT_FALSE(layer.Holds(View, { a }, SortedByProp({ a, { &PropB, 8 }, c }), Now))
    << "b, drawn, not needed, changed: its old depths may shadow what the view shades";
  EXPECT_FALSE(layer.Holds(View, { a }, SortedByProp({ a, c }), Now)) << "b gone";
  EXPECT_FALSE(layer.Holds(View, { a }, SortedByProp({ c }), Now)) << "a and b gone";
  EXPECT_FALSE(layer.Holds(View, {}, {}, Now)) << "every caster gone";
}

// The drawn casters are compared with the current ones only when the frame's
// casters changed since the layer was drawn (its generation): the same
// generation means the same casters with the same data.
TEST(ShadowMapLayerContent, TheSameGenerationKeepsTheDrawnCastersCurrent)
{
  const CasterStamp a{ &PropA, 5 };
  const CasterStamp b{ &PropB, 7 };
  const LayerContent layer(View, { a, b }, Then, false);
  EXPECT_TRUE(layer.Holds(View, { a }, SortedByProp({ a, b }), Then));
  EXPECT_FALSE(layer.Holds(View, { a, { &PropC, 1 } }, SortedByProp({ a, b }), Then))
    << "a needed caster not drawn still re-renders";
  EXPECT_FALSE(layer.Holds({ 9 }, { a }, SortedByProp({ a, b }), Then)) << "another view";
}

// A layer drawn with every caster in its view (a drag's) holds whatever a frame
// of the same casters needs in the same view, without comparing casters; a new
// generation or another view goes through the comparison.
TEST(ShadowMapLayerContent, EveryCasterInViewHoldsForTheSameGenerationAndView)
{
  const CasterStamp a{ &PropA, 5 };
  const CasterStamp b{ &PropB, 7 };
  const LayerContent layer(View, { a, b }, Then, true);
  EXPECT_TRUE(layer.HoldsEveryCasterInView(View, Then));
  EXPECT_FALSE(layer.HoldsEveryCasterInView(View, Now)) << "the casters changed since";
  EXPECT_FALSE(layer.HoldsEveryCasterInView({ 1, 2, 4 }, Then)) << "another view";
  EXPECT_TRUE(layer.Holds(View, { b }, SortedByProp({ a, b }), Now));
  EXPECT_FALSE(layer.Holds(View, { b }, SortedByProp({ { &PropA, 6 }, b }), Now)) << "a changed";
}
