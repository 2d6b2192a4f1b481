// What llvmpipe's frame in glrender/ spends besides shading the scene, at 720p, to explain why
// our GL frame is slower than a plain one (docs/performance.md):
//   - clearing the offscreen framebuffer's four attachments (colour, triangle ids, line mask,
//     depth) against clearing colour and depth only;
//   - a full-screen pass (two triangles, depth test on) writing colour alone against colour
//     and a triangle id, the second output every surface draw of glrender/ writes;
//   - reading back each attachment with glReadPixels, and RenderTargets::readBack (all four,
//     rows flipped, the line mask reduced to one byte) as a frame does.
// Each case ends with glFinish, so the time is llvmpipe's work, not its queueing.
#include "glrender/context_osmesa.h"
#include "glrender/gl_context.h"
#include "glrender/gl_objects.h"
#include "glrender/gl_targets.h"
#include "scene/renderer.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace twr;

constexpr int kWidth = 1280;  // pixels
constexpr int kHeight = 720;  // pixels

// A triangle that covers the whole viewport (corners at clip -1 and 3), depth 0.5.
constexpr const char* kVertexShader = R"(#version 330 core
const vec2 corners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() { gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0); }
)";
constexpr const char* kColourShader = R"(#version 330 core
layout(location = 0) out vec4 colour;
void main() { colour = vec4(gl_FragCoord.xy * 0.001, 0.5, 1.0); }
)";
constexpr const char* kColourAndIdShader = R"(#version 330 core
layout(location = 0) out vec4 colour;
layout(location = 1) out uint triangleId;
void main() {
  colour = vec4(gl_FragCoord.xy * 0.001, 0.5, 1.0);
  triangleId = uint(gl_PrimitiveID);
}
)";

GLuint compile(GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) throw std::runtime_error("bench_gl_targets: a shader did not compile");
  return shader;
}

GLuint link(const char* fragmentSource) {
  const GLuint program = glCreateProgram();
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentSource);
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) throw std::runtime_error("bench_gl_targets: a program did not link");
  return program;
}

// One OSMesa core context with glrender's render targets at 720p, made once per process
// (llvmpipe reads LP_NUM_THREADS when the first context is created: set it to compare).
struct Gl {
  std::unique_ptr<OsMesaContext> context;
  RenderTargets targets;
  GLuint colourProgram = 0, colourAndIdProgram = 0, vertexArray = 0;

  Gl() {
    OsMesaContextDesc desc;
    desc.fastSampling = true;  // what `twinraster bench` times
    context = std::make_unique<OsMesaContext>(desc);
    context->makeCurrent();
    OsMesaContext* raw = context.get();
    loadCoreGl([raw](const char* name) { return raw->procAddress(name); }, "OSMesa context");
    targets.prepare(kWidth, kHeight);
    targets.bind();
    colourProgram = link(kColourShader);
    colourAndIdProgram = link(kColourAndIdShader);
    glGenVertexArrays(1, &vertexArray);
    glBindVertexArray(vertexArray);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  }
};

Gl& gl() {
  static Gl instance;
  return instance;
}

// What the renderer clears colour to: an opaque grey, as a scene file's [r, g, b] gives.
const vec4 kBackground{0.1f, 0.1f, 0.1f, 1.0f};

void clearColourAndDepth() {
  const std::array<GLenum, 1> colourOnly = {GL_COLOR_ATTACHMENT0};
  glDrawBuffers(static_cast<GLsizei>(colourOnly.size()), colourOnly.data());
  const std::array<GLfloat, 4> background = {kBackground.r, kBackground.g, kBackground.b, kBackground.a};
  glClearBufferfv(GL_COLOR, 0, background.data());
  const GLfloat farDepth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
}

void BM_ClearFourAttachments(benchmark::State& state) {
  Gl& g = gl();
  for (auto _ : state) {
    g.targets.clear(kBackground);
    glFinish();
  }
}

void BM_ClearColourAndDepth(benchmark::State& state) {
  gl();
  for (auto _ : state) {
    clearColourAndDepth();
    glFinish();
  }
}

void BM_FullScreenColour(benchmark::State& state) {
  Gl& g = gl();
  glUseProgram(g.colourProgram);
  for (auto _ : state) {
    clearColourAndDepth();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
  }
}

void BM_FullScreenColourAndId(benchmark::State& state) {
  Gl& g = gl();
  glUseProgram(g.colourAndIdProgram);
  for (auto _ : state) {
    g.targets.clear(kBackground);
    g.targets.drawSurfaces();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
  }
}

// Args: 0 colour RGBA8, 1 triangle id R32UI, 2 line mask RGBA8, 3 depth as float.
void BM_ReadOneAttachment(benchmark::State& state) {
  Gl& g = gl();
  g.targets.clear(kBackground);
  glFinish();
  const int which = static_cast<int>(state.range(0));
  const std::array<GLenum, 4> attachments = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_NONE};
  const std::array<GLenum, 4> formats = {GL_RGBA, GL_RED_INTEGER, GL_RGBA, GL_DEPTH_COMPONENT};
  const std::array<GLenum, 4> types = {GL_UNSIGNED_BYTE, GL_UNSIGNED_INT, GL_UNSIGNED_BYTE, GL_FLOAT};
  const std::size_t index = static_cast<std::size_t>(which);
  std::vector<std::uint32_t> pixels(static_cast<std::size_t>(kWidth) * static_cast<std::size_t>(kHeight));  // 4 bytes each
  g.targets.bind();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (auto _ : state) {
    if (attachments[index] != GL_NONE) glReadBuffer(attachments[index]);
    glReadPixels(0, 0, kWidth, kHeight, formats[index], types[index], pixels.data());
    benchmark::DoNotOptimize(pixels.data());
  }
}

void BM_ReadBackAsAFrameDoes(benchmark::State& state) {
  Gl& g = gl();
  g.targets.clear(kBackground);
  glFinish();
  for (auto _ : state) {
    RenderOutput out;
    g.targets.readBack(out);
    benchmark::DoNotOptimize(out.rgba.data());
  }
}

BENCHMARK(BM_ClearFourAttachments)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ClearColourAndDepth)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FullScreenColour)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FullScreenColourAndId)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReadOneAttachment)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ReadBackAsAFrameDoes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
