//VTK::System::Dec
// The volumes' marcher (shadowmaps::VolumeCasters): the faces of a volume's
// box, a unit cube, seen from a layer's light view.
in vec4 vertexMC;
uniform mat4 vtkVolumeBoxToClip;
out vec3 boxPosition;

void main()
{
  boxPosition = vertexMC.xyz;
  gl_Position = vtkVolumeBoxToClip * vec4(vertexMC.xyz, 1.0);
}
