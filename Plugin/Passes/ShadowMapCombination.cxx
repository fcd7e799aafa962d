#include "ShadowMapCombination.h"

#include "ShadowMapLight.h"
#include "ShadowMapStoreFromLightDepths.h"
#include "ShadowMapTextureArray.h"
#include "ShadowMapTransmittance.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShadowMapExchange.h"
#include "vtkShadowMapRepresentation.h"

#include <algorithm>
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
    if (!lightDepths.Store(window, maps, layer, storage.StoreFunctions, storage.StoreCode,
          storage.StoreUniforms, error))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
FrameAgreement AgreeOnFrame(vtkShadowMapExchange* exchange, bool interactive, bool translucent)
{
  // Two flags, not one reduction of both: MinimumOf is the maps' texels' (a
  // parallel renderer may count what it carries as the maps' traffic).
  FrameAgreement agreed;
  agreed.AllInteractive = !exchange->AnyOf(!interactive);
  agreed.AnyTranslucent = exchange->AnyOf(translucent);
  return agreed;
}

//------------------------------------------------------------------------------
bool AgreeOnShape(vtkShadowMapExchange* exchange, int resolution, int layers, Combination how,
  bool transmittance)
{
  // Each value and its negation: the least of both is their range's ends.
  const float kind = static_cast<float>(how);
  const float transmits = transmittance ? 1.0f : 0.0f;
  std::vector<float> shape = { float(resolution), -float(resolution), float(layers),
    -float(layers), kind, -kind, transmits, -transmits };
  return exchange->MinimumOf(shape) && shape.size() == 8 && shape[0] == -shape[1] &&
    shape[2] == -shape[3] && shape[4] == -shape[5] && shape[6] == -shape[7];
}

//------------------------------------------------------------------------------
bool CombineTransmittances(vtkShadowMapExchange* exchange, vtkOpenGLRenderWindow* window,
  TransmittanceMaps& maps, int layers, int resolution, bool& multiplied, std::string& error)
{
  // Every process makes both calls, of the agreed sizes, whatever it could
  // read: the colours, then the depths with whether each read its maps.
  const std::size_t count = static_cast<std::size_t>(resolution) * resolution * layers;
  std::vector<float> texels;
  const bool readable = maps.ReadTexels(window->GetState(), layers, texels, error) &&
    texels.size() == 4 * count;
  std::vector<float> colours(3 * count, 1.0f);
  std::vector<float> depths(count + 1, 1.0f);
  for (std::size_t i = 0; readable && i < count; ++i)
  {
    std::copy(texels.begin() + 4 * i, texels.begin() + 4 * i + 3, colours.begin() + 3 * i);
    depths[i] = texels[4 * i + 3];
  }
  const bool multipliedHere = exchange->ProductOf(colours);
  // Whether each process read its maps (-2 where not) and multiplied (-1):
  // every process then takes the same branch.
  depths[count] = !readable ? -2.0f : !multipliedHere ? -1.0f : 0.0f;
  if (!exchange->MinimumOf(depths) || depths[count] < -1.0f)
  {
    if (readable)
    {
      error = "the transmittance maps could not be combined across processes";
    }
    return false;
  }
  multiplied = depths[count] == 0.0f;
  if (!multiplied)
  {
    return true;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    std::copy(colours.begin() + 3 * i, colours.begin() + 3 * i + 3, texels.begin() + 4 * i);
    texels[4 * i + 3] = depths[i];
  }
  return maps.WriteTexels(window->GetState(), layers, texels, error);
}
} // namespace shadowmaps
