// The GL objects behind the shadow maps: one texture array (one layer per light
// view) holding either depth or two float values per texel, and the framebuffer
// that renders into a layer. vtkTextureObject
// and vtkOpenGLFramebufferObject in VTK 9.1 cannot attach array layers, hence
// this small owner of raw GL names. Not a VTK class: it holds no VTK state.
#ifndef ShadowMapTextureArray_h
#define ShadowMapTextureArray_h

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

class vtkOpenGLState;

namespace shadowmaps
{

/// What one texel holds: a depth (sampled with comparison), 32-bit float or
/// 16-bit normalized, or two or four values, 32- or 16-bit floats or 16-bit
/// normalized integers, in a colour attachment (sampled as values, filterable).
enum class TexelFormat
{
  Depth,
  /// Half the memory, and cheaper to sample where texel fetches dominate the
  /// frame (software rasterisers); for maps whose depth steps stay well below
  /// their texels (shadowmaps::SixteenBitDepthSuffices).
  Depth16,
  TwoFloats,
  FourFloats,
  TwoHalfFloats,
  FourHalfFloats,
  /// Values in [0, 1], evenly spaced: finer than half floats near 1.
  FourNormalized16
};

/// How the pass makes a map of the two nearest caster surfaces along each
/// light ray (MapStorage::SecondDepth).
enum class SecondDepthMethod
{
  /// One map of what StoreCode writes.
  None,
  /// One caster pass with minimum blending: x the nearest front face, y the
  /// nearest back face. Right for closed casters only.
  FrontAndBackFaces,
  /// Two caster passes (depth peeling): x the nearest surface, y the nearest
  /// behind it. Right for any casters.
  Peeling,
  /// FrontAndBackFaces when every caster is closed (ShadowMapClosedSurfaces),
  /// else Peeling.
  Auto
};

inline bool IsDepth(TexelFormat format)
{
  return format == TexelFormat::Depth || format == TexelFormat::Depth16;
}

/// Values per texel of a value format; 0 for depth.
inline int ValueChannels(TexelFormat format)
{
  return format == TexelFormat::TwoFloats || format == TexelFormat::TwoHalfFloats ? 2
    : IsDepth(format)                                                            ? 0
                                                                                 : 4;
}

/// Bytes of one texel of the format.
inline int TexelBytes(TexelFormat format)
{
  if (IsDepth(format))
  {
    return format == TexelFormat::Depth16 ? 2 : 4;
  }
  const bool sixteen = format == TexelFormat::TwoHalfFloats ||
    format == TexelFormat::FourHalfFloats || format == TexelFormat::FourNormalized16;
  return ValueChannels(format) * (sixteen ? 2 : 4);
}

/// The GL internal format (GLenum) of a texel format.
unsigned int InternalFormat(TexelFormat format);

/// Allocates `levels` mipmap levels of `layers` layers of resolution^2 texels
/// of the value format `format` for the 2D array texture bound to the active
/// unit, and limits sampling to them.
void AllocateValueLevels(int resolution, int layers, TexelFormat format, int levels);

/// Whether the current GL has sampler objects (3.3).
bool SamplerObjectsAvailable();

/// Drops the GL errors pending, so that the next glGetError reports only what follows.
void ClearGLErrors();

/// "GL error 0x..." for a glGetError code.
std::string GLErrorText(unsigned int code);

/// Restores the active unit's 2D (or, with `array`, 2D array) texture binding
/// when it goes: that unit may belong to someone else.
class ScopedTextureBinding
{
public:
  explicit ScopedTextureBinding(bool array);
  ~ScopedTextureBinding();
  ScopedTextureBinding(const ScopedTextureBinding&) = delete;
  ScopedTextureBinding& operator=(const ScopedTextureBinding&) = delete;

private:
  bool Array;
  int Previous = 0;
};

/// Delete the GL object `name` names, if any, and zero the name.
void DeleteTexture(unsigned int& name);
void DeleteFramebuffer(unsigned int& name);
void DeleteRenderbuffer(unsigned int& name);

/// Sets the bound framebuffer's `count` (1 or 2) draw buffers and its read
/// buffer through `state`, whose cache ParaView's VTK checks against GL; two
/// draw buffers are also set in GL directly, since VTK 9.1's cache re-reads only
/// the first when a framebuffer is bound and may skip a call it thinks is made.
void SelectBuffers(vtkOpenGLState* state, int count, const unsigned int* draws, unsigned int read);

class TextureArray
{
public:
  TextureArray() = default;
  ~TextureArray() = default; // GL names need a current context: call Release().
  TextureArray(const TextureArray&) = delete;
  TextureArray& operator=(const TextureArray&) = delete;

  /// Makes room for `layers` layers of resolution^2 texels of `format`
  /// (value layers share one depth buffer for the depth test, unless
  /// `depthTest` is false, and may have mipmaps). Keeps the current storage
  /// when it fits. On GL failure releases everything, fills `error` and
  /// returns false.
  bool Reserve(int resolution, int layers, TexelFormat format, bool mipmaps, std::string& error,
    bool depthTest = true);

  /// Binds the framebuffer (through the state cache) with `layer` attached.
  /// The caller pushes and pops the framebuffer bindings. `secondOutput`: also
  /// a one-float colour buffer of the layer's size for the casters' second
  /// output (gl_FragData[1]). Depth formats: casters of a linear-depth view
  /// write that depth there for LinearDepthResolve to copy into the layer (the
  /// casters' shaders then write no gl_FragDepth, which would cost the scene's
  /// draws of the same programs their early depth test). Two values: peeling
  /// casters keep there the nearest depth, which the next pass peels away.
  bool BindLayer(vtkOpenGLState* state, int layer, std::string& error, bool secondOutput = false);

  /// Value formats: binds, instead of a layer, multisample buffers of the
  /// layers' size with `samples` samples per texel (made on first use) for the
  /// casters to draw into; ResolveSamples then averages them into a layer.
  /// Moments average, so the layer holds the moments of its texels' samples.
  bool BindSamples(vtkOpenGLState* state, int samples, std::string& error);

  /// Averages the samples BindSamples' buffers hold into `layer` (a blit).
  bool ResolveSamples(vtkOpenGLState* state, int layer, std::string& error);

  /// The colour buffer of BindLayer's secondOutput (0 before its first use).
  unsigned int GetSecondOutput() const { return this->H.SecondOutput; }

  /// Frees that buffer while no view needs it (it is made again on demand).
  void ReleaseSecondOutput();

  /// Frees BindSamples' buffers while no view needs them.
  void ReleaseSamples();

  /// Depth: nearest (hard) or linear (hardware 2x2 PCF) comparison filtering.
  /// Values: nearest or (mipmapped) linear value filtering.
  void SetLinearFiltering(bool linear);

  /// Depth: whether sampling compares (shadow samplers) or returns the depth.
  void SetDepthComparison(bool compare);

  /// Rebuilds the mipmaps of a mipmapped value array from level 0.
  void GenerateMipmaps();

  /// The texels of the first `layers` layers as floats (a depth, or a value
  /// format's values), layer after layer, row after row (ReadTexels), and back
  /// (WriteTexels, the same size); false on GL failure. Pixel alignment goes
  /// through `state`'s cache.
  bool ReadTexels(
    vtkOpenGLState* state, int layers, std::vector<float>& texels, std::string& error) const;
  bool WriteTexels(
    vtkOpenGLState* state, int layers, const std::vector<float>& texels, std::string& error);

  TexelFormat GetFormat() const { return this->H.Format; }
  unsigned int GetTextureName() const { return this->H.Texture; }
  int GetResolution() const { return this->H.Resolution; }

  /// Counts the allocations so far: layers keep their content while it stays the same.
  unsigned long GetAllocations() const { return this->H.Allocations; }

  /// Binds the texture to texture unit `unit`, which it leaves active (through
  /// the state cache, which VTK's textures rely on to find their units).
  void BindToUnit(vtkOpenGLState* state, int unit) const;

  /// Depth formats: binds the texture to `unit` too, read through a sampler
  /// object that returns the stored depths (no comparison, nearest) for
  /// shaders that need them (the soft shadows' blocker search), whatever the
  /// texture's own comparison and filtering. Leaves `unit` active. False where
  /// the GL has no sampler objects (before 3.3).
  bool BindRawDepthToUnit(vtkOpenGLState* state, int unit);

  /// Takes the sampler object off `unit` (BindRawDepthToUnit's).
  static void UnbindRawDepth(vtkOpenGLState* state, int unit);

  void Release();

  /// Exchanges what this array and `other` hold (GL objects, contents and
  /// allocation counts), allocating nothing.
  void Swap(TextureArray& other) noexcept { std::swap(this->H, other.H); }

  std::size_t GetMemoryBytes() const;

private:
  void AllocateDepthLayers(int resolution, int layers, TexelFormat format);
  void AllocateValueLayers(int resolution, int layers, TexelFormat format);
  void ApplyFiltering(bool linear);
  /// Floats of one layer's texels for ReadTexels and WriteTexels.
  std::size_t FloatsPerLayer() const;

  // Everything the array holds, in one place so that Swap exchanges all of it.
  struct Held
  {
    unsigned int Texture = 0;
    unsigned int Framebuffer = 0;
    unsigned int DepthBuffer = 0; // value formats only
    unsigned int SecondOutput = 0; // BindLayer's secondOutput, made on first use
    unsigned int SampleFramebuffer = 0; // BindSamples' buffers, made on first use
    unsigned int SampleColor = 0;
    unsigned int SampleDepth = 0;
    unsigned int RawDepthSampler = 0; // BindRawDepthToUnit's, made on first use
    int Samples = 0;
    int AllocatedSamples = 0;
    TexelFormat Format = TexelFormat::Depth;
    bool Mipmaps = false;
    bool DepthTest = true;
    int Resolution = 0;
    int Layers = 0;
    int LinearFiltering = -1;
    unsigned long Allocations = 0;
  };
  Held H;
};

} // namespace shadowmaps

#endif
