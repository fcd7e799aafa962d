#include "vtkVarianceShadowMapRepresentation.h"

#include "ShadowMapBlur.h"
#include "ShadowMapFloatUniforms.h"
#include "ShadowMapRotationNoise.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapsMomentsFS.h"
#include "vtkShadowMapsSoftKernelFS.h"
#include "vtkShadowMapsSoftMomentsFS.h"
#include "vtkShadowMapsVarianceLookupFS.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkVarianceShadowMapRepresentation);

namespace
{
// exp(c) of a stored value and, for the variance maps, exp(2 c) of its square
// must stay below the storage's largest finite value, with room for a blur's
// sums: 3.4e38 = e^88.7 for 32-bit floats, 65504 = e^11.09 for 16-bit ones.
constexpr double LargestExponent32 = 88.0;
constexpr double LargestExponent16 = 11.08;
} // namespace

//------------------------------------------------------------------------------
vtkVarianceShadowMapRepresentation::vtkVarianceShadowMapRepresentation()
  : Noise(new shadowmaps::RotationNoise())
{
}

//------------------------------------------------------------------------------
vtkVarianceShadowMapRepresentation::~vtkVarianceShadowMapRepresentation() = default;

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::SetMoments(int moments)
{
  moments = std::min(std::max(moments, static_cast<int>(VSM)), static_cast<int>(ESM));
  if (moments != this->Moments)
  {
    this->Moments = moments;
    this->ClampExponents();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::SetStorage(int bits)
{
  const int storage = bits < 24 ? HALF_FLOAT : FLOAT;
  if (storage != this->Storage)
  {
    this->Storage = storage;
    this->ClampExponents();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::SetPositiveExponent(double exponent)
{
  if (!vtkShadowMapsIsFiniteParameter(this, "PositiveExponent", exponent, this->PositiveExponent))
  {
    return;
  }
  exponent = std::max(exponent, 0.0);
  if (exponent != this->PositiveExponent)
  {
    this->PositiveExponent = exponent;
    this->ClampExponents();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::SetNegativeExponent(double exponent)
{
  if (!vtkShadowMapsIsFiniteParameter(this, "NegativeExponent", exponent, this->NegativeExponent))
  {
    return;
  }
  exponent = std::max(exponent, 0.0);
  if (exponent != this->NegativeExponent)
  {
    this->NegativeExponent = exponent;
    this->ClampExponents();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkVarianceShadowMapRepresentation::StoresChebyshevMoments() const
{
  return this->Moments == MSM && this->Storage == HALF_FLOAT;
}

//------------------------------------------------------------------------------
double vtkVarianceShadowMapRepresentation::GetMaximumExponent() const
{
  const double largest = this->Storage == FLOAT ? LargestExponent32 : LargestExponent16;
  // Variance maps store the square too.
  const double limit = this->Moments == ESM ? largest : 0.5 * largest;
  // Headroom for the blur's and the filtering's weighted sums.
  return std::floor(limit * 0.95 * 100.0) / 100.0;
}

//------------------------------------------------------------------------------
double vtkVarianceShadowMapRepresentation::GetWarpExponent() const
{
  // ESM has no variance to absorb filtering: the steepest warp the storage holds.
  return this->Moments == ESM ? this->GetMaximumExponent() : this->PositiveExponent;
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::ClampExponents()
{
  if (this->Moments == VSM || this->Moments == MSM)
  {
    // They warp no depth: the exponents are clamped when moments that do are chosen.
    return;
  }
  const double maximum = this->GetMaximumExponent();
  if (this->PositiveExponent > maximum || this->NegativeExponent > maximum)
  {
    vtkWarningMacro(<< "Exponents " << this->PositiveExponent << " and " << this->NegativeExponent
                    << " exceed what " << this->Storage
                    << "-bit storage holds for these moments; reduced to " << maximum << ".");
    this->PositiveExponent = std::min(this->PositiveExponent, maximum);
    this->NegativeExponent = std::min(this->NegativeExponent, maximum);
  }
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::GetMomentsOfDepth(double depth, double moments[4]) const
{
  const double d = std::min(std::max(depth, 0.0), 1.0);
  const double warped = 2.0 * d - 1.0;
  const double positive = std::exp(this->GetWarpExponent() * warped);
  const double negative = -std::exp(-this->NegativeExponent * warped);
  switch (this->Moments)
  {
    case VSM:
      moments[0] = d;
      moments[1] = d * d;
      moments[2] = moments[3] = 0.0;
      break;
    case EVSM2:
    case EVSM4:
      moments[0] = positive;
      moments[1] = positive * positive;
      moments[2] = this->Moments == EVSM4 ? negative : 0.0;
      moments[3] = this->Moments == EVSM4 ? negative * negative : 0.0;
      break;
    case MSM:
      if (this->StoresChebyshevMoments())
      {
        // Shaders/vtkShadowMapsMomentsFS.glsl says why.
        const double u = warped;
        const double polynomials[4] = { u, 2.0 * u * u - 1.0, u * (4.0 * u * u - 3.0),
          8.0 * u * u * (u * u - 1.0) + 1.0 };
        std::transform(polynomials, polynomials + 4, moments, [](double t) { return 0.5 + 0.5 * t; });
        break;
      }
      moments[0] = d;
      moments[1] = d * d;
      moments[2] = d * d * d;
      moments[3] = d * d * d * d;
      break;
    default:
      moments[0] = positive;
      moments[1] = moments[2] = moments[3] = 0.0;
  }
}

//------------------------------------------------------------------------------
std::string vtkVarianceShadowMapRepresentation::MomentDefinitions() const
{
  std::ostringstream definitions;
  // The exponents are uniforms (ExponentUniforms): a slider builds no shader.
  definitions << "#define VTK_SHADOW_MOMENTS " << this->Moments << "\n"
              << "#define VTK_SHADOW_CHEBYSHEV_BASIS " << this->StoresChebyshevMoments() << "\n";
  return definitions.str();
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::GetMapStorage(shadowmaps::MapStorage& storage) const
{
  using shadowmaps::TexelFormat;
  storage = shadowmaps::MapStorage();
  const bool four = this->Moments == EVSM4 || this->Moments == MSM;
  const bool half = this->Storage == HALF_FLOAT;
  storage.Format = this->StoresChebyshevMoments() ? TexelFormat::FourNormalized16
    : four ? (half ? TexelFormat::FourHalfFloats : TexelFormat::FourFloats)
           : (half ? TexelFormat::TwoHalfFloats : TexelFormat::TwoFloats);
  storage.LightDepth = true;
  storage.StoreFunctions = this->MomentDefinitions() + vtkShadowMapsMomentsFS;
  storage.StoreCode = "    gl_FragData[0] = vtkShadowMomentsOf(vtkShadowCasterDepth);";
  storage.StoreUniforms = this->ExponentUniforms();
  double far[4];
  this->GetMomentsOfDepth(1.0, far);
  std::transform(far, far + 4, storage.ClearValues, [](double v) { return static_cast<float>(v); });
  storage.Mipmaps = this->Mipmaps;
  storage.Samples = this->CasterSamples;
  const bool warped = this->Moments == EVSM2 || this->Moments == EVSM4 || this->Moments == ESM;
  storage.WarpExponent = warped ? this->GetWarpExponent() : 0.0;
}

//------------------------------------------------------------------------------
std::string vtkVarianceShadowMapRepresentation::GetReceiverLookupCode() const
{
  return std::string(vtkShadowMapsMomentsFS) + vtkShadowMapsVarianceLookupFS;
}

//------------------------------------------------------------------------------
std::string vtkVarianceShadowMapRepresentation::GetSoftShadowCode() const
{
  // ESM keeps no variance; EVSM2's one warp squeezes the blockers' depths,
  // far in front of a receiver, into too few digits of the moments' mean for
  // their own mean to be recovered (docs/SOFT.md).
  if (this->Moments == ESM || this->Moments == EVSM2 || !this->Mipmaps)
  {
    return std::string();
  }
  return std::string(vtkShadowMapsSoftKernelFS) + vtkShadowMapsSoftMomentsFS;
}

//------------------------------------------------------------------------------
std::string vtkVarianceShadowMapRepresentation::GetReceiverDefinitions() const
{
  return this->MomentDefinitions() + "#define VTK_SHADOW_MAP_FOOTPRINT\n";
}

//------------------------------------------------------------------------------
double vtkVarianceShadowMapRepresentation::GetFilterReachTexels() const
{
  // The blur's kernel, and the bilinear sample's texel beyond it.
  return std::ceil(2.0 * shadowmaps::BlurSigma(this->BlurRadius)) + 1.0;
}

//------------------------------------------------------------------------------
bool vtkVarianceShadowMapRepresentation::PostProcessMaps(vtkOpenGLRenderer* renderer,
  shadowmaps::TextureArray& maps, const std::vector<shadowmaps::RenderedLayer>& layers)
{
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  std::unique_ptr<shadowmaps::MapBlur>& blur = this->BlurPerWindow[window];
  if (!blur)
  {
    blur.reset(new shadowmaps::MapBlur());
  }
  for (const shadowmaps::RenderedLayer& layer : layers)
  {
    std::string error;
    if (!blur->Blur(window, maps, layer.Layer, this->BlurRadius * layer.FilterScale, error))
    {
      vtkWarningMacro(<< error);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVarianceShadowMapRepresentation::GetPostProcessingFollowsFilterScale() const
{
  return this->BlurRadius > 0.0;
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::ActivateReceiverResources(vtkOpenGLRenderWindow* window)
{
  this->Noise->Activate(window);
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::SetReceiverUniforms(
  vtkShaderProgram* program, const std::string& nameSuffix)
{
  this->Noise->SetUniform(program, nameSuffix);
  const auto blurSigma = static_cast<float>(shadowmaps::BlurSigma(this->BlurRadius));
  shadowmaps::FloatUniforms uniforms = this->ExponentUniforms();
  uniforms.insert(uniforms.end(),
    { { "vtkShadowLightBleeding", static_cast<float>(this->LightBleedingReduction) },
      { "vtkShadowMinimumVariance", static_cast<float>(this->MinimumVariance) },
      { "vtkShadowMomentBias", static_cast<float>(this->MomentBias) },
      { "vtkShadowMomentsBlurSigma", blurSigma },
      { "vtkShadowAnisotropy", static_cast<float>(this->Anisotropy) } });
  shadowmaps::SetFloatUniforms(program, uniforms, nameSuffix);
}

//------------------------------------------------------------------------------
std::vector<std::pair<std::string, float>> vtkVarianceShadowMapRepresentation::ExponentUniforms()
  const
{
  return { { "vtkShadowPositiveExponent", static_cast<float>(this->GetWarpExponent()) },
    { "vtkShadowNegativeExponent", static_cast<float>(this->NegativeExponent) } };
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::DeactivateReceiverResources()
{
  this->Noise->Deactivate();
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Noise->ReleaseGraphicsResources(window);
  const auto found = this->BlurPerWindow.find(window);
  if (found != this->BlurPerWindow.end())
  {
    found->second->ReleaseGraphicsResources(window);
    this->BlurPerWindow.erase(found);
  }
}

//------------------------------------------------------------------------------
void vtkVarianceShadowMapRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Moments: " << this->Moments << "\n";
  os << indent << "Storage: " << this->Storage << "\n";
  os << indent << "PositiveExponent: " << this->PositiveExponent << "\n";
  os << indent << "NegativeExponent: " << this->NegativeExponent << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "Mipmaps: " << this->Mipmaps << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "CasterSamples: " << this->CasterSamples << "\n";
  os << indent << "LightBleedingReduction: " << this->LightBleedingReduction << "\n";
  os << indent << "MinimumVariance: " << this->MinimumVariance << "\n";
  os << indent << "MomentBias: " << this->MomentBias << "\n";
}
