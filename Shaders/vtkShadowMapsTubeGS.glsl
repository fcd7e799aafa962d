// Lines drawn as tubes (RenderLinesAsTubes) are quads that VTK's geometry
// shader widens to the line width in pixels. Drawn into a map as they are, they
// would be that width in map texels. While casting, each corner is put instead
// where the quad holds the map's image of the tube the scene camera shows (its
// radius at each end from vtkShadowMapsImpostorSizes, capped at the ends): in
// the plane across the light's direction at that end, across the line and a
// radius beyond the end, widened as the light's tangent planes widen it. The
// tube goes to vtkShadowMapsTubeFS, which finds where each texel's ray meets it.
flat out vec3 vtkShadowTubeStart;
flat out vec3 vtkShadowTubeEnd;
flat out vec2 vtkShadowTubeRadii;
flat out vec4 vtkShadowTubeStartClip;

// Corner `corner` of the line's quad, in VTK's order: two at each end, the
// first of each on the positive side.
vec4 vtkShadowTubeCorner(int corner)
{
  vec3 first = vtkShadowImpostorWorld(gl_in[0].gl_Position);
  vec3 last = vtkShadowImpostorWorld(gl_in[1].gl_Position);
  vtkShadowTubeStart = first;
  vtkShadowTubeEnd = last;
  vtkShadowTubeRadii = vec2(vtkShadowImpostorRadius(first), vtkShadowImpostorRadius(last));
  vtkShadowTubeStartClip = gl_in[0].gl_Position;

  bool atStart = corner < 2;
  vec3 end = atStart ? first : last;
  float radius = atStart ? vtkShadowTubeRadii.x : vtkShadowTubeRadii.y;
  vec3 toLight = vtkShadowImpostorToLight(end);
  float distance = vtkShadowImpostorLight.w > 0.5 ? length(vtkShadowImpostorLight.xyz - end) : 0.0;
  float ratio = distance > 0.0 ? min(radius / distance, 0.99) : 0.0;
  float reach = 1.05 * radius / sqrt(1.0 - ratio * ratio);
  vec3 across = vtkShadowImpostorAcross(last - first, toLight);
  vec3 along = cross(toLight, across);
  float outward = (atStart ? -1.0 : 1.0) * (dot(last - first, along) < 0.0 ? -1.0 : 1.0);
  float side = corner % 2 == 0 ? 1.0 : -1.0;
  return vtkShadowImpostorClipOffset(
    gl_in[atStart ? 0 : 1].gl_Position, reach * (side * across + outward * along));
}
