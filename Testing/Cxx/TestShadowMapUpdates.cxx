// The frame-to-frame policy of a renderer's maps (Plugin/Passes/ShadowMapUpdates):
// which casters a layer draws, when a frame keeps a layer, when views are kept.
#include "ShadowMapUpdates.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using shadowmaps::Aabb;
using shadowmaps::Caster;
using shadowmaps::LayerRequest;
using shadowmaps::MapSignature;
using shadowmaps::MapUpdates;
using shadowmaps::ShadowFrame;
using shadowmaps::ShadowLight;

namespace
{
// A sun straight above, its orthographic view from z = 10 down to z = -10,
// with the near plane at z = 2: a fit that put it there for depth precision.
ShadowLight SunAbove()
{
  ShadowLight light;
  light.Kind = shadowmaps::LightKind::Directional;
  light.Position = glm::dvec3(0.0, 0.0, 10.0);
  light.Direction = glm::dvec3(0.0, 0.0, -1.0);
  shadowmaps::LightView view;
  view.View = glm::lookAt(light.Position, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  view.Projection = glm::ortho(-5.0, 5.0, -5.0, 5.0, 8.0, 20.0);
  light.Views.push_back(view);
  return light;
}

Caster BoxCaster(const void* prop, double zMin, double zMax, vtkMTimeType version = 1)
{
  Caster caster;
  caster.Prop = static_cast<vtkProp*>(const_cast<void*>(prop));
  caster.Bounds = Aabb::FromBounds(std::array<double, 6>{ -1.0, 1.0, -1.0, 1.0, zMin, zMax }.data());
  caster.Version = version;
  return caster;
}

const int Props[2] = { 0, 0 };
const std::vector<glm::dvec3> NoCulling;

LayerRequest RequestFor(const ShadowLight& light)
{
  LayerRequest request;
  request.Light = &light;
  request.Visible = &NoCulling;
  return request;
}

// A drag's frame, and its request for a layer of every caster in view.
ShadowFrame DragFrame()
{
  ShadowFrame drag;
  drag.Interactive = true;
  return drag;
}

LayerRequest DragRequestFor(const ShadowLight& light)
{
  LayerRequest request = RequestFor(light);
  request.DrawsAllInView = true;
  return request;
}
} // namespace

// Casters draw with depth clamping: one nearer the light than its view's near
// plane is pancaked onto it and still shadows what lies below.
TEST(ShadowMapUpdates, CastersNearerThanTheNearPlaneAreDrawn)
{
  const ShadowLight light = SunAbove();
  const std::vector<Caster> casters = { BoxCaster(&Props[0], 3.0, 4.0),
    BoxCaster(&Props[1], 11.0, 12.0) };
  MapUpdates updates;
  updates.BeginUpdate({ 1 }, 1, false, casters);
  const shadowmaps::LayerPlan plan = updates.Plan(ShadowFrame(), casters, RequestFor(light));
  ASSERT_TRUE(plan.Render);
  ASSERT_EQ(plan.Casters.size(), 2u) << "the caster between the near plane and the light, and "
                                        "the one above the light, which a sun also casts from";
}

// A layer drawn during a drag (coarse levels of detail) is not kept by the
// still frame after it; a layer drawn still is kept by the drag.
TEST(ShadowMapUpdates, StillFramesKeepNoLayerDrawnInADrag)
{
  const ShadowLight light = SunAbove();
  const std::vector<Caster> casters = { BoxCaster(&Props[0], 0.0, 1.0) };
  ShadowFrame still;
  ShadowFrame drag;
  drag.Interactive = true;
  MapUpdates updates;
  updates.BeginUpdate({ 1 }, 1, false, casters);
  updates.Rendered(0, updates.Plan(still, casters, RequestFor(light)));
  EXPECT_FALSE(updates.Plan(drag, casters, RequestFor(light)).Render) << "a drag keeps it";
  EXPECT_FALSE(updates.Plan(still, casters, RequestFor(light)).Render) << "so does a still frame";
  // Drawn in a drag: a new version of the caster makes the drag render it.
  const std::vector<Caster> changed = { BoxCaster(&Props[0], 0.0, 1.0, 2) };
  updates.BeginUpdate({ 1 }, 1, false, changed);
  shadowmaps::LayerPlan dragged = updates.Plan(drag, changed, RequestFor(light));
  ASSERT_TRUE(dragged.Render);
  updates.Rendered(0, std::move(dragged));
  EXPECT_FALSE(updates.Plan(drag, changed, RequestFor(light)).Render) << "the next drag frame";
  EXPECT_TRUE(updates.Plan(still, changed, RequestFor(light)).Render) << "the still frame";
}

// A caster whose version changed re-renders the layers that drew it; the
// layers' key forgets every layer.
TEST(ShadowMapUpdates, ChangedCastersAndKeysReRender)
{
  const ShadowLight light = SunAbove();
  std::vector<Caster> casters = { BoxCaster(&Props[0], 0.0, 1.0) };
  MapUpdates updates;
  updates.BeginUpdate({ 1 }, 1, false, casters);
  updates.Rendered(0, updates.Plan(ShadowFrame(), casters, RequestFor(light)));
  EXPECT_FALSE(updates.Plan(ShadowFrame(), casters, RequestFor(light)).Render);
  casters[0].Version = 2;
  updates.BeginUpdate({ 1 }, 1, false, casters);
  EXPECT_TRUE(updates.Plan(ShadowFrame(), casters, RequestFor(light)).Render) << "new version";
  updates.Rendered(0, updates.Plan(ShadowFrame(), casters, RequestFor(light)));
  updates.BeginUpdate({ 2 }, 1, false, casters);
  EXPECT_TRUE(updates.Plan(ShadowFrame(), casters, RequestFor(light)).Render) << "new key";
}

// A layer a drag drew with every caster in its view is kept by the drag's
// next frames while the casters stay the same; a caster gone, or a new one in
// view, re-renders it (the casters' generation moved on, and the casters are
// compared).
TEST(ShadowMapUpdates, ADragsLayerOfEveryCasterInViewFollowsTheCasters)
{
  const ShadowLight light = SunAbove();
  const int more[2] = { 0, 0 };
  const std::vector<Caster> two = { BoxCaster(&Props[0], 0.0, 1.0), BoxCaster(&Props[1], 0.0, 1.0) };
  const std::vector<Caster> one = { two[0] };
  const std::vector<Caster> three = { two[0], two[1], BoxCaster(&more[0], 0.0, 1.0) };
  const ShadowFrame drag = DragFrame();
  const LayerRequest request = DragRequestFor(light);
  MapUpdates updates;
  updates.BeginUpdate({ 1 }, 1, false, two);
  shadowmaps::LayerPlan first = updates.Plan(drag, two, request);
  ASSERT_TRUE(first.Render);
  EXPECT_EQ(first.Casters.size(), 2u);
  updates.Rendered(0, std::move(first));
  updates.BeginUpdate({ 1 }, 1, false, two);
  EXPECT_FALSE(updates.Plan(drag, two, request).Render) << "the same casters";
  updates.BeginUpdate({ 1 }, 1, false, one);
  EXPECT_TRUE(updates.Plan(drag, one, request).Render) << "a drawn caster gone";
  updates.BeginUpdate({ 1 }, 1, false, two);
  EXPECT_FALSE(updates.Plan(drag, two, request).Render) << "back as drawn: compared, kept";
  updates.BeginUpdate({ 1 }, 1, false, three);
  EXPECT_TRUE(updates.Plan(drag, three, request).Render) << "a new caster in view";
}

// A prop that is not an actor may move with its version unchanged (only an
// actor's bounds follow its version): its bounds entering a drag's layer's view
// re-render the layer.
TEST(ShadowMapUpdates, ADragsLayerFollowsCastersBoundsAsWellAsVersions)
{
  const ShadowLight light = SunAbove();
  Caster away = BoxCaster(&Props[0], 0.0, 1.0);
  away.Bounds = Aabb::FromBounds(std::array<double, 6>{ 100.0, 101.0, 0.0, 1.0, 0.0, 1.0 }.data());
  const std::vector<Caster> before = { BoxCaster(&Props[1], 0.0, 1.0), away };
  const std::vector<Caster> after = { BoxCaster(&Props[1], 0.0, 1.0), BoxCaster(&Props[0], 0.0, 1.0) };
  const ShadowFrame drag = DragFrame();
  const LayerRequest request = DragRequestFor(light);
  MapUpdates updates;
  updates.BeginUpdate({ 1 }, 1, false, before);
  shadowmaps::LayerPlan first = updates.Plan(drag, before, request);
  ASSERT_TRUE(first.Render);
  EXPECT_EQ(first.Casters.size(), 1u) << "the one out of view is not drawn";
  updates.Rendered(0, std::move(first));
  updates.BeginUpdate({ 1 }, 1, false, after);
  EXPECT_TRUE(updates.Plan(drag, after, request).Render) << "the same version, now in view";
}

namespace
{
MapSignature WordsOnly(std::vector<vtkMTimeType> words)
{
  MapSignature signature;
  signature.Words = std::move(words);
  return signature;
}
} // namespace

// Views are kept only where nothing but the camera moved since.
TEST(ShadowMapUpdates, ViewsKeptOnlyWhenOnlyTheCameraMoved)
{
  const ShadowLight light = SunAbove();
  const Aabb bounds = Aabb::FromBounds(std::array<double, 6>{ -1, 1, -1, 1, -1, 1 }.data());
  MapUpdates updates;
  updates.Finish({ light }, WordsOnly({ 1, 2, 3 }), 5, 1024, bounds);
  EXPECT_TRUE(updates.Current(WordsOnly({ 1, 2, 3 })));
  EXPECT_FALSE(updates.Current(WordsOnly({ 1, 2, 4 })));
  EXPECT_EQ(updates.KeptViews(light, 5, 1024, bounds).size(), 1u);
  EXPECT_TRUE(updates.KeptViews(light, 6, 1024, bounds).empty()) << "a parameter changed";
  EXPECT_TRUE(updates.KeptViews(light, 5, 2048, bounds).empty()) << "another resolution";
  ShadowLight moved = light;
  moved.Direction = glm::dvec3(0.0, 0.1, -1.0);
  EXPECT_TRUE(updates.KeptViews(moved, 5, 1024, bounds).empty()) << "the light turned";
  updates.Invalidate();
  EXPECT_FALSE(updates.Current(WordsOnly({ 1, 2, 3 })));
  EXPECT_TRUE(updates.KeptViews(light, 5, 1024, bounds).empty());
}

// A projection derived by another path (a capture's, about 5e-9 apart) is the
// same; one zoomed the least a user can is not, nor a parallel scale or a
// window centre moved; the rest of the signature (the view among it, whose
// translation is in world units) is compared bit for bit.
TEST(ShadowMapUpdates, ProjectionsMatchWithinATenMillionth)
{
  MapSignature rendered = WordsOnly({ 1, 2, 3 });
  rendered.CameraProjection = glm::perspective(glm::radians(30.0), 1.5, 0.1, 100.0);
  MapSignature capture = rendered;
  capture.CameraProjection[0][0] *= 1.0 + 5e-9;
  capture.CameraProjection[3][2] *= 1.0 - 5e-9;
  EXPECT_TRUE(capture.Matches(rendered));
  MapSignature zoomed = rendered;
  zoomed.CameraProjection[1][1] *= 1.0 + 1e-5;
  EXPECT_FALSE(zoomed.Matches(rendered));
  MapSignature parallel = WordsOnly({ 1, 2, 3 });
  parallel.CameraProjection = glm::ortho(-2.0, 2.0, -1.5, 1.5, 0.1, 100.0);
  MapSignature scaled = parallel;
  scaled.CameraProjection[0][0] *= 1.0 + 1e-5;
  EXPECT_FALSE(scaled.Matches(parallel));
  MapSignature shifted = parallel;
  shifted.CameraProjection[3][0] += 1e-5; // a window centre moved
  EXPECT_FALSE(shifted.Matches(parallel));
  MapSignature other = capture;
  other.Words.back() = 4;
  EXPECT_FALSE(other.Matches(rendered));
  MapSignature huge = WordsOnly({ 1, 2, 3 });
  huge.CameraProjection = glm::ortho(-2e5, 2e5, -1.5e5, 1.5e5, 0.1, 1e6);
  MapSignature zoomedOut = huge;
  zoomedOut.CameraProjection[0][0] *= 1.0 + 1e-5; // a parallel scale of 2e5 changed
  EXPECT_FALSE(zoomedOut.Matches(huge));
}

// The camera's view is in the signature bit for bit: a camera a million units
// from the origin moved by a thousandth renders new maps.
TEST(ShadowMapUpdates, AViewFarFromTheOriginMovedRendersNewMaps)
{
  shadowmaps::MapInputs inputs;
  ShadowFrame frame;
  frame.CameraProjection = glm::perspective(glm::radians(30.0), 1.5, 0.1, 100.0);
  frame.CameraView =
    glm::lookAt(glm::dvec3(1e6, 0.0, 5.0), glm::dvec3(1e6, 0.0, 0.0), glm::dvec3(0, 1, 0));
  const MapSignature rendered = MapUpdates::Signature(inputs, frame, {}, {});
  EXPECT_TRUE(MapUpdates::Signature(inputs, frame, {}, {}).Matches(rendered));
  frame.CameraView =
    glm::lookAt(glm::dvec3(1e6 + 1e-3, 0.0, 5.0), glm::dvec3(1e6 + 1e-3, 0.0, 0.0), glm::dvec3(0, 1, 0));
  EXPECT_FALSE(MapUpdates::Signature(inputs, frame, {}, {}).Matches(rendered));
}
