// The tessellation knob's reference: the exact sphere, ray-traced in double with N x N
// samples per pixel and shaded by the pipeline's own fragment stage (shadeFragment<double>)
// from the analytic position, normal, tangent, bitangent and uv at the hit point, so the only
// thing a tessellated sphere is measured on is its tessellation.
//
// The scene must hold exactly one node, a sphere mesh (MeshType::Sphere) translated and
// uniformly scaled (no rotation), seen from outside. The RenderOutput follows the reference
// renderer's rules (softrender/reference_renderer.h): rgb the box filter over samples,
// alpha the coverage fraction, depth and id of the covered sample nearest the pixel centre.
#pragma once

#include "scene/renderer.h"

namespace twr::report {

// Throws InputError when the scene is not such a sphere or samplesPerAxis is outside [1, 16].
RenderOutput renderAnalyticSphere(const Scene& scene, const RenderSettings& settings, int width, int height,
                                  int samplesPerAxis);

}  // namespace twr::report
