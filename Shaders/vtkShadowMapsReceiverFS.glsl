// Shadow-map receiver functions, injected into a mapper's fragment shader after
// its lighting declarations. The pass defines before this block:
//   VTK_SHADOW_FILTER          0 hard, 1 hardware 2x2 PCF, 2 N x N PCF, 3 Poisson
//   VTK_SHADOW_KERNEL          N of the N x N filter
//   VTK_SHADOW_POISSON_SAMPLES taps of the Poisson filter
//   VTK_SHADOW_MAX_VIEWS, VTK_SHADOW_MAX_LIGHTS  array sizes
// and appends after it the lookup of its texel storage, which declares the
// sampler vtkShadowMaps and defines vtkShadowLookup (vtkShadowMapsDepthLookupFS
// for depth maps).

uniform sampler2D vtkShadowNoise;
uniform mat4 vtkShadowViewToWorld;
uniform mat4 vtkShadowWorldToMap[VTK_SHADOW_MAX_VIEWS];
// World-space size of one texel of a view: x + y * (distance to the light).
uniform vec2 vtkShadowTexelSize[VTK_SHADOW_MAX_VIEWS];
uniform vec3 vtkShadowLightPosition[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_MAX_LIGHTS];
uniform float vtkShadowMapResolution;
uniform float vtkShadowNormalOffset;
uniform float vtkShadowFilterRadius;

// Visibility in [0, 1] of the map point mapCoord (xy: texture coordinates,
// z: the receiver's depth in the map) in layer `layer`.
float vtkShadowLookup(vec3 mapCoord, int layer);

// Cube face order +x, -x, +y, -y, +z, -z (see shadowmaps::CubeFaceIndex).
int vtkShadowCubeFace(vec3 d)
{
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z)
  {
    return d.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z)
  {
    return d.y >= 0.0 ? 2 : 3;
  }
  return d.z >= 0.0 ? 4 : 5;
}

// Fraction of light `light` reaching the receiver, in [0, 1]. The light's views
// start at layer firstView; a cube light has six of them.
float vtkShadowVisibility(vec3 positionWorld, vec3 normalWorld, int light, int firstView, bool cube)
{
  vec3 fromLight = positionWorld - vtkShadowLightPosition[light];
  int view = cube ? firstView + vtkShadowCubeFace(fromLight) : firstView;
  vec2 texelSize = vtkShadowTexelSize[view];
  float texel = texelSize.x + texelSize.y * length(fromLight);
  // Normal offset scaled by the world-space texel size (Kozlov, GPU Gems 14).
  vec3 biased = positionWorld + normalWorld * (vtkShadowNormalOffset * texel);
  vec4 clip = vtkShadowWorldToMap[view] * vec4(biased, 1.0);
  if (clip.w <= 0.0)
  {
    return 1.0;
  }
  vec3 mapCoord = clip.xyz / clip.w;
  if (any(lessThan(mapCoord, vec3(0.0))) || any(greaterThan(mapCoord, vec3(1.0))))
  {
    return 1.0;
  }
  return vtkShadowLookup(mapCoord, view);
}

// Factor that scales the light's diffuse and specular terms.
float vtkShadowFactor(vec3 positionWorld, vec3 normalWorld, int light, int firstView, bool cube)
{
  float visibility = vtkShadowVisibility(positionWorld, normalWorld, light, firstView, cube);
  return 1.0 - vtkShadowAttenuation[light] * (1.0 - visibility);
}
