//VTK::System::Dec
// The SHADOW_MAP analysis view: the analysed light's maps tiled over the
// viewport, depth (or the first stored value) as grey; maps of two surfaces
// (dual depth) show the nearest on the left of their tile, the next on the right;
// exponentially warped values (vtkShadowWarpExponent c > 0: exp(c (2d - 1)))
// show their depth d.
in vec2 texCoord;
uniform sampler2DArray vtkShadowMaps;
uniform int vtkShadowFirstView;
uniform int vtkShadowViewCount;
uniform int vtkShadowSurfaces;
uniform float vtkShadowWarpExponent;
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
  vec2 inTile = fract(cell);
  int surface = 0;
  if (vtkShadowSurfaces == 2)
  {
    surface = inTile.x < 0.5 ? 0 : 1;
    inTile.x = fract(2.0 * inTile.x);
  }
  vec4 stored = texture(vtkShadowMaps, vec3(inTile, float(vtkShadowFirstView + view)));
  float value = surface == 0 ? stored.x : stored.y;
  if (vtkShadowWarpExponent > 0.0)
  {
    value = 0.5 * log(max(value, 1e-38)) / vtkShadowWarpExponent + 0.5;
  }
  gl_FragData[0] = vec4(vec3(value), 1.0);
}
