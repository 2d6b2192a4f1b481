// The offscreen framebuffer every GL render draws into, and its read-back into
// RenderOutput (GL rows are bottom row first; RenderOutput is top row first).
//   colour attachment 0: RGBA8, cleared to the background (RGB and the scene's alpha);
//                        surfaces and lines write alpha 1
//   colour attachment 1: R32UI triangle id, cleared to kNoTriangle
//   colour attachment 2: RGBA8 TBN-line mask, cleared to 0; lines write their colour with
//                        alpha 1 here too, so alpha != 0 marks a line pixel
//   depth: DEPTH_COMPONENT24, cleared to 1, read back as float window depth
// A lean set (GlFrame::Lean) has only the colour and depth attachments; its read-back is the
// colour alone, one glReadPixels.
#pragma once

#include "glrender/gl_objects.h"
#include "glrender/gl_renderer.h"
#include "scene/conventions.h"
#include "scene/renderer.h"

#include <vector>

namespace twr {

class RenderTargets {
 public:
  explicit RenderTargets(GlFrame set = GlFrame::Full) : set_(set) {}

  // (Re)creates the attachments when the size changes; throws InputError above the
  // context's limits (GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS).
  void prepare(int width, int height);
  // Binds the framebuffer and sets the viewport to the whole target.
  void bind() const;
  // Clears colour to `background` (OutputDesc::background, alpha included), ids to
  // kNoTriangle, the line mask to 0, depth to 1.
  void clear(const vec4& background) const;

  // Which attachments fragment outputs go to (location 0, 1 in the shaders).
  // Full: location 0 -> colour, location 1 -> triangle id. Lean: location 0 -> colour (the
  // lean frame's programs have no id output, see drawScene()).
  void drawSurfaces() const;
  // Binds the line framebuffer: the same colour, mask and depth storage without the
  // integer triangle-id attachment (Mesa refuses fixed-function drawing, immediate mode,
  // into a framebuffer with any integer attachment). location 0 -> colour, location 1 ->
  // line mask; fixed-function fragments replicate their one colour to both, so one pass
  // fills colour and mask alike. Lean: the one framebuffer, colour only (no mask).
  void bindForLines() const;

  // Reads every attachment into `out` (sizes set here), flipping rows to top first. Lean:
  // the colour only; out.depth, triangleId and lineMask are emptied.
  void readBack(RenderOutput& out) const;
  // Reads pixel (x, yGl) (GL window coordinates, row 0 at the bottom) of every attachment
  // into `out` as a 1 x 1 output. Full sets only.
  void readPixel(int x, int yGl, RenderOutput& out) const;

  // For the deferred pipeline's G-buffer (gl_gbuffer.h), which draws into this frame's
  // triangle-id storage (0 in a lean set) and copies its depth into this framebuffer.
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint framebufferId() const { return framebuffer_.id(); }
  GLuint triangleIdStorage() const { return triangleId_.id(); }

 private:
  GlFrame set_;
  int width_ = 0;
  int height_ = 0;
  GlFramebuffer framebuffer_;
  GlFramebuffer lineFramebuffer_;
  GlRenderbuffer colour_;
  GlRenderbuffer triangleId_;
  GlRenderbuffer lineMask_;
  GlRenderbuffer depth_;
  // Kept across frames so a read-back allocates nothing of its own: one row for flipping in
  // place, and the line attachment's RGBA (only its alpha goes out).
  mutable std::vector<std::uint8_t> rowScratch_;
  mutable std::vector<std::uint8_t> lineRgba_;
};

}  // namespace twr
