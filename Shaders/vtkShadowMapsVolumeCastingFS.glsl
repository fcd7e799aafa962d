//VTK::System::Dec
// The volumes' marcher (shadowmaps::VolumeCasters): where a light ray leaves
// a volume's box, what the volume lets through along it, marched in thin
// slices of the translucent surfaces' model (VolumeReading,
// docs/TRANSLUCENT.md), and the light depth where it starts to absorb. Drawn
// into a transmittance layer, whose blending multiplies the colours and keeps
// the least depth. Positions are in box coordinates: the unit cube over the
// image's bounds.
in vec3 boxPosition;

uniform sampler3D vtkVolumeScalars;   // normalized over the table's range; g: 1 where defined
uniform sampler2D vtkVolumeTable;     // colour, opacity over that range
uniform int vtkVolumeTableSize;
uniform vec3 vtkVolumeTextureScale;   // box to texture coordinates
uniform vec3 vtkVolumeTextureShift;
uniform int vtkVolumePositional;
uniform vec3 vtkVolumeLight;          // the light's position, or the direction it shines, in the box
uniform vec3 vtkVolumeBoxSides;       // the box's sides in data lengths
uniform mat4 vtkVolumeBoxToLight;     // to positions relative to the light depth's origin
uniform float vtkVolumeDataStep;      // the data length of a step
uniform int vtkVolumeMostSteps;
uniform float vtkVolumeUnitDistance;  // a data length, as the step's
// The mapper's clipping planes in box coordinates: a sample p is kept where
// dot(plane, vec4(p, 1)) >= 0.
uniform int vtkVolumeClippingPlaneCount;
uniform vec4 vtkVolumeClippingPlanes[6];
//VTK::Output::Dec

// Where the line p + t d, d of unit length, is inside the unit cube: [enter, leave].
vec2 vtkVolumeCrossing(vec3 p, vec3 d)
{
  vec2 inside = vec2(-1e30, 1e30);
  for (int axis = 0; axis < 3; ++axis)
  {
    if (abs(d[axis]) > 1e-12)
    {
      float t0 = (0.0 - p[axis]) / d[axis];
      float t1 = (1.0 - p[axis]) / d[axis];
      inside = vec2(max(inside.x, min(t0, t1)), min(inside.y, max(t0, t1)));
    }
  }
  return inside;
}

bool vtkVolumeClippedAway(vec3 p)
{
  for (int i = 0; i < vtkVolumeClippingPlaneCount; ++i)
  {
    if (dot(vtkVolumeClippingPlanes[i], vec4(p, 1.0)) < 0.0)
    {
      return true;
    }
  }
  return false;
}

void main()
{
  vec3 toward = vtkVolumePositional != 0 ? boxPosition - vtkVolumeLight : vtkVolumeLight;
  float fromLight = length(toward);
  if (!(fromLight > 0.0))
  {
    discard;
  }
  vec3 d = toward / fromLight;
  vec2 inside = vtkVolumeCrossing(boxPosition, d);
  // Each ray is marched once, from the face it leaves the box by (a box seen
  // edge-on may count twice, over a length that absorbs nothing).
  if (inside.y > 1e-4)
  {
    discard;
  }
  float enter = vtkVolumePositional != 0 ? max(inside.x, -fromLight) : inside.x;
  if (!(enter < 0.0))
  {
    discard;
  }
  vec3 start = boxPosition + enter * d;
  vec3 span = boxPosition - start;
  int steps = int(clamp(ceil(length(vtkVolumeBoxSides * span) / vtkVolumeDataStep), 1.0,
    float(vtkVolumeMostSteps)));
  vec3 step = span / float(steps);
  float exponent = length(vtkVolumeBoxSides * step) / vtkVolumeUnitDistance;
  float tableScale = float(vtkVolumeTableSize - 1) / float(vtkVolumeTableSize);
  float tableShift = 0.5 / float(vtkVolumeTableSize);
  vec3 transmitted = vec3(1.0);
  bool absorbed = false;
  vec3 firstAbsorbing = start;
  for (int i = 0; i < steps; ++i)
  {
    vec3 at = start + (float(i) + 0.5) * step;
    if (vtkVolumeClippedAway(at))
    {
      continue;
    }
    vec2 sampled = texture(vtkVolumeScalars, at * vtkVolumeTextureScale + vtkVolumeTextureShift).rg;
    if (sampled.g < 0.9999)
    {
      continue; // next to a voxel without data: nothing absorbs
    }
    vec4 entry = texture(vtkVolumeTable, vec2(sampled.r * tableScale + tableShift, 0.5));
    float a = clamp(entry.a, 0.0, 1.0);
    float alpha = a >= 1.0 ? 1.0 : 1.0 - pow(1.0 - a, exponent);
    if (alpha > 0.0 && !absorbed)
    {
      absorbed = true;
      firstAbsorbing = at - 0.5 * step;
    }
    transmitted *= vtkShadowTransmitted(entry.rgb, alpha);
    if (all(equal(transmitted, vec3(0.0))))
    {
      break;
    }
  }
  if (!absorbed)
  {
    discard;
  }
  vec4 relative = vtkVolumeBoxToLight * vec4(firstAbsorbing, 1.0);
  gl_FragData[0] = vec4(transmitted, vtkShadowLightDepthOf(relative.xyz / relative.w));
}
