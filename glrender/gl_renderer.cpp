// First step of the GL path: the entry points exist so the CLI links; rendering follows.
#include "glrender/gl_renderer.h"

#include <cmath>

namespace twr {
namespace {

class GlRenderer final : public Renderer {
 public:
  explicit GlRenderer(const GlOptions& options) : options_(options) {}
  std::string name() const override { return "gl"; }

  RenderOutput render(const Scene& scene, const RenderSettings&, int width, int height) override {
    RenderOutput out;
    out.width = width;
    out.height = height;
    const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    out.rgba.resize(pixelCount * 4);
    for (std::size_t i = 0; i < pixelCount; ++i) {
      for (int c = 0; c < 3; ++c) {
        const float v = glm::clamp(scene.output.background[c], 0.0f, 1.0f);
        out.rgba[i * 4 + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
      }
      out.rgba[i * 4 + 3] = 0;
    }
    out.depth.assign(pixelCount, 1.0f);
    out.triangleId.assign(pixelCount, kNoTriangle);
    out.lineMask.assign(pixelCount, 0);
    return out;
  }

 private:
  GlOptions options_;
};

}  // namespace

std::unique_ptr<Renderer> makeGlRenderer(const GlOptions& options) { return std::make_unique<GlRenderer>(options); }

std::string glVersionString() { return ""; }
std::string glRendererString() { return ""; }

}  // namespace twr
