// What both traversals of the CPU pipeline (the teaching one in cpu_renderer.cpp, the fast
// one in fast_pipeline.cpp) need per draw item: the vertex and fragment stages' uniforms,
// the clipper's configuration, the shader permutation and the fixed-function state.
#pragma once

#include "scene/scene.h"
#include "softrender/clip.h"
#include "softrender/setup.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

namespace twr {

struct ItemState {
  const DrawItem* item = nullptr;
  VertexUniforms vertexUniforms;
  ShadeUniforms shade;
  ShaderKey shaderKey;
  ClipConfig clip;
  CullMode cull = CullMode::Back;
  FrontFace frontFace = FrontFace::Ccw;
  Viewport viewport;
  bool tangentLighting = false;
  Interpolation interpolation = Interpolation::Perspective;  // how varyings spread (interpolate.h)
};

ItemState makeItemState(const DrawItem& item, const mat4& clipFromWorld, const Scene& scene,
                        const RenderSettings& settings, int width, int height);

// Throws InputError unless the size is allowed (renderSizeProblem); `renderer` starts the
// message ("cpu renderer", "reference renderer").
void validateImageSize(int width, int height, const char* renderer = "cpu renderer");

// Throws InputError naming the node and the first index at or past the vertex count.
void validateIndices(const DrawItem& item);
// The InputError validateIndices throws for index position i.
[[noreturn]] void throwIndexError(const DrawItem& item, std::size_t i);
// validateIndices for the indices past the last whole triangle (a count that is not a multiple
// of three), which no triangle reads; the fast path checks the others as its front end reads
// them (a second pass over a million-triangle mesh cost a serial 2 ms a frame).
void validateTrailingIndices(const DrawItem& item);

}  // namespace twr
