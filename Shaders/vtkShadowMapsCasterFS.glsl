// The casters' branch the shadow-map pass puts in every shader it builds. The
// same program draws a prop into the maps and into the scene, so that moving
// the camera, which re-renders the maps, rebuilds no shader: VTK's mapper keeps
// one program per primitive type and rebuilds it whenever the set of render
// passes on its prop changes. The uniform vtkShadowCasting selects the branch
// (ShadowMapCasterShader.cxx declares it once for every group's branch): the
// branch costs one test in the scene's draws.

// Face selection is done here rather than with GL_CULL_FACE because vtkProperty
// culling settings override that state.
bool vtkShadowCastsThisFace()
{
#if defined(VTK_SHADOW_CAST_FRONT_ONLY)
  return gl_FrontFacing;
#elif defined(VTK_SHADOW_CAST_BACK_ONLY)
  return !gl_FrontFacing;
#else
  return true;
#endif
}

#ifdef VTK_SHADOW_PEEL
// Depth peeling (two-surface maps): the second pass keeps the nearest surface
// behind the first pass's, whose depths it reads per texel. The same fragment
// of the same draw gets the same depth in both passes, so the nearest surface
// itself is peeled away exactly.
uniform int vtkShadowPeelSecondPass;
uniform sampler2D vtkShadowPeelDepths;

bool vtkShadowPeeledAway(float depth)
{
  return vtkShadowPeelSecondPass != 0 &&
    depth <= texelFetch(vtkShadowPeelDepths, ivec2(gl_FragCoord.xy), 0).x;
}
#endif

#ifdef VTK_SHADOW_LIGHT_DEPTH
// Filterable maps store the light depth (shadowmaps::LightDepth): linear in
// light space and shared by all views of a light, whatever a view's projection
// does to the window depth. The fragment's position, relative to the light
// depth's origin, is recovered from its window position, which works for every
// projective view.
uniform mat4 vtkShadowWindowToLight;

float vtkShadowLightDepthAtWindow(vec3 window)
{
  vec4 h = vtkShadowWindowToLight * vec4(window, 1.0);
  return vtkShadowLightDepthOf(h.xyz / h.w);
}

float vtkShadowLightDepthAt(float windowDepth)
{
  return vtkShadowLightDepthAtWindow(vec3(gl_FragCoord.xy, windowDepth));
}
#endif

#ifdef VTK_SHADOW_TRANSMITTANCE
// The window depth's change to the next texel along x and y, taken at the
// start of main(), before any discard (derivatives need uniform control flow).
float vtkShadowCasterDepthDx = 0.0;
float vtkShadowCasterDepthDy = 0.0;

// The light depth a translucent caster keeps: its own, moved away from the
// light by the depth it spans over two texels, so that a surface seen at a
// grazing angle from the light, whose texel holds nearer parts of it, does
// not shadow itself.
float vtkShadowTransmittedDepth(float windowDepth)
{
  float depth = vtkShadowLightDepthAt(windowDepth);
  float alongX = vtkShadowLightDepthAtWindow(
    vec3(gl_FragCoord.xy + vec2(1.0, 0.0), windowDepth + vtkShadowCasterDepthDx)) - depth;
  float alongY = vtkShadowLightDepthAtWindow(
    vec3(gl_FragCoord.xy + vec2(0.0, 1.0), windowDepth + vtkShadowCasterDepthDy)) - depth;
  return depth + 2.0 * max(abs(alongX), abs(alongY));
}

// The caster's own colour from VTK's diffuse colour, which is it times the
// property's Diffuse coefficient.
vec3 vtkShadowCasterColor(vec3 diffuse, float coefficient)
{
  return coefficient > 0.0 ? diffuse / coefficient : vec3(1.0);
}
#endif
