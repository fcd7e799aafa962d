// The window depth of a point drawn as a sphere, while casting: where the ray
// of the map texel the fragment covers meets the sphere vtkShadowMapsSpriteVS
// passes (nearest the light), and where it leaves it; texels whose rays miss
// it are discarded.
flat in vec3 vtkShadowSpriteCentre;
flat in float vtkShadowSpriteRadius;
flat in vec4 vtkShadowSpriteClip;

float vtkShadowSpriteDepth()
{
  vec3 origin;
  vec3 direction;
  vtkShadowImpostorTexelRay(origin, direction);
  vec3 fromCentre = origin - vtkShadowSpriteCentre;
  float along = dot(fromCentre, direction);
  float radius = vtkShadowSpriteRadius;
  float discriminant = along * along - (dot(fromCentre, fromCentre) - radius * radius);
  // Continuous across the silhouette for the depths' derivatives, then cut.
  float halfChord = sqrt(max(discriminant, 0.0));
  float enters = max(-along - halfChord, 0.0);
  float leaves = max(-along + halfChord, 0.0);
  float depth = vtkShadowImpostorOffsetDepth(vtkShadowSpriteClip, fromCentre + enters * direction);
  vtkShadowImpostorBackDepth =
    vtkShadowImpostorOffsetDepth(vtkShadowSpriteClip, fromCentre + leaves * direction);
  if (discriminant < 0.0)
  {
    discard;
  }
  return depth;
}
