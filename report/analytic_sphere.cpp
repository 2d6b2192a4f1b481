#include "report/analytic_sphere.h"

#include "scene/errors.h"
#include "softrender/framebuffer.h"
#include "softrender/reference_renderer.h"
#include "softrender/shade.h"

#include <cmath>
#include <string>
#include <vector>

namespace twr::report {

namespace {
constexpr double kTwoPi = 2.0 * kPi;
// makeSphere's handedness: B = -cross(N, T) everywhere (see scene/primitives.cpp).
constexpr double kSphereHandedness = -1.0;

struct SphereGeometry {
  glm::dvec3 centreWorld{0.0};
  double scale = 1.0;         // uniform node scale
  double radiusModel = 1.0;   // MeshDesc::radius
  const Material* material = nullptr;
};

SphereGeometry sphereOf(const Scene& scene) {
  const std::string what = "analytic sphere reference: ";
  if (scene.nodes.size() != 1 || !scene.nodes[0].children.empty()) throw InputError(what + "expected exactly one node");
  const Node& node = scene.nodes[0];
  if (node.meshIndex < 0 || node.meshIndex >= static_cast<int>(scene.meshDescs.size()) ||
      scene.meshDescs[static_cast<std::size_t>(node.meshIndex)].type != MeshType::Sphere) {
    throw InputError(what + "node '" + node.name + "' must be a sphere mesh");
  }
  if (node.rotateDeg != vec3(0.0f) || node.scale.x != node.scale.y || node.scale.y != node.scale.z ||
      !(node.scale.x > 0.0f)) {
    throw InputError(what + "node '" + node.name + "' must have no rotation and a positive uniform scale");
  }
  SphereGeometry g;
  g.centreWorld = glm::dvec3(node.translate);
  g.scale = node.scale.x;
  g.radiusModel = scene.meshDescs[static_cast<std::size_t>(node.meshIndex)].radius;
  g.material = (node.materialIndex >= 0 && node.materialIndex < static_cast<int>(scene.materials.size()))
                   ? &scene.materials[static_cast<std::size_t>(node.materialIndex)]
                   : &defaultMaterial();
  return g;
}

struct Hit {
  bool covered = false;
  double depth = 1.0;  // window depth
  FragmentT<double> fragment;
};

// The nearest visible intersection of the ray through window point (sx, sy) with the sphere.
Hit traceSample(const SphereGeometry& g, const glm::dmat4& clipFromWorld, const glm::dmat4& worldFromClip,
                const glm::dvec3& eyeWorld, double sx, double sy, int width, int height, int lightCount,
                const Scene& scene) {
  Hit hit;
  const glm::dvec4 nearClip(2.0 * sx / width - 1.0, 2.0 * sy / height - 1.0, -1.0, 1.0);
  const glm::dvec4 nearWorldH = worldFromClip * nearClip;
  const glm::dvec3 direction = glm::normalize(glm::dvec3(nearWorldH) / nearWorldH.w - eyeWorld);
  const double radiusWorld = g.radiusModel * g.scale;
  const glm::dvec3 toEye = eyeWorld - g.centreWorld;
  const double b = glm::dot(toEye, direction);
  const double c = glm::dot(toEye, toEye) - radiusWorld * radiusWorld;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return hit;
  const double t = -b - std::sqrt(discriminant);  // the front intersection (the back one faces away)
  if (!(t > 0.0)) return hit;
  const glm::dvec3 posWorld = eyeWorld + t * direction;
  const glm::dvec4 posClip = clipFromWorld * glm::dvec4(posWorld, 1.0);
  if (posClip.z < -posClip.w || posClip.z > posClip.w) return hit;  // near / far planes
  hit.covered = true;
  hit.depth = 0.5 * (posClip.z / posClip.w) + 0.5;

  // Model-space parametrisation of makeSphere: n = (sin psi cos phi, cos psi, sin psi sin phi).
  const glm::dvec3 n = (posWorld - g.centreWorld) / radiusWorld;
  const double psi = std::acos(std::fmin(std::fmax(n.y, -1.0), 1.0));
  double phi = std::atan2(n.z, n.x);
  if (phi < 0.0) phi += kTwoPi;
  const glm::dvec3 tangent(-std::sin(phi), 0.0, std::cos(phi));
  FragmentT<double>& f = hit.fragment;
  f.posWorld = posWorld;
  f.nWorld = n;
  f.tWorld = tangent;
  f.bWorld = kSphereHandedness * glm::cross(n, tangent);
  f.uv = glm::dvec2(phi / kTwoPi, 1.0 - psi / kPi);
  f.depth = hit.depth;
  // Tangent lighting space: the vertex stage's formula evaluated at the pixel itself.
  const glm::dvec3 tUnit = glm::normalize(f.tWorld), bUnit = glm::normalize(f.bWorld), nUnit = glm::normalize(n);
  for (int i = 0; i < lightCount; ++i) {
    const glm::dvec3 lw = glm::dvec3(scene.lights[static_cast<std::size_t>(i)].posWorld) - posWorld;
    f.lightDirTangent[static_cast<std::size_t>(i)] = glm::dvec3(glm::dot(tUnit, lw), glm::dot(bUnit, lw), glm::dot(nUnit, lw));
  }
  const glm::dvec3 ew = eyeWorld - posWorld;
  f.eyeDirTangent = glm::dvec3(glm::dot(tUnit, ew), glm::dot(bUnit, ew), glm::dot(nUnit, ew));
  return hit;
}

}  // namespace

RenderOutput renderAnalyticSphere(const Scene& scene, const RenderSettings& settings, int width, int height,
                                  int samplesPerAxis) {
  if (samplesPerAxis < 1 || samplesPerAxis > kMaxReferenceSamplesPerAxis) {
    throw InputError("analytic sphere reference: samples per axis must be within 1.." +
                     std::to_string(kMaxReferenceSamplesPerAxis));
  }
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError("analytic sphere reference: bad image size");
  }
  const SphereGeometry g = sphereOf(scene);
  const glm::dmat4 clipFromWorld = referenceClipFromWorld(scene.camera, width, height);
  const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
  const glm::dvec3 eyeWorld(scene.camera.position);
  const ShadeUniformsT<double> shade = makeShadeUniforms<double>(*g.material, scene, settings);
  const int lightCount = shade.lightCount;
  const glm::dvec3 background(vec3(scene.output.background));  // RGB: alpha here is coverage
  const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const double sampleCount = static_cast<double>(samplesPerAxis) * samplesPerAxis;

  RenderOutput out;
  out.width = width;
  out.height = height;
  out.rgba.assign(pixelCount * 4, 0);
  out.depth.assign(pixelCount, kClearDepth);
  // No triangles: triangleId stays empty ("not available"), so compare() tells a different
  // surface from a shading difference by depth instead.
  out.lineMask.assign(pixelCount, 0);
  withShaderFeatures(shaderKeyFor(shade, settings), [&]<typename Features>() {
    for (int py = 0; py < height; ++py) {
      for (int px = 0; px < width; ++px) {
        glm::dvec3 sum(0.0);
        int covered = 0;
        double nearestDistance = 0.0;
        double depth = kClearDepth;
        for (int j = 0; j < samplesPerAxis; ++j) {
          for (int i = 0; i < samplesPerAxis; ++i) {
            const double ox = (i + 0.5) / samplesPerAxis - 0.5, oy = (j + 0.5) / samplesPerAxis - 0.5;
            const Hit hit = traceSample(g, clipFromWorld, worldFromClip, eyeWorld, px + 0.5 + ox, py + 0.5 + oy,
                                        width, height, lightCount, scene);
            if (!hit.covered) {
              sum += background;
              continue;
            }
            sum += glm::dvec3(shadeFragment<Features>(hit.fragment, shade, nullptr));
            const double distance = ox * ox + oy * oy;
            if (covered++ == 0 || distance < nearestDistance) {
              nearestDistance = distance;
              depth = hit.depth;
            }
          }
        }
        const std::size_t to = static_cast<std::size_t>(height - 1 - py) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(px);  // top row first
        const glm::dvec3 mean = sum / sampleCount;
        out.rgba[to * 4 + 0] = unitToByte(static_cast<float>(mean.r));
        out.rgba[to * 4 + 1] = unitToByte(static_cast<float>(mean.g));
        out.rgba[to * 4 + 2] = unitToByte(static_cast<float>(mean.b));
        out.rgba[to * 4 + 3] = unitToByte(static_cast<float>(covered / sampleCount));
        out.depth[to] = static_cast<float>(depth);
      }
    }
  });
  return out;
}

}  // namespace twr::report
