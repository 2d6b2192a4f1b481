// The reference renderer: the pipeline stages with T = double, N x N sub-pixel passes, box
// filter. The draw loop is the teaching path's own (draw_loop.h: clip, fan, setup, raster,
// interpolate, depth test, shade), writing unrounded colours into a sample target instead of
// the RGBA8 framebuffer. With T = float the same loop measures what double itself costs
// (ReferenceOptions::doublePrecision).
#include "softrender/reference_renderer.h"

#include "scene/environment_capture.h"
#include "scene/mip_level_view.h"

#include "scene/camera.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "softrender/clip.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/draw_loop.h"
#include "softrender/raster.h"
#include "softrender/setup.h"
#include "softrender/shadow_pass.h"
#include "softrender/shade.h"
#include "softrender/sky-inl.h"
#include "softrender/vertex.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <cmath>
#include <functional>
#include <string>
#include <thread>

namespace twr {

namespace {

glm::dmat4 localFromNodeTrsDouble(const Node& node) {
  const glm::dmat4 identity(1.0);
  const glm::dvec3 rotateRad = glm::dvec3(node.rotateDeg) * (kPi / 180.0);
  const glm::dmat4 t = glm::translate(identity, glm::dvec3(node.translate));
  const glm::dmat4 rx = glm::rotate(identity, rotateRad.x, glm::dvec3(1, 0, 0));
  const glm::dmat4 ry = glm::rotate(identity, rotateRad.y, glm::dvec3(0, 1, 0));
  const glm::dmat4 rz = glm::rotate(identity, rotateRad.z, glm::dvec3(0, 0, 1));
  const glm::dmat4 s = glm::scale(identity, glm::dvec3(node.scale));
  return t * rz * ry * rx * s;
}

// Same walk and same test for "has a mesh" as flattenScene, so the results line up.
void flattenNodeDouble(const Scene& scene, const Node& node, const glm::dmat4& worldFromParent,
                       std::vector<glm::dmat4>& out) {
  const glm::dmat4 worldFromNode = worldFromParent * localFromNodeTrsDouble(node);
  if (node.meshIndex >= 0 && node.meshIndex < static_cast<int>(scene.meshes.size())) out.push_back(worldFromNode);
  for (const Node& child : node.children) flattenNodeDouble(scene, child, worldFromNode, out);
}

// One sub-pixel sample: offset from the pixel centre, pixels.
struct SampleOffset {
  double x = 0.0, y = 0.0;
};

// The N x N sample offsets, nearest the pixel centre first (ties in row order), so the first
// pass that covers a pixel gives its depth and triangle id.
std::vector<SampleOffset> sampleOffsets(int samplesPerAxis) {
  std::vector<SampleOffset> offsets;
  for (int j = 0; j < samplesPerAxis; ++j) {
    for (int i = 0; i < samplesPerAxis; ++i) {
      offsets.push_back({(i + 0.5) / samplesPerAxis - 0.5, (j + 0.5) / samplesPerAxis - 0.5});
    }
  }
  std::stable_sort(offsets.begin(), offsets.end(), [](const SampleOffset& a, const SampleOffset& b) {
    return a.x * a.x + a.y * a.y < b.x * b.x + b.y * b.y;
  });
  return offsets;
}

// One pass's buffers, GL order (row 0 at the bottom).
struct SampleTarget {
  int width = 0, height = 0;
  std::vector<glm::dvec3> colour;
  std::vector<double> depth;
  std::vector<std::uint32_t> triangleId;

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x); }
};

// The reference's draw loop target: unrounded colours in the pass's sample buffer.
template <typename T>
struct SampleBufferTarget {
  SampleTarget& target;
  T storedDepth(int px, int py) const { return static_cast<T>(target.depth[target.index(px, py)]); }
  // Every bit of the double sample kept (storedDepth rounds no double to 24 bits either).
  DepthFormat depthFormat() const { return DepthFormat::Float32; }
  void write(int px, int py, const Vec4T<T>& colour, T depth, std::uint32_t triangleId) {
    const std::size_t i = target.index(px, py);
    target.colour[i] = glm::dvec3(colour);
    target.depth[i] = depth;
    target.triangleId[i] = triangleId;
  }
};

class ReferenceRenderer final : public Renderer {
 public:
  explicit ReferenceRenderer(const ReferenceOptions& options) : options_(options) {
    if (options.samplesPerAxis < 1 || options.samplesPerAxis > kMaxReferenceSamplesPerAxis) {
      throw InputError("reference renderer: samples per axis " + std::to_string(options.samplesPerAxis) +
                       " must be within 1.." + std::to_string(kMaxReferenceSamplesPerAxis));
    }
  }
  std::string name() const override { return "reference"; }

  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    if (needsEnvironmentCapture(scene)) {  // drawn by this renderer itself, then the frame with it
      const CapturedEnvironment captured = captureEnvironment(scene, settings, *this);
      RenderOutput out = render(captured.scene, settings, width, height);
      attachCapture(out, captured);
      return out;
    }
    return options_.doublePrecision ? renderWith<double>(scene, settings, width, height)
                                    : renderWith<float>(scene, settings, width, height);
  }

 private:
  template <typename T>
  RenderOutput renderWith(const Scene& scene, const RenderSettings& requested, int width, int height) {
    validateImageSize(width, height, "reference renderer");
    const auto start = std::chrono::steady_clock::now();
    std::vector<DrawItem> items = flattenScene(scene);
    RenderSettings settings = requested;
    const MipLevelView mipLevelView = applyMipLevelView(items, settings);  // owns stand-ins while drawn
    const std::vector<glm::dmat4> worldFromModel = referenceWorldFromModel(scene);
    for (const DrawItem& item : items) validateIndices(item);
    const glm::dmat4 clipFromWorldCentre = referenceClipFromWorld(scene.camera, width, height);
    const Viewport viewport{width, height};
    const std::vector<SampleOffset> offsets = sampleOffsets(options_.samplesPerAxis);
    const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const glm::dvec3 background(vec3(scene.output.background));
    const double backgroundAlpha = scene.output.background.a;
    const std::uint32_t clearWord = backgroundWord(scene.output.background);
    // The sky box in the shaded view (sky.h), sampled at each pass's sample position.
    const SkyUniformsT<double> sky = makeSkyUniforms<double>(scene, width, height, requested.view);

    std::vector<glm::dvec3> colourSum(pixelCount, glm::dvec3(0.0));
    std::vector<int> coveredSamples(pixelCount, 0);
    std::vector<double> firstDepth(pixelCount, static_cast<double>(kClearDepth));
    std::vector<std::uint32_t> firstTriangleId(pixelCount, kNoTriangle);
    SampleTarget target;
    target.width = width;
    target.height = height;
    RenderStats stats;
    std::vector<LoopItemT<T>> states(items.size());
    // The lights' shadow maps, drawn once by the teaching traversal (shadow_pass.h): the
    // reference shades in double against the maps the CPU frame reads, so its error measures
    // the shading, not the map's resolution (the ray-traced visibility measures that).
    Framebuffer shadowTarget;
    double shadowMilliseconds = 0.0;
    const ShadowMaps shadows = renderShadowMaps(
        scene, requested,
        [&](const std::vector<ItemState>& passItems, int size) -> const Framebuffer& {
          shadowTarget = makeShadowFramebuffer(size, scene.output.background);
          RenderStats passStats;
          drawTeachingItems(passItems, options_.threads, shadowTarget, passStats);
          return shadowTarget;
        },
        shadowMilliseconds);

    for (std::size_t pass = 0; pass < offsets.size(); ++pass) {
      // Moving the scene by -offset puts the pixel centre on the sample: window x shifts by
      // -offset.x pixels when x_ndc shifts by -2 offset.x / W, i.e. x_clip by -2 offset.x w / W.
      glm::dmat4 ndcShift(1.0);
      ndcShift[3][0] = -2.0 * offsets[pass].x / width;
      ndcShift[3][1] = -2.0 * offsets[pass].y / height;
      const Mat4T<T> clipFromWorld(ndcShift * clipFromWorldCentre);
      for (std::size_t k = 0; k < items.size(); ++k) {
        LoopItemT<T>& s = states[k];
        const VertexUniformsT<T> vertexUniforms =
            makeVertexUniforms(Mat4T<T>(worldFromModel[k]), clipFromWorld, scene, settings);
        s.mesh = items[k].mesh;
        s.firstTriangleId = items[k].firstTriangleId;
        s.vertices.resize(s.mesh->vertices.size());
        for (std::size_t i = 0; i < s.vertices.size(); ++i) {
          s.vertices[i] = runVertexStage(s.mesh->vertices[i], vertexUniforms);
        }
        s.shade = makeShadeUniforms<T>(*items[k].material, scene, settings);
        setShadowUniforms(s.shade, shadows);
        s.shaderKey = shaderKeyFor(s.shade, settings);
        s.clip = makeClipConfig(settings.clip, vertexUniforms.userClipPlaneCount, width, height,
                                 settings.interpolation);
        s.cull = settings.cull;
        s.frontFace = settings.frontFace;
        s.viewport = viewport;
        s.tangentLighting = vertexUniforms.tangentLighting;
        s.interpolation = settings.interpolation;
      }
      target.colour.assign(pixelCount, background);
      target.depth.assign(pixelCount, static_cast<double>(kClearDepth));
      target.triangleId.assign(pixelCount, kNoTriangle);

      // The draw loop the teaching path runs (draw_loop.h), in T; triangles counted in the
      // first pass only.
      SampleBufferTarget<T> sampleTarget{target};
      drawInBands(
          options_.threads, height, pass == 0,
          [&](const RowBand& band, RenderStats& bandStats) { drawBand(states, band, sampleTarget, bandStats); },
          stats);

      // The sky where this pass's sample saw no triangle, at the sample's own position.
      if (sky.cube) {
        for (int y = 0; y < height; ++y) {
          for (int x = 0; x < width; ++x) {
            const std::size_t i = target.index(x, y);
            if (target.triangleId[i] != kNoTriangle) continue;
            target.colour[i] = lanes::skyColour<double>(sky, x + offsets[pass].x, y + offsets[pass].y);
          }
        }
      }
      for (std::size_t i = 0; i < pixelCount; ++i) {
        colourSum[i] += target.colour[i];
        if (target.triangleId[i] == kNoTriangle) continue;
        if (coveredSamples[i]++ == 0) {
          firstDepth[i] = target.depth[i];
          firstTriangleId[i] = target.triangleId[i];
        }
      }
    }

    RenderOutput out;
    out.width = width;
    out.height = height;
    out.rgba.assign(pixelCount * 4, 0);
    out.depth.assign(pixelCount, kClearDepth);
    out.triangleId.assign(pixelCount, kNoTriangle);
    out.lineMask.assign(pixelCount, 0);
    const double sampleCount = static_cast<double>(offsets.size());
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t from = target.index(x, y);
        const std::size_t to = static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x);  // top row first
        const int covered = coveredSamples[from];
        if (covered == 0 && !sky.cube) {
          // Only background: the clear colour, stored as a clear stores it (clearByte).
          std::memcpy(&out.rgba[to * 4], &clearWord, sizeof(clearWord));
        } else {
          // The box filter of every sample's RGBA: surfaces and the sky are opaque, the
          // background has its alpha.
          const glm::dvec3 mean = colourSum[from] / sampleCount;
          const double uncoveredAlpha = sky.cube ? 1.0 : backgroundAlpha;
          const double alpha = (covered + (sampleCount - covered) * uncoveredAlpha) / sampleCount;
          out.rgba[to * 4 + 0] = unitToByte(static_cast<float>(mean.r));
          out.rgba[to * 4 + 1] = unitToByte(static_cast<float>(mean.g));
          out.rgba[to * 4 + 2] = unitToByte(static_cast<float>(mean.b));
          out.rgba[to * 4 + 3] = unitToByte(static_cast<float>(alpha));
        }
        out.depth[to] = static_cast<float>(firstDepth[from]);
        out.triangleId[to] = firstTriangleId[from];
      }
    }
    stats.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.shadowMilliseconds = shadowMilliseconds;
    out.stats = stats;
    out.shadowMaps = shadows;
    return out;
  }

  ReferenceOptions options_;
};

}  // namespace

std::vector<glm::dmat4> referenceWorldFromModel(const Scene& scene) {
  std::vector<glm::dmat4> out;
  for (const Node& node : scene.nodes) flattenNodeDouble(scene, node, glm::dmat4(1.0), out);
  return out;
}

glm::dmat4 referenceClipFromWorld(const Camera& camera, int width, int height) {
  // The formulas of scene/camera.cpp in double; validateCamera throws the same errors.
  if (std::string error = validateCamera(camera); !error.empty()) throw InputError("camera: " + error);
  const glm::dvec3 position(camera.position), target(camera.target);
  const glm::dvec3 d = glm::normalize(position - target);
  const glm::dvec3 r = glm::normalize(glm::cross(glm::dvec3(camera.up), d));
  const glm::dvec3 u = glm::cross(d, r);
  glm::dmat4 viewFromWorld(1.0);
  for (int i = 0; i < 3; ++i) {
    viewFromWorld[i][0] = r[i];
    viewFromWorld[i][1] = u[i];
    viewFromWorld[i][2] = d[i];
  }
  viewFromWorld[3] = glm::dvec4(-glm::dot(r, position), -glm::dot(u, position), -glm::dot(d, position), 1.0);
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  const double f = 1.0 / std::tan(0.5 * static_cast<double>(camera.fovDeg) * (kPi / 180.0));
  const double n = camera.near, fa = camera.far;
  glm::dmat4 clipFromView(0.0);
  clipFromView[0][0] = f / aspect;
  clipFromView[1][1] = f;
  clipFromView[2][2] = (fa + n) / (n - fa);
  clipFromView[2][3] = -1.0;
  clipFromView[3][2] = 2.0 * fa * n / (n - fa);
  return clipFromView * viewFromWorld;
}

std::unique_ptr<Renderer> makeReferenceRenderer(const ReferenceOptions& options) {
  return std::make_unique<ReferenceRenderer>(options);
}

}  // namespace twr
