// Lines drawn as tubes (RenderLinesAsTubes) are quads that VTK's geometry
// shader widens to the line width in pixels. Drawn into a map as they are, they
// would be that width in map texels. While casting, each corner is put instead
// where the quad holds the map's image of the tube the scene camera shows (its
// radius at each end from vtkShadowMapsImpostorSizes, capped at the ends): in
// the plane across the light's direction at that end, across the line and a
// radius beyond the end, widened as the light's tangent planes widen it. The
// tube goes to vtkShadowMapsTubeFS, which finds where each texel's ray meets it.

// The tube, the same at every corner: its start and radius there (xyz, w),
// its end and radius there, and the start's clip position.
flat out vec4 vtkShadowTubeStart;
flat out vec4 vtkShadowTubeEnd;
flat out vec4 vtkShadowTubeStartClip;

// Corner `corner` of the line's quad, in VTK's order: two at each end, the
// first of each on the positive side.
vec4 vtkShadowTubeCorner(int corner)
{
  vec3 first = vtkShadowImpostorWorld(gl_in[0].gl_Position);
  vec3 last = vtkShadowImpostorWorld(gl_in[1].gl_Position);
  vtkShadowTubeStart = vec4(first, vtkShadowImpostorRadius(first));
  vtkShadowTubeEnd = vec4(last, vtkShadowImpostorRadius(last));
  vtkShadowTubeStartClip = gl_in[0].gl_Position;

  bool atStart = corner < 2;
  vec3 end = atStart ? first : last;
  float radius = atStart ? vtkShadowTubeStart.w : vtkShadowTubeEnd.w;
  vec3 toLight = vtkShadowImpostorToLight(end);
  float reach = 1.05 * vtkShadowImpostorConeRadius(end, radius);
  vec3 across = vtkShadowImpostorAcross(last - first, toLight);
  vec3 along = cross(toLight, across);
  float outward = (atStart ? -1.0 : 1.0) * (dot(last - first, along) < 0.0 ? -1.0 : 1.0);
  float side = corner % 2 == 0 ? 1.0 : -1.0;
  // gl_in indexed by constants: with an index chosen at run time llvmpipe
  // (Mesa 25) drew nothing, or crashed.
  vec4 endClip = atStart ? gl_in[0].gl_Position : gl_in[1].gl_Position;
  return vtkShadowImpostorClipOffset(endClip, reach * (side * across + outward * along));
}
