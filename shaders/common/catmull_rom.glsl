// Catmull–Rom (bicubic) resampling, shared by the lens pass and the field-curvature sum. Bilinear
// would blur every sample that falls between texels; Catmull–Rom reproduces the texel values and
// keeps edges. For a position `p` in texels (texel centres at i + 0.5): the first of the 4 × 4
// texels to read, and the weights of the four columns (.x) and rows (.y).
void catmullRomTaps(vec2 p, out ivec2 first, out vec2 w[4]) {
  vec2 q = p - 0.5;
  vec2 base = floor(q);
  vec2 t = q - base;
  vec2 t2 = t * t, t3 = t2 * t;
  w[0] = -0.5 * t3 + t2 - 0.5 * t;
  w[1] = 1.5 * t3 - 2.5 * t2 + 1.0;
  w[2] = -1.5 * t3 + 2.0 * t2 + 0.5 * t;
  w[3] = 0.5 * t3 - 0.5 * t2;
  first = ivec2(base) - 1;
}
