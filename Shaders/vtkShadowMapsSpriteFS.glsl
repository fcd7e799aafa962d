// The window depth of a point drawn as a sphere, while casting: where the ray
// of the map texel the fragment covers meets the sphere vtkShadowMapsSpriteVS
// passes (nearest the light), and where it leaves it; texels whose rays miss
// it are discarded.
flat in vec3 vtkShadowSpriteCentre;
flat in float vtkShadowSpriteRadius;
flat in vec4 vtkShadowSpriteClip;
flat in float vtkShadowSpriteReach;
flat in vec4 vtkShadowSpriteNear;
flat in vec4 vtkShadowSpriteMiddle;

float vtkShadowSpriteDepth()
{
  // gl_PointCoord runs down the square.
  vec2 offset = vtkShadowSpriteReach * vec2(2.0 * gl_PointCoord.x - 1.0, 1.0 - 2.0 * gl_PointCoord.y);
  vec4 across = vtkShadowImpostorClipToWorld[0] * offset.x + vtkShadowImpostorClipToWorld[1] * offset.y;
  vec4 near = vtkShadowSpriteNear + across;
  vec4 middle = vtkShadowSpriteMiddle + across;
  vec3 origin = near.xyz / near.w;
  vec3 direction = normalize(middle.xyz / middle.w - origin);
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
