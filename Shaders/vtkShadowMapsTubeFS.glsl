// The window depth of a line drawn as a tube, while casting: where the ray of
// the map texel the fragment covers meets the tube vtkShadowMapsTubeGS passes
// (nearest the light), a cylinder capped at the line's ends whose radius is
// the one where the ray passes nearest its axis; texels whose rays miss it
// are discarded.
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
  // Ray and axis relative to the start: p(t) = w + t d, q(s) = s a.
  vec3 w = origin - vtkShadowTubeStart;
  float da = dot(direction, axis);
  float wa = dot(w, axis);
  float sine2 = 1.0 - da * da;
  float nearest = sine2 > 1e-6 ? (da * wa - dot(w, direction)) / sine2 : -dot(w, direction);
  float radius = mix(vtkShadowTubeRadii.x, vtkShadowTubeRadii.y,
    clamp((wa + nearest * da) / length_, 0.0, 1.0));
  // The side: the ray and the start across the axis.
  vec3 dAcross = direction - da * axis;
  vec3 wAcross = w - wa * axis;
  float b = dot(wAcross, dAcross);
  float discriminant = b * b - sine2 * (dot(wAcross, wAcross) - radius * radius);
  float t = nearest;
  bool hits = false;
  if (sine2 > 1e-6 && discriminant >= 0.0)
  {
    float side = (-b - sqrt(discriminant)) / sine2;
    float at = wa + side * da;
    hits = at >= 0.0 && at <= length_;
    t = hits ? side : t;
  }
  if (!hits && abs(da) > 1e-6)
  {
    // The cap the ray meets first, where it leaves the side's span.
    float capAt = da > 0.0 ? 0.0 : length_;
    float onCap = (capAt - wa) / da;
    vec3 fromCapCentre = w + onCap * direction - capAt * axis;
    hits = dot(fromCapCentre, fromCapCentre) <= radius * radius;
    t = hits ? onCap : t;
  }
  float depth = vtkShadowImpostorOffsetDepth(vtkShadowTubeStartClip, w + max(t, 0.0) * direction);
  if (!hits)
  {
    discard;
  }
  return depth;
}
