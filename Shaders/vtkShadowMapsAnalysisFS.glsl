// Analysis views (vtkAbstractShadowMapPass::AnalysisView), appended to the
// receivers' shadow code when one is on (shadowmaps::AddAnalysisReceiverCode).
// They replace the colour of the receivers, by VTK_SHADOW_ANALYSIS: 1 the
// analysed light's visibility as grey (per channel where translucent casters
// tint it); 2 the texel density as a heat map; 4
// the map (partition) each pixel was shaded from; 5 the kind of views the
// light got (VTK_SHADOW_VIEWS_COLOR), its odd maps a quarter darker.

// Screen pixels covered by one map texel, along one side: 1 / sqrt(|det J|)
// with J the derivative of texel coordinates by window pixels.
float vtkShadowTexelFootprint(vec4 clip)
{
  vec2 texel = clip.xy / clip.w * vtkShadowMapResolution;
  vec2 dx = dFdx(texel);
  vec2 dy = dFdy(texel);
  float texelsPerPixelArea = abs(dx.x * dy.y - dx.y * dy.x);
  return inversesqrt(max(texelsPerPixelArea, 1e-12));
}

// Not undersampled (footprint <= 1.5 pixels): blue (dense) to green (1.5), red
// channel at most 0.5. Undersampled: full red, the green fading from 0.6 as the
// footprint grows to 64 pixels; the benchmark counts red = 1 as undersampled.
vec3 vtkShadowDensityColor(float footprint)
{
  float octaves = log2(footprint);
  float limit = log2(1.5);
  if (octaves <= limit)
  {
    float t = clamp((octaves + 4.0) / (limit + 4.0), 0.0, 1.0);
    return mix(vec3(0.1, 0.2, 1.0), vec3(0.4, 0.9, 0.2), t);
  }
  float t = clamp((octaves - limit) / (6.0 - limit), 0.0, 1.0);
  return vec3(1.0, 0.6 * (1.0 - t), 0.0);
}

vec3 vtkShadowPartitionColor(int index)
{
  const vec3 palette[8] = vec3[8](vec3(0.9, 0.2, 0.2), vec3(0.2, 0.8, 0.2), vec3(0.2, 0.4, 1.0),
    vec3(0.95, 0.85, 0.2), vec3(0.8, 0.3, 0.9), vec3(0.2, 0.85, 0.85), vec3(1.0, 0.55, 0.1),
    vec3(0.6, 0.6, 0.6));
  return palette[index % 8];
}

vec4 vtkShadowAnalysisColor(
  vec3 positionVC, vec3 normalVC, int light, int firstView, int viewLayout, int count, int features)
{
  int view = vtkShadowSelectView(positionVC, normalVC, light, firstView, viewLayout, count, features);
  vec4 clip = vtkShadowMapClip(positionVC, normalVC, light, firstView, view, viewLayout, features);
  float footprint = vtkShadowTexelFootprint(clip);
  VTK_SHADOW_VALUE visibility =
    vtkShadowVisibility(positionVC, normalVC, light, firstView, viewLayout, count, features);
#if VTK_SHADOW_ANALYSIS == 1
  return vec4(vec3(visibility), 1.0);
#elif VTK_SHADOW_ANALYSIS == 2
  return vec4(vtkShadowInsideMap(clip, view, features) ? vtkShadowDensityColor(footprint) : vec3(0.0), 1.0);
#elif VTK_SHADOW_ANALYSIS == 4
  vec3 color = vtkShadowInsideMap(clip, view, features) ? vtkShadowPartitionColor(view - firstView) : vec3(0.0);
  return vec4(color * (0.5 + 0.5 * visibility), 1.0);
#else
  float shade = (view - firstView) % 2 == 1 ? 0.75 : 1.0;
  vec3 color = vtkShadowInsideMap(clip, view, features) ? shade * VTK_SHADOW_VIEWS_COLOR : vec3(0.0);
  return vec4(color * (0.5 + 0.5 * visibility), 1.0);
#endif
}
