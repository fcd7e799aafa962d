//VTK::System::Dec
// One direction of the separable Gaussian blur of value maps
// (shadowmaps::MapBlur): texels beyond the map's edge repeat the edge.
in vec2 texCoord;
uniform sampler2DArray vtkShadowBlurSource;
uniform int vtkShadowBlurLayer;
uniform ivec2 vtkShadowBlurStep;
uniform int vtkShadowBlurTaps;
uniform float vtkShadowBlurSigma;
//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(vtkShadowBlurSource, 0).xy;
  ivec2 texel = ivec2(texCoord * vec2(size));
  float twoSigmaSquared = 2.0 * vtkShadowBlurSigma * vtkShadowBlurSigma;
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int i = -vtkShadowBlurTaps; i <= vtkShadowBlurTaps; ++i)
  {
    ivec2 at = clamp(texel + i * vtkShadowBlurStep, ivec2(0), size - 1);
    float weight = exp(-float(i * i) / twoSigmaSquared);
    sum += weight * texelFetch(vtkShadowBlurSource, ivec3(at, vtkShadowBlurLayer), 0);
    weights += weight;
  }
  gl_FragData[0] = sum / weights;
}
