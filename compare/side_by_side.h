// Viewable images of a render and the labelled side-by-side composition.
#pragma once

#include "scene/image.h"
#include "scene/renderer.h"

namespace twr {

// How pixels where nothing was drawn (drawnAt: no triangle id, no line) are shown in viewable
// images. Alpha does not say it: the background has the scene's alpha, 1 by default.
enum class BackgroundMode {
  RendererColour,  // keep the RGB the renderer wrote (the scene's background colour): RGB unchanged
  // The dark checker of the diff images where nothing was drawn; a drawn pixel composited
  // over it by its alpha, rgb * a + checker * (1 - a) (255 from the renderers, the coverage
  // fraction from a supersampled reference).
  Checker,
};

// The render exactly as produced, alpha included (the scene's background alpha where nothing
// was drawn), for cpu.png / gl.png.
Image rawImage(const RenderOutput& output);
// The render with alpha 255 everywhere, background shown as `mode` says.
Image viewImage(const RenderOutput& output, BackgroundMode mode);

struct SideBySideOptions {
  int gapPx = 2;        // panel-coloured columns between the two images, >= 0
  bool labels = true;   // a strip above with "CPU" over the left image and "GL" over the right
  BackgroundMode background = BackgroundMode::RendererColour;
};

// Label strip height in pixels for images `width` wide (0 without labels).
int sideBySideLabelHeight(int width, const SideBySideOptions& options);

// Canvas (2 * width + gapPx) x (labelHeight + height): CPU at (0, labelHeight), GL at
// (width + gapPx, labelHeight), each viewImage(output, options.background).
// Throws InputError when the outputs differ in size or are malformed.
Image makeSideBySide(const RenderOutput& cpu, const RenderOutput& gl, const SideBySideOptions& options = {});

}  // namespace twr
