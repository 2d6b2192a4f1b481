// Mouse moves of the course's P/T camera: orbit P around T, pan both, zoom along P - T.
// Screen deltas are in screen points (ImGui units), +x right, +y down, as the mouse reports
// them, so the feel is the same on a HiDPI display.
#pragma once

#include "scene/camera.h"

namespace twr::gui {

// Orbit speed, radians of yaw or pitch per point of mouse travel.
inline constexpr float kOrbitRadiansPerPoint = 0.008f;
// Pitch limit, radians, inclusive: D = normalize(P - T) must never be parallel to the
// world up (0, 1, 0), or R = normalize(cross(Up, D)) has no direction. 1.55 rad = 88.8 deg.
inline constexpr float kMaxPitchRadians = 1.55f;
// Each wheel step scales |P - T| by this (< 1 moves closer).
inline constexpr float kZoomFactorPerWheelStep = 0.9f;
// Closest P may come to T, world units (inclusive).
inline constexpr float kMinOrbitDistance = 1e-3f;
// Farthest P may go from T, world units (inclusive), so zooming out cannot overflow.
inline constexpr float kMaxOrbitDistance = 1e5f;

// Turns P around T: dragging right turns the scene right (yaw), dragging down tilts it.
void orbitCamera(Camera& camera, float dxPoints, float dyPoints);
// Moves P and T together in the view plane so the point under the mouse follows it at the
// distance of T. viewHeightPoints is the height of the image on screen.
void panCamera(Camera& camera, float dxPoints, float dyPoints, float viewHeightPoints);
// Moves P along T - P; positive steps come closer.
void zoomCamera(Camera& camera, float wheelSteps);
// Moves a point (a light) parallel to the image plane so that it follows the mouse at its
// own depth. Returns false (and leaves it) when the point is not in front of the camera.
bool dragPointInViewPlane(const Camera& camera, vec3& pointWorld, float dxPoints, float dyPoints,
                          float viewHeightPoints);

}  // namespace twr::gui
