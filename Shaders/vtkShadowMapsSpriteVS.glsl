// Points drawn as spheres (RenderPointsAsSpheres) are squares that the
// rasteriser sizes in pixels and the fragment shader rounds. Drawn into a map as
// they are, they would be the point's size in map texels. While casting, this
// sizes each point to hold the image of the sphere the scene camera shows
// (vtkShadowMapsImpostorSizes) in the map, and passes the sphere to
// vtkShadowMapsSpriteFS, which finds where each texel's ray meets it. A
// perspective map draws an off-axis sphere as an ellipse, longer than wide
// and off the centre's image: the square holds the circle through its
// farthest point.
flat out vec3 vtkShadowSpriteCentre;
flat out float vtkShadowSpriteRadius;
flat out vec4 vtkShadowSpriteClip;

// The GL drops a point whose centre lies outside the view, however far its
// square reaches into it, and caps its size (255 texels on llvmpipe): the
// square `reach` (normalized device coordinates) each side of `centre` is
// drawn as the square that holds its part inside the view, centred in that
// part. A sphere across a cube face's or a cascade's edge casts in both
// layers, and one half outside a layer needs half the size. (The casters'
// branch finds the sphere in each texel's ray: where the square lies does not
// matter to it.)
void vtkShadowDrawPartInView(vec2 centre, float reach)
{
  vec2 low = max(centre - reach, vec2(-1.0));
  vec2 high = min(centre + reach, vec2(1.0));
  vec2 halfSide = max(high - low, vec2(0.0)) * 0.5;
  // Half a texel's margin each side.
  gl_PointSize =
    min(max(halfSide.x, halfSide.y) * vtkShadowImpostorScale.z + 1.0, vtkShadowImpostorScale.w);
  if (gl_Position.w > 0.0)
  {
    gl_Position.xy = 0.5 * (low + high) * gl_Position.w;
  }
}

void vtkShadowSizeSprite()
{
  vec3 p = vtkShadowImpostorWorld(gl_Position);
  float radius = vtkShadowImpostorRadius(p);
  vec3 toLight = vtkShadowImpostorToLight(p);
  float cone = vtkShadowImpostorConeRadius(p, radius);
  // The image of that circle, to first order: the map's normalized device
  // coordinates change with world position by J (2 x 3) at the centre, and
  // the circle's image is an ellipse whose longer half-axis is the largest
  // singular value of J [u v] times its radius. A perspective map draws the
  // sphere larger than that on the side nearer its eye, by about the
  // radius over the depth: a margin of twice that.
  vec3 u = vtkShadowImpostorAcross(toLight, vec3(0.0, 0.0, 1.0));
  vec3 v = cross(toLight, u);
  mat4 m = vtkShadowImpostorWorldToClip;
  vec2 centre = gl_Position.xy / gl_Position.w;
  vec3 w = vec3(m[0][3], m[1][3], m[2][3]);
  vec3 jx = (vec3(m[0][0], m[1][0], m[2][0]) - centre.x * w) / gl_Position.w;
  vec3 jy = (vec3(m[0][1], m[1][1], m[2][1]) - centre.y * w) / gl_Position.w;
  vec4 image = vec4(dot(jx, u), dot(jx, v), dot(jy, u), dot(jy, v));
  float sum = dot(image, image);
  float det = image.x * image.w - image.y * image.z;
  float largest = sqrt(0.5 * (sum + sqrt(max(sum * sum - 4.0 * det * det, 0.0))));
  float depthRatio = abs(cone * dot(w, toLight) / gl_Position.w);
  vtkShadowSpriteCentre = p;
  vtkShadowSpriteRadius = radius;
  vtkShadowSpriteClip = gl_Position;
  vtkShadowDrawPartInView(centre, cone * largest * (1.0 + 2.0 * depthRatio));
}
