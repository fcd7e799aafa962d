// Transmittance maps: beside each shadow-map layer, what the translucent
// casters let through toward the light (docs/TRANSLUCENT.md). Per texel (four
// 32-bit floats, read texel by texel, no depth buffer), rgb
// is the product over the translucent surfaces drawn there of what each lets
// through ((1 - a)(1 - a + a c), shadoworacle::SurfaceTransmittance's model),
// multiplied by blending in any draw order; a is the light depth
// (ShadowLight::Depth) of the nearest of them, kept by minimum blending. A
// receiver farther from the light than that depth gets the product. Made only
// while some caster is translucent. Not a VTK class.
#ifndef ShadowMapTransmittance_h
#define ShadowMapTransmittance_h

#include "ShadowMapTextureArray.h"

#include <functional>
#include <string>
#include <vector>

class vtkOpenGLState;

namespace shadowmaps
{
class TransmittanceMaps
{
public:
  /// Makes room for `layers` layers of resolution^2 texels (RGBA, 32-bit
  /// floats, nearest filtering), keeping the current ones when they fit.
  /// False with `error` on GL failure.
  bool Reserve(int resolution, int layers, std::string& error);

  /// Clears layer `layer` to "all light, no translucent surface" and calls
  /// draw() with the layer bound and blending that multiplies the colours and
  /// keeps the least alpha; the GL state goes back after. False with `error`
  /// when the layer cannot be bound.
  bool Render(vtkOpenGLState* state, int layer, const std::function<void()>& draw,
    std::string& error);

  /// The first `layers` layers' texels (four floats each), and back
  /// (TextureArray's): for the processes' combination.
  bool ReadTexels(vtkOpenGLState* state, int layers, std::vector<float>& texels,
    std::string& error) const
  {
    return this->Layers.ReadTexels(state, layers, texels, error);
  }
  bool WriteTexels(
    vtkOpenGLState* state, int layers, const std::vector<float>& texels, std::string& error)
  {
    return this->Layers.WriteTexels(state, layers, texels, error);
  }

  /// Binds the maps to `unit`, which it leaves active.
  void BindToUnit(vtkOpenGLState* state, int unit) const;

  bool IsAllocated() const { return this->Layers.GetTextureName() != 0; }
  unsigned long GetAllocations() const { return this->Layers.GetAllocations(); }
  std::size_t GetMemoryBytes() const { return this->Layers.GetMemoryBytes(); }
  void Release() { this->Layers.Release(); }

private:
  TextureArray Layers;
};
} // namespace shadowmaps

#endif
