//VTK::System::Dec
// Shadow caster. Depth comes from the rasterizer (with the pass's polygon
// offset); maps that store values get them from the pass's store code. Face selection is done here rather than
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
//VTK::ShadowMaps::Impl
}
