//VTK::System::Dec
// The SHADOW_MAP analysis view: the analysed light's maps tiled over the
// viewport, depth (or the first stored value) as grey.
in vec2 texCoord;
uniform sampler2DArray vtkShadowMaps;
uniform int vtkShadowFirstView;
uniform int vtkShadowViewCount;
//VTK::Output::Dec

void main()
{
  int columns = int(ceil(sqrt(float(vtkShadowViewCount))));
  int rows = (vtkShadowViewCount + columns - 1) / columns;
  vec2 cell = texCoord * vec2(float(columns), float(rows));
  ivec2 index = min(ivec2(floor(cell)), ivec2(columns - 1, rows - 1));
  int view = (rows - 1 - index.y) * columns + index.x;
  if (view >= vtkShadowViewCount)
  {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  float value = texture(vtkShadowMaps, vec3(fract(cell), float(vtkShadowFirstView + view))).x;
  gl_FragData[0] = vec4(vec3(value), 1.0);
}
