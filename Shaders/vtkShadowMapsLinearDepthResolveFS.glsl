//VTK::System::Dec
// Copies the linear depths a view's casters wrote as colour into the map
// layer's depth (shadowmaps::LinearDepthResolve).
in vec2 texCoord;
uniform sampler2D vtkShadowLinearDepths;
//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(vtkShadowLinearDepths, 0);
  gl_FragDepth = texelFetch(vtkShadowLinearDepths, ivec2(texCoord * vec2(size)), 0).r;
}
