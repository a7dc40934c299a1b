#version 450 core
// Clips each triangle, in double, to |x|, |y| ≤ 2·w (twice the image, so that no clip edge falls
// inside it) before GL sees it in float. What reaches GL is then within a few window widths of
// the image, where float places it to 1e-7 of the image; GL's own clipping and rasterisation do
// the rest (near and far, the exact image edges). Attributes are interpolated linearly in clip
// space, as GL's clipper does, which is correct under perspective.

layout(triangles) in;
// A triangle clipped by four planes has at most 7 corners: a fan of 5 triangles.
layout(triangle_strip, max_vertices = 15) out;

in ToClip {
  dvec4 clipPosition;
  vec3 worldNormal;
  vec2 uv;
  vec4 vertexColor;
  vec3 shadingPosition;
#ifdef MATERIAL_MAPS
  vec4 worldTangent;
  vec2 uv1;
#endif
} vertex[];

// Added views draw twice (depth, then colour where depth is EQUAL): both must place each vertex alike.
invariant gl_Position;

out vec3 worldNormal;
out vec2 uv;
out vec4 vertexColor;
out vec3 shadingPosition;
#ifdef MATERIAL_MAPS
out vec4 worldTangent;
out vec2 uv1;
#endif

const int kMaxCorners = 7;
const double kGuard = 2.0;

struct Corner {
  dvec4 clip;
  vec3 worldNormal;
  vec2 uv;
  vec4 vertexColor;
  vec3 shadingPosition;
#ifdef MATERIAL_MAPS
  vec4 worldTangent;
  vec2 uv1;
#endif
};

Corner mixCorners(Corner a, Corner b, double t) {
  Corner c;
  c.clip = mix(a.clip, b.clip, t);
  c.worldNormal = mix(a.worldNormal, b.worldNormal, float(t));
  c.uv = mix(a.uv, b.uv, float(t));
  c.vertexColor = mix(a.vertexColor, b.vertexColor, float(t));
  c.shadingPosition = mix(a.shadingPosition, b.shadingPosition, float(t));
#ifdef MATERIAL_MAPS
  c.worldTangent = mix(a.worldTangent, b.worldTangent, float(t));
  c.uv1 = mix(a.uv1, b.uv1, float(t));
#endif
  return c;
}

// Signed distance inside plane `p` (0: x ≤ g·w, 1: −x ≤ g·w, 2: y ≤ g·w, 3: −y ≤ g·w); ≥ 0 inside.
double inside(dvec4 c, int p) {
  const double coordinate = p < 2 ? c.x : c.y;
  return kGuard * c.w - ((p & 1) == 0 ? coordinate : -coordinate);
}

void main() {
  Corner polygon[kMaxCorners];
  int count = 3;
  for (int i = 0; i < 3; ++i)
#ifdef MATERIAL_MAPS
    polygon[i] = Corner(vertex[i].clipPosition, vertex[i].worldNormal, vertex[i].uv, vertex[i].vertexColor,
                        vertex[i].shadingPosition, vertex[i].worldTangent, vertex[i].uv1);
#else
    polygon[i] = Corner(vertex[i].clipPosition, vertex[i].worldNormal, vertex[i].uv, vertex[i].vertexColor,
                        vertex[i].shadingPosition);
#endif

  // Sutherland–Hodgman, one plane at a time.
  for (int p = 0; p < 4 && count > 0; ++p) {
    Corner clipped[kMaxCorners];
    int kept = 0;
    for (int i = 0; i < count; ++i) {
      const Corner a = polygon[i], b = polygon[(i + 1) % count];
      const double da = inside(a.clip, p), db = inside(b.clip, p);
      if (da >= 0.0 && kept < kMaxCorners) clipped[kept++] = a;
      if ((da >= 0.0) != (db >= 0.0) && kept < kMaxCorners) clipped[kept++] = mixCorners(a, b, da / (da - db));
    }
    polygon = clipped;
    count = kept;
  }

  // A fan from the first corner keeps the triangle's winding (face culling still applies).
  for (int i = 1; i + 1 < count; ++i) {
    for (int k = 0; k < 3; ++k) {
      const Corner c = polygon[k == 0 ? 0 : i + k - 1];
      gl_Position = vec4(c.clip);
      worldNormal = c.worldNormal;
      uv = c.uv;
      vertexColor = c.vertexColor;
      shadingPosition = c.shadingPosition;
#ifdef MATERIAL_MAPS
      worldTangent = c.worldTangent;
      uv1 = c.uv1;
#endif
      EmitVertex();
    }
    EndPrimitive();
  }
}
