// The GL objects behind the shadow maps: one depth texture array (one layer per
// light view) and the framebuffer that renders into a layer. vtkTextureObject
// and vtkOpenGLFramebufferObject in VTK 9.1 cannot attach array layers, hence
// this small owner of raw GL names. Not a VTK class: it holds no VTK state.
#ifndef ShadowMapTextureArray_h
#define ShadowMapTextureArray_h

#include <cstddef>
#include <string>

class vtkOpenGLState;

namespace shadowmaps
{

class TextureArray
{
public:
  TextureArray() = default;
  ~TextureArray() = default; // GL names need a current context: call Release().
  TextureArray(const TextureArray&) = delete;
  TextureArray& operator=(const TextureArray&) = delete;

  /// Makes room for `layers` layers of resolution^2 32-bit float depth. Keeps
  /// the current storage when it is big enough. On GL failure releases
  /// everything, fills `error` and returns false.
  bool Reserve(int resolution, int layers, std::string& error);

  /// Binds the framebuffer (through the state cache) with `layer` as its depth
  /// attachment. The caller pushes and pops the framebuffer bindings.
  bool BindLayer(vtkOpenGLState* state, int layer, std::string& error);

  /// Nearest (hard) or linear (hardware 2x2 PCF) comparison filtering.
  void SetLinearFiltering(bool linear);

  /// Binds the texture to texture unit `unit`.
  void BindToUnit(int unit) const;

  void Release();

  std::size_t GetMemoryBytes() const;

private:
  unsigned int Texture = 0;
  unsigned int Framebuffer = 0;
  int Resolution = 0;
  int Layers = 0;
  int LinearFiltering = -1;
};

} // namespace shadowmaps

#endif
