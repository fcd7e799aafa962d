#include "vtkShadowMapViews.h"

#include "ShadowMapLight.h"

//------------------------------------------------------------------------------
void vtkShadowMapViews::FitUniformViews(
  const shadowmaps::ShadowFrame& frame, shadowmaps::ShadowLight& light)
{
  light.Views.clear();
  if (shadowmaps::NeedsCubeFaces(light))
  {
    light.Layout = shadowmaps::ViewLayout::CubeFaces;
    const auto faces = shadowmaps::FitCubeFacesToView(
      frame.CameraViewProjection(), frame.SceneBounds, light.Position, frame.Resolution);
    light.Views.assign(faces.begin(), faces.end());
    return;
  }
  light.Layout = shadowmaps::ViewLayout::Single;
  if (light.Kind == shadowmaps::LightKind::Spot)
  {
    light.Views.push_back(shadowmaps::FitSpot(frame.CameraViewProjection(), frame.SceneBounds,
      light.Position, light.Direction, light.ConeAngle, frame.Resolution, true));
    return;
  }
  light.Views.push_back(shadowmaps::FitDirectional(
    frame.CameraViewProjection(), frame.SceneBounds, light.Direction, frame.Resolution, true));
}

//------------------------------------------------------------------------------
void vtkShadowMapViews::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
