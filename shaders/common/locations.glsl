// Where the scene's programs take their inputs, for both languages: the shaders include this file
// as GLSL, and the C++ that sets the inputs (render/GpuScene.cpp, ScenePass, SceneUniforms,
// GpuEnvironment, VignettePass) includes it as C++, so a location is written once. #define lines only.
#ifndef LENSLAB_LOCATIONS_GLSL
#define LENSLAB_LOCATIONS_GLSL

// Vertex attributes of the scene's meshes (GpuScene's vertex arrays; scene.vert, narrow_field.vert).
#define ATTRIBUTE_POSITION 0
#define ATTRIBUTE_NORMAL 1
#define ATTRIBUTE_UV 2
#define ATTRIBUTE_COLOR 3
#define ATTRIBUTE_TANGENT 4  // MATERIAL_MAPS
#define ATTRIBUTE_UV1 5      // MATERIAL_MAPS: TEXCOORD_1

// Uniform locations of the scene programs, by who uses them:
//   0–1, 12, 20   the vertex stage (scene.vert, narrow_field.vert)
//   2–16          base colour, alpha, the surround, emission (scene.frag)
//   21–63         metallic-roughness, occlusion and punctual lights
//   80–99         normal maps and KHR_texture_transform (MATERIAL_MAPS)
//   100–119       the environment (environment_textures.glsl)
#define LOCATION_CLIP_FROM_MODEL 0
#define LOCATION_WORLD_NORMAL_FROM_MODEL 1
#define LOCATION_BASE_COLOR_FACTOR 2
#define LOCATION_HAS_BASE_COLOR_TEXTURE 3
#define LOCATION_UNLIT 4
#define LOCATION_ALPHA_MASK 5
#define LOCATION_ALPHA_CUTOFF 6
#define LOCATION_DOUBLE_SIDED 7
#define LOCATION_AMBIENT 9
#define LOCATION_LOD_BIAS 11
#define LOCATION_CLIP_FROM_MODEL_DOUBLE 12  // narrow_field.vert
#define LOCATION_BACKGROUND 13              // ADD_TO_SUM
#define LOCATION_ADD_WEIGHT 14              // ADD_TO_SUM
#define LOCATION_EMISSIVE 15
#define LOCATION_HAS_EMISSIVE_TEXTURE 16
#define LOCATION_SHADING_FROM_MODEL 20
#define LOCATION_TOWARD_VIEWER 21
#define LOCATION_PARALLEL_VIEW 22
#define LOCATION_METALLIC_FACTOR 23
#define LOCATION_ROUGHNESS_FACTOR 24
#define LOCATION_HAS_METALLIC_ROUGHNESS_TEXTURE 25
#define LOCATION_HAS_OCCLUSION_TEXTURE 26
#define LOCATION_OCCLUSION_STRENGTH 27
#define LOCATION_LIGHT_COUNT 28
// Arrays of MAX_SHADING_LIGHTS (scene/ShadingLights.h's kMaxShadingLights), 8 locations each.
#define MAX_SHADING_LIGHTS 8
#define LOCATION_LIGHT_POSITION_RANGE 32
#define LOCATION_LIGHT_DIRECTION_TYPE 40
#define LOCATION_LIGHT_INTENSITY 48
#define LOCATION_LIGHT_SPOT 56
#define LOCATION_WORLD_TANGENT_FROM_MODEL 80
#define LOCATION_HANDEDNESS_FROM_MODEL 81
#define LOCATION_HAS_NORMAL_TEXTURE 82
#define LOCATION_NORMAL_SCALE 83
// Each texture slot: its TEXCOORD set, and its uv transform one location on.
#define LOCATION_NORMAL_TEX_COORD 84
#define LOCATION_BASE_COLOR_TEX_COORD 86
#define LOCATION_EMISSIVE_TEX_COORD 88
#define LOCATION_METALLIC_ROUGHNESS_TEX_COORD 90
#define LOCATION_OCCLUSION_TEX_COORD 92
#define LOCATION_ENVIRONMENT_ROTATION 100
#define LOCATION_ENVIRONMENT_INTENSITY 101
#define LOCATION_ENVIRONMENT_LEVELS 102
#define LOCATION_HAS_ENVIRONMENT 103

// The environment's background pass (scene/environment_background.frag, a program of its own).
#define LOCATION_WORLD_DIRECTION_FROM_NDC 0
#define LOCATION_NDC_PER_PIXEL 1
#define LOCATION_BACKGROUND_WEIGHT 2

// The accumulation of aperture views (accumulate/accumulate.frag, accumulate/gather_lens.frag),
// set by render/Accumulator.cpp: a batch of at most ACCUMULATE_MAX_BATCH views (Accumulator's
// kMaxBatch), one array element per view.
#define ACCUMULATE_MAX_BATCH 8
#define LOCATION_ACCUMULATE_VIEW_COUNT 0
#define LOCATION_ACCUMULATE_WEIGHTS 1                // 1–8
#define LOCATION_ACCUMULATE_SHIFT_PER_RADIUS2 9      // 9–16, FIELD_CURVATURE
#define LOCATION_ACCUMULATE_NORMALISED_AT_ORIGIN 17  // FIELD_CURVATURE or BARREL
#define LOCATION_ACCUMULATE_NORMALISED_PER_PIXEL 18
#define LOCATION_GATHER_JITTER 19                    // 19–26, the lens gather or BARREL
#define LOCATION_GATHER_REACH 27
#define LOCATION_GATHER_PRINCIPAL_POINT 28           // LATERAL_COLOUR
#define LOCATION_GATHER_LATERAL_SCALE 29
#define LOCATION_ACCUMULATE_BARREL_LENS 30           // 30–37, BARREL without the lens gather
#define LOCATION_ACCUMULATE_BARREL_REACH 38
#define LOCATION_GATHER_BARREL_AT_ORIGIN 60          // BARREL with the lens gather
#define LOCATION_GATHER_BARREL_PER_PIXEL 61
#define LOCATION_GATHER_BARREL_LENS 62               // 62–69

// The cell filter (accumulate/cell_filter.frag), one view at a time, set by render/Accumulator.cpp.
#define LOCATION_CELL_WEIGHT 0
#define LOCATION_CELL_SPREAD_AT_INFINITY 1     // mat2 as vec4, column-major
#define LOCATION_CELL_SPREAD_PER_INVERSE_DEPTH 2
#define LOCATION_CELL_INVERSE_DEPTH 3
#define LOCATION_CELL_LENS_POINT 4
#define LOCATION_CELL_RADII2 5
#define LOCATION_CELL_FIRST_EDGE 6
#define LOCATION_CELL_LAST_EDGE 7
#define LOCATION_CELL_WHOLE_RING 8
#define LOCATION_CELL_AREA 9
#define LOCATION_CELL_DISPLACEMENTS 10  // the box of x − y to gather: min x, y, max x, y
#define LOCATION_CELL_MARGIN 12      // the views' margin around the sum, pixels
#define LOCATION_CELL_DEPTH_REFERENCE 13
#define LOCATION_CELL_RECTANGLE_CENTRE 14  // the cell's moment rectangle (ApertureCell::momentRectangle)
#define LOCATION_CELL_RECTANGLE_AXES 15    // its half-axes, as a vec4 (axis0, axis1)
#define LOCATION_CELL_SECTORS 16  // the shape's map (lens/ApertureShape.h's ApertureSectors): first normal, half angle, straight, round
#define LOCATION_CELL_SECTOR_SCALE 17  // scale, squeeze root, blades (0: a circle), twice a sector's area
#define LOCATION_CELL_SQUARE_BOX 11  // a box of the concentric square: min x, y, max x, y (or all 0: a ring's sector)

// The vignetting gain's inputs (common/vignetting.glsl) in the post passes that multiply by it:
// accumulate/resolve.frag and lens/vignetting.frag, set by render/VignettePass.cpp.
#define LOCATION_VIGNETTING_AT_ORIGIN 40
#define LOCATION_VIGNETTING_PER_PIXEL 41
#define LOCATION_VIGNETTING_COEFFICIENTS 42

// Texture units.
#define UNIT_BASE_COLOR 0              // sRGB
#define UNIT_EMISSIVE 1                // sRGB
#define UNIT_METALLIC_ROUGHNESS 2      // linear
#define UNIT_OCCLUSION 3               // linear
#define UNIT_NORMAL 4                  // linear
#define UNIT_ENVIRONMENT_BACKGROUND 5  // the environment's maps: texel fetches only
#define UNIT_ENVIRONMENT_SPECULAR 6
#define UNIT_ENVIRONMENT_DIFFUSE 7
#define UNIT_DFG 9                     // scene/Brdf.h's table, RGB32F, bilinear

#endif
