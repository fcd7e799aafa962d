// Comparison of depth maps (vtkDepthShadowMapRepresentation): one hardware
// comparison, hard or 2x2 bilinear by the map's texture filter (nearest /
// linear). vtkShadowMapsFilterFS builds the PCF family on it.

uniform sampler2DArrayShadow vtkShadowMaps;

float vtkShadowCompare(vec2 uv, float depth, int layer)
{
  return texture(vtkShadowMaps, vec4(uv, float(layer), depth));
}

#ifdef VTK_SHADOW_SIZED_LIGHTS
// The same maps without comparison (a sampler object on another unit), for
// the soft shadows' blocker search (vtkShadowMapsSoftFS).
uniform sampler2DArray vtkShadowDepths;

vec2 vtkShadowBlockerDepth(vec2 uv, int layer)
{
  return vec2(texture(vtkShadowDepths, vec3(uv, float(layer))).r);
}
#endif
