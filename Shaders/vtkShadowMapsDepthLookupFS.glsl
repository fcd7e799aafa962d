// Comparison of depth maps (vtkDepthShadowMapRepresentation): one hardware
// comparison, hard or 2x2 bilinear by the map's texture filter (nearest /
// linear). vtkShadowMapsFilterFS builds the PCF family on it.

uniform sampler2DArrayShadow vtkShadowMaps;

float vtkShadowCompare(vec2 uv, float depth, int layer)
{
  return texture(vtkShadowMaps, vec4(uv, float(layer), depth));
}
