#include "ShadowMapCombination.h"

#include "ShadowMapLight.h"
#include "ShadowMapStoreFromLightDepths.h"
#include "ShadowMapTextureArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShadowMapExchange.h"
#include "vtkShadowMapRepresentation.h"

#include <vector>

namespace shadowmaps
{
//------------------------------------------------------------------------------
Combination CombinationOf(const MapStorage& storage)
{
  if (storage.SecondDepth == SecondDepthMethod::Peeling)
  {
    return Combination::NearestTwoSurfaces;
  }
  if (IsDepth(storage.Format) || storage.SecondDepth == SecondDepthMethod::FrontAndBackFaces)
  {
    return Combination::NearestTexels;
  }
  return storage.LightDepth ? Combination::NearestLightDepths : Combination::None;
}

//------------------------------------------------------------------------------
bool GatherPropBounds(vtkShadowMapExchange* exchange, ShadowFrame& frame, bool sceneBoundsGiven)
{
  std::vector<double> boxes;
  for (const Aabb& box : frame.PropBounds)
  {
    boxes.insert(boxes.end(), { box.Min.x, box.Max.x, box.Min.y, box.Max.y, box.Min.z, box.Max.z });
  }
  if (!exchange->AllBoxes(boxes))
  {
    frame.PropBounds.assign(1, frame.SceneBounds);
    return false;
  }
  frame.PropBounds.clear();
  Aabb all;
  for (std::size_t i = 0; i + 6 <= boxes.size(); i += 6)
  {
    const Aabb box = Aabb::FromBounds(boxes.data() + i);
    if (box.IsUsable())
    {
      frame.PropBounds.push_back(box);
      all.Add(box);
    }
  }
  if (!sceneBoundsGiven)
  {
    frame.SceneBounds = all;
  }
  return true;
}

//------------------------------------------------------------------------------
bool CombineTexels(vtkShadowMapExchange* exchange, vtkOpenGLRenderWindow* window, Combination how,
  TextureArray& maps, const MapStorage& storage, StoreFromLightDepths& lightDepths, int layers,
  int resolution, std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  const bool fromLightDepths = how == Combination::NearestLightDepths;
  std::vector<float> read;
  const bool readable = fromLightDepths || maps.ReadTexels(state, layers, read, error);
  std::vector<float>& texels = fromLightDepths ? lightDepths.GetDepths() : read;
  const float kind = static_cast<float>(how);
  std::vector<float> shape = { float(resolution), -float(resolution), float(layers),
    -float(layers), kind, -kind, float(texels.size()), -float(texels.size()),
    readable ? 0.0f : -1.0f };
  if (!exchange->MinimumOf(shape) || shape[0] != -shape[1] || shape[2] != -shape[3] ||
    shape[4] != -shape[5] || shape[6] != -shape[7] || shape[8] != 0.0f)
  {
    if (readable)
    {
      error = "the processes' shadow maps differ in size or kind, or one could not read its maps";
    }
    return false;
  }
  const bool combined = how == Combination::NearestTwoSurfaces ? exchange->NearestTwoOf(texels)
                                                               : exchange->MinimumOf(texels);
  if (!combined)
  {
    error = "the shadow maps could not be combined across processes";
    return false;
  }
  if (!fromLightDepths)
  {
    return maps.WriteTexels(state, layers, texels, error);
  }
  for (int layer = 0; layer < layers; ++layer)
  {
    if (!lightDepths.Store(window, maps, layer, storage.StoreFunctions, storage.StoreCode, error))
    {
      return false;
    }
  }
  return true;
}
} // namespace shadowmaps
