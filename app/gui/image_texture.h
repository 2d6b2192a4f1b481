// An RGBA8 image in a GL texture for ImGui::Image. Rows are uploaded top row first, so
// ImGui's uv (0, 0) is the image's top-left, as it is for ImGui's own font atlas.
// The window's context must be current whenever one is uploaded or destroyed.
#pragma once

#include "glrender/gl_objects.h"
#include "scene/image.h"

#include <imgui.h>

#include <cstdint>

namespace twr::gui {

class ImageTexture {
 public:
  // (Re)creates the texture at the image's size and uploads it. Magnified pixels stay
  // sharp squares (GL_NEAREST): this is a tool for looking at single pixels.
  void upload(const Image& image);
  void reset();

  bool empty() const { return texture_.id() == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_.id())); }

 private:
  GlTexture texture_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace twr::gui
