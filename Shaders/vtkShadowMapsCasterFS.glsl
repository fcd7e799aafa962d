// The casters' branch the shadow-map pass puts in every shader it builds. The
// same program draws a prop into the maps and into the scene, so that moving
// the camera, which re-renders the maps, rebuilds no shader: VTK's mapper keeps
// one program per primitive type and rebuilds it whenever the set of render
// passes on its prop changes. vtkShadowCasting selects the branch (a uniform:
// the branch costs one test in the scene's draws).
uniform int vtkShadowCasting;

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
