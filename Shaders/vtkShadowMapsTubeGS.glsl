// Lines drawn as tubes (RenderLinesAsTubes) are quads that VTK's geometry
// shader widens to the line width in pixels. Drawn into a map as
// they are, they would be that width in map texels. While casting, each corner
// is put instead a tube's radius (vtkShadowMapsImpostorSizes) from the line,
// across both the line and the light's direction, in world space: the shadow
// of the tube the scene camera shows, at least as long as wide where the light
// sees the line end-on. Each corner also passes the window depth
// of the line's point nearest the light and its side of the line, for
// vtkShadowMapsTubeFS's depth.
noperspective out float vtkShadowTubeNearDepth;
noperspective out float vtkShadowTubeSide;

// Corner `corner` of the line's quad, in VTK's order: two at each end, the
// first of each on the positive side.
vec4 vtkShadowTubeCorner(int corner)
{
  vec3 first = vtkShadowImpostorWorld(gl_in[0].gl_Position);
  vec3 last = vtkShadowImpostorWorld(gl_in[1].gl_Position);
  vec3 end = corner < 2 ? first : last;
  float radius = vtkShadowImpostorRadius(end);
  vec3 toLight = vtkShadowImpostorToLight(end);
  vtkShadowTubeSide = corner % 2 == 0 ? 1.0 : -1.0;
  vtkShadowTubeNearDepth = vtkShadowImpostorWindowDepth(end + radius * toLight);
  vec3 across = vtkShadowImpostorAcross(last - first, toLight);
  // A segment the light sees nearly end-on would cast a sliver: its ends move
  // apart along the line, across the light, until it is as long as it is wide.
  vec3 along = cross(toLight, across);
  float seen = abs(dot(last - first, along));
  float extension = max(radius - 0.5 * seen, 0.0) * (corner < 2 ? -1.0 : 1.0) *
    (dot(last - first, along) < 0.0 ? -1.0 : 1.0);
  return vtkShadowImpostorClip(end + vtkShadowTubeSide * radius * across + extension * along);
}
