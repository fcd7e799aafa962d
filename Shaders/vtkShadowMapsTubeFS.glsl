// The window depth of a line drawn as a tube, while casting: between its
// centre line's and that of its points nearest the light
// (vtkShadowMapsTubeGS), by the tube's normal towards the viewer of the map.
noperspective in float vtkShadowTubeNearDepth;
noperspective in float vtkShadowTubeSide;

float vtkShadowTubeDepth()
{
  return mix(gl_FragCoord.z, vtkShadowTubeNearDepth,
    sqrt(max(1.0 - vtkShadowTubeSide * vtkShadowTubeSide, 0.0)));
}
