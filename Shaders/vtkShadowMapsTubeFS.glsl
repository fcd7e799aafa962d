// The window depth of a line drawn as a tube, while casting: where the ray of
// the map texel the fragment covers enters the tube vtkShadowMapsTubeGS passes
// (nearest the light), and where it leaves it. The tube is a cylinder capped
// at the line's ends, whose radius is the one where the ray passes nearest its
// axis: the ray's span inside the infinite cylinder, cut to its span between
// the caps' planes. Texels whose rays miss it are discarded.
flat in vec3 vtkShadowTubeStart;
flat in vec3 vtkShadowTubeEnd;
flat in vec2 vtkShadowTubeRadii;
flat in vec4 vtkShadowTubeStartClip;
uniform vec4 vtkShadowImpostorScale;

float vtkShadowTubeDepth()
{
  // The casters' viewport is the whole map layer.
  vec2 ndc = 2.0 * gl_FragCoord.xy / vtkShadowImpostorScale.z - 1.0;
  vec3 origin = vtkShadowImpostorRayPoint(ndc, -1.0);
  vec3 direction = normalize(vtkShadowImpostorRayPoint(ndc, 0.0) - origin);
  vec3 axis = vtkShadowTubeEnd - vtkShadowTubeStart;
  float length_ = max(length(axis), 1e-30);
  axis /= length_;
  // The ray from the start: w + t d; its distance along the axis: wa + t da.
  vec3 w = origin - vtkShadowTubeStart;
  float da = dot(direction, axis);
  float wa = dot(w, axis);
  float sine2 = 1.0 - da * da;
  float nearest = sine2 > 1e-6 ? (da * wa - dot(w, direction)) / sine2 : -dot(w, direction);
  float radius = mix(vtkShadowTubeRadii.x, vtkShadowTubeRadii.y,
    clamp((wa + nearest * da) / length_, 0.0, 1.0));
  // Inside the infinite cylinder (a ray along the axis: inside or not, everywhere).
  vec3 wAcross = w - wa * axis;
  vec3 dAcross = direction - da * axis;
  float b = dot(wAcross, dAcross);
  float c = dot(wAcross, wAcross) - radius * radius;
  float discriminant = b * b - sine2 * c;
  float halfChord = sqrt(max(discriminant, 0.0));
  vec2 side = sine2 > 1e-6 ? vec2(-b - halfChord, -b + halfChord) / sine2
                           : (c <= 0.0 ? vec2(-1e30, 1e30) : vec2(1e30, -1e30));
  // Between the caps' planes.
  vec2 planes = vec2(-wa, length_ - wa) / da;
  vec2 caps = abs(da) > 1e-6 ? vec2(min(planes.x, planes.y), max(planes.x, planes.y))
                             : (wa >= 0.0 && wa <= length_ ? vec2(-1e30, 1e30) : vec2(1e30, -1e30));
  // Spans, not their parts beyond the near plane: a part nearer the light
  // than the near plane takes its depth (the casters' depth clamp).
  float entry = max(side.x, caps.x);
  float exit = min(side.y, caps.y);
  bool hits = discriminant >= 0.0 && entry <= exit;
  float enters = max(entry, 0.0);
  float leaves = max(exit, 0.0);
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
