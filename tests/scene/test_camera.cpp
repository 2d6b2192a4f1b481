// Camera view and projection against matrices worked out by hand from the course's
// formulas (D = normalize(P - T), R = normalize(cross(Up, D)), U = cross(D, R)), and every
// rejection the issue lists.
#include "scene/camera.h"
#include "scene/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace twr {
namespace {

// Single-precision matrix products of small integers and sqrt(2): a few ulps.
constexpr float kMatrixTolerance = 1e-5f;

void expectMatrixNear(const mat4& actual, const mat4& expected) {
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      EXPECT_NEAR(actual[column][row], expected[column][row], kMatrixTolerance)
          << "at row " << row << ", column " << column;
    }
  }
}

// Builds a matrix from rows as written on paper (GLM stores columns).
mat4 fromRows(const vec4& r0, const vec4& r1, const vec4& r2, const vec4& r3) {
  return glm::transpose(mat4(r0, r1, r2, r3));
}

Camera makeCamera(vec3 position, vec3 target) {
  Camera camera;
  camera.position = position;
  camera.target = target;
  return camera;
}

TEST(CameraView, LookingDownMinusZIsATranslation) {
  // P = (0,0,5), T = 0: D = (0,0,1), R = cross((0,1,0),(0,0,1)) = (1,0,0), U = (0,1,0).
  const mat4 expected = fromRows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -5}, {0, 0, 0, 1});
  expectMatrixNear(viewFromWorld(makeCamera({0, 0, 5}, {0, 0, 0})), expected);
}

TEST(CameraView, FromPlusXLooksDownMinusX) {
  // P = (3,0,0): D = (1,0,0), R = cross(Y, X) = (0,0,-1), U = cross(D, R) = (0,1,0).
  // Rows [R; U; D] times translate(-P): (x,y,z) -> (-z, y, x - 3).
  const mat4 expected = fromRows({0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, -3}, {0, 0, 0, 1});
  const mat4 view = viewFromWorld(makeCamera({3, 0, 0}, {0, 0, 0}));
  expectMatrixNear(view, expected);
  // The target lies 3 units down -Z in view space.
  const vec4 targetView = view * vec4(0, 0, 0, 1);
  EXPECT_NEAR(targetView.x, 0.0f, kMatrixTolerance);
  EXPECT_NEAR(targetView.y, 0.0f, kMatrixTolerance);
  EXPECT_NEAR(targetView.z, -3.0f, kMatrixTolerance);
}

TEST(CameraView, ElevatedCameraTiltsUp) {
  // P = (0,4,4): D = (0,1,1)/sqrt2, R = (1,0,0), U = cross(D, R) = (0,1,-1)/sqrt2.
  const float s = 1.0f / std::sqrt(2.0f);
  // Row U dotted with -P: -(4 s - 4 s) = 0; row D: -(4 s + 4 s) = -8 s = -4 sqrt2.
  const mat4 expected = fromRows({1, 0, 0, 0}, {0, s, -s, 0}, {0, s, s, -8 * s}, {0, 0, 0, 1});
  const mat4 view = viewFromWorld(makeCamera({0, 4, 4}, {0, 0, 0}));
  expectMatrixNear(view, expected);
  // The view basis is orthonormal and right-handed (det +1).
  EXPECT_NEAR(glm::determinant(mat3(view)), 1.0f, kMatrixTolerance);
  // World up projects onto +Y in view space: the image is not upside down.
  EXPECT_GT((view * vec4(0, 1, 0, 0)).y, 0.0f);
}

TEST(CameraProjection, MatchesHandComputedMatrix) {
  // fov 90 deg: f = 1 / tan(45 deg) = 1. aspect 2, near 1, far 3:
  // m00 = f / aspect = 0.5, m11 = 1, m22 = (3 + 1) / (1 - 3) = -2,
  // m23 = 2 * 3 * 1 / (1 - 3) = -3, m32 = -1.
  Camera camera;
  camera.fovDeg = 90.0f;
  camera.near = 1.0f;
  camera.far = 3.0f;
  const mat4 expected = fromRows({0.5f, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -2, -3}, {0, 0, -1, 0});
  const mat4 projection = clipFromView(camera, 2.0f);
  expectMatrixNear(projection, expected);

  // z = -near maps to NDC -1 and z = -far to NDC +1 (GL's [-1, 1] depth).
  const vec4 nearClip = projection * vec4(0, 0, -1, 1);
  const vec4 farClip = projection * vec4(0, 0, -3, 1);
  EXPECT_NEAR(nearClip.z / nearClip.w, -1.0f, kMatrixTolerance);
  EXPECT_NEAR(farClip.z / farClip.w, 1.0f, kMatrixTolerance);
}

TEST(CameraProjection, SixtyDegreeFieldOfView) {
  // fov 60: f = 1 / tan(30 deg) = sqrt(3). A view point at (0, y, -1) with y = tan(30 deg)
  // sits exactly on the top edge: NDC y = 1.
  Camera camera;
  camera.fovDeg = 60.0f;
  camera.near = 0.5f;
  camera.far = 10.0f;
  const mat4 projection = clipFromView(camera, 1.5f);
  EXPECT_NEAR(projection[1][1], std::sqrt(3.0f), kMatrixTolerance);
  EXPECT_NEAR(projection[0][0], std::sqrt(3.0f) / 1.5f, kMatrixTolerance);
  const vec4 topEdge = projection * vec4(0, 1.0f / std::sqrt(3.0f), -1, 1);
  EXPECT_NEAR(topEdge.y / topEdge.w, 1.0f, kMatrixTolerance);
  // The right edge at aspect 1.5 is 1.5 times further out.
  const vec4 rightEdge = projection * vec4(1.5f / std::sqrt(3.0f), 0, -1, 1);
  EXPECT_NEAR(rightEdge.x / rightEdge.w, 1.0f, kMatrixTolerance);
}

TEST(CameraValidation, DefaultCameraIsValid) { EXPECT_EQ(validateCamera(Camera{}), ""); }

// Each rejection must name the problem and must throw from both matrix functions.
void expectRejected(const Camera& camera, const std::string& expectedWords) {
  const std::string error = validateCamera(camera);
  EXPECT_NE(error.find(expectedWords), std::string::npos) << "got: '" << error << "'";
  EXPECT_THROW(viewFromWorld(camera), InputError);
  EXPECT_THROW(clipFromView(camera, 1.0f), InputError);
}

TEST(CameraValidation, RejectsNearNotPositive) {
  Camera camera;
  camera.near = 0.0f;
  expectRejected(camera, "near");
  camera.near = -1.0f;
  expectRejected(camera, "near");
  camera.near = std::numeric_limits<float>::quiet_NaN();
  expectRejected(camera, "near");
}

TEST(CameraValidation, RejectsFarNotBeyondNear) {
  Camera camera;
  camera.near = 1.0f;
  camera.far = 1.0f;
  expectRejected(camera, "far");
  camera.far = 0.5f;
  expectRejected(camera, "far");
}

TEST(CameraValidation, RejectsFieldOfViewOutsideOpenInterval) {
  Camera camera;
  for (float fovDeg : {0.0f, -10.0f, 180.0f, 200.0f}) {
    camera.fovDeg = fovDeg;
    expectRejected(camera, "fov");
  }
  // Just inside the bounds is fine.
  camera.fovDeg = 179.0f;
  EXPECT_EQ(validateCamera(camera), "");
  camera.fovDeg = 1.0f;
  EXPECT_EQ(validateCamera(camera), "");
}

TEST(CameraValidation, RejectsPositionEqualToTarget) {
  expectRejected(makeCamera({1, 2, 3}, {1, 2, 3}), "differ");
}

TEST(CameraValidation, RejectsViewDirectionParallelToUp) {
  expectRejected(makeCamera({0, 5, 0}, {0, 0, 0}), "parallel");
  expectRejected(makeCamera({0, -5, 0}, {0, 0, 0}), "parallel");
  // Slightly off the axis is a valid (if steep) camera.
  EXPECT_EQ(validateCamera(makeCamera({0.01f, 5, 0}, {0, 0, 0})), "");
}

TEST(CameraValidation, RejectsNonPositiveAspect) {
  EXPECT_THROW(clipFromView(Camera{}, 0.0f), InputError);
  EXPECT_THROW(clipFromView(Camera{}, -1.0f), InputError);
}

}  // namespace
}  // namespace twr
