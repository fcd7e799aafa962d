//VTK::System::Dec
// Depth-only shadow caster. Depth comes from the rasterizer (with the pass's
// polygon offset); no colour is stored. Face selection is done here rather than
// with GL_CULL_FACE because vtkProperty culling settings override that state.
//VTK::ShadowMaps::Dec
//VTK::Output::Dec

void main()
{
#if defined(VTK_SHADOW_CAST_FRONT_ONLY)
  if (!gl_FrontFacing)
  {
    discard;
  }
#elif defined(VTK_SHADOW_CAST_BACK_ONLY)
  if (gl_FrontFacing)
  {
    discard;
  }
#endif
  gl_FragData[0] = vec4(1.0);
}
