// The window depth of a line drawn as a tube, while casting: where the ray of
// the map texel the fragment covers enters the tube vtkShadowMapsTubeGS passes
// (nearest the light), and where it leaves it. The tube is a cylinder capped
// at the line's ends, whose radius is the one where the ray passes nearest its
// axis: the ray's span inside the infinite cylinder, cut to its span between
// the caps' planes. Texels whose rays miss it are discarded.
flat in vec4 vtkShadowTubeStart;
flat in vec4 vtkShadowTubeEnd;
flat in vec4 vtkShadowTubeStartClip;

float vtkShadowTubeDepth()
{
  vec3 origin;
  vec3 direction;
  vtkShadowImpostorTexelRay(origin, direction);
  vec3 axis = vtkShadowTubeEnd.xyz - vtkShadowTubeStart.xyz;
  float length_ = max(length(axis), 1e-30);
  axis /= length_;
  // The ray from the start: w + t d; its distance along the axis: wa + t da.
  vec3 w = origin - vtkShadowTubeStart.xyz;
  float da = dot(direction, axis);
  float wa = dot(w, axis);
  float sine2 = 1.0 - da * da;
  // Divisions only by what is not near 0: GLSL leaves infinities undefined, and
  // a compiler may fold the branch that discards them.
  bool across = sine2 > 1e-6;
  bool alongAxis = abs(da) > 1e-6;
  float safeSine2 = across ? sine2 : 1.0;
  float safeDa = alongAxis ? da : 1.0;
  float nearest = across ? (da * wa - dot(w, direction)) / safeSine2 : -dot(w, direction);
  float radius = mix(vtkShadowTubeStart.w, vtkShadowTubeEnd.w,
    clamp((wa + nearest * da) / length_, 0.0, 1.0));
  // The ray's span inside the infinite cylinder (a ray along the axis: all
  // of it or none) and between the caps' planes (a ray across the axis: all
  // of it or none), then their common part. No infinities stand in for
  // "all": GLSL leaves them undefined.
  vec3 wAcross = w - wa * axis;
  vec3 dAcross = direction - da * axis;
  float b = dot(wAcross, dAcross);
  float c = dot(wAcross, wAcross) - radius * radius;
  float discriminant = b * b - sine2 * c;
  float halfChord = sqrt(max(discriminant, 0.0));
  vec2 sideSpan = vec2(-b - halfChord, -b + halfChord) / safeSine2;
  vec2 planes = vec2(-wa, length_ - wa) / safeDa;
  vec2 capsSpan = vec2(min(planes.x, planes.y), max(planes.x, planes.y));
  vec2 span = across && alongAxis
    ? vec2(max(sideSpan.x, capsSpan.x), min(sideSpan.y, capsSpan.y))
    : (across ? sideSpan : capsSpan);
  bool insideSide = across ? discriminant >= 0.0 : c <= 0.0;
  bool insideCaps = alongAxis || (wa >= 0.0 && wa <= length_);
  bool hits = insideSide && insideCaps && span.x <= span.y;
  // A part nearer the light than the near plane takes its depth (the
  // casters' depth clamp).
  float enters = max(span.x, 0.0);
  float leaves = max(span.y, 0.0);
  // Continuous where the ray grazes the tube, for the depths' derivatives.
  float t = hits ? enters : max(nearest, 0.0);
  float depth = vtkShadowImpostorOffsetDepth(vtkShadowTubeStartClip, w + t * direction);
  vtkShadowImpostorBackDepth =
    vtkShadowImpostorOffsetDepth(vtkShadowTubeStartClip, w + (hits ? leaves : t) * direction);
  if (!hits)
  {
    discard;
  }
  return depth;
}
