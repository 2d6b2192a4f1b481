// Shading: Phong with attenuation against hand-computed values, maps, lighting spaces,
// debug views, and every NaN source guarded.
#include "softrender/shade.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace twr {
namespace {

constexpr float kEps = 1e-5f;

using PlainShaded = ShaderFeatures<false, LightingSpace::World>;

// Surface at the origin facing +z, eye on +z.
Fragment surfaceFragment() {
  Fragment f;
  f.posWorld = vec3(0.0f);
  f.nWorld = vec3(0, 0, 1);
  f.tWorld = vec3(1, 0, 0);
  f.bWorld = vec3(0, 1, 0);
  f.uv = vec2(0.25f, 0.25f);
  f.depth = 0.5f;
  return f;
}

ShadeUniforms uniformsWithLight(vec3 lightPos, vec3 attenuation) {
  ShadeUniforms u;
  u.ka = vec3(0.2f);
  u.kd = vec3(0.5f);
  u.ks = vec3(0.25f);
  u.shininess = 8.0f;
  u.ambient = vec3(0.5f);
  u.eyePosWorld = vec3(0, 0, 5);
  u.lightCount = 1;
  u.lights[0].vectorWorld = vec4(lightPos, 1.0f);  // a point light
  u.lights[0].diffuse = vec3(1.0f);
  u.lights[0].specular = vec3(1.0f);
  u.lights[0].attenuation = attenuation;
  return u;
}

TEST(Shade, PhongHeadOnByHand) {
  // L = V = N = (0,0,1), d = 2, If = 1 / (1 + 0.5 * 2 + 0.25 * 4) = 1/3:
  // C = 0.2 * 0.5 + (0.5 * 1 + 0.25 * 1^8) / 3 = 0.1 + 0.25 = 0.35.
  ShadeTerms terms;
  const vec4 c = shadeFragment<PlainShaded>(surfaceFragment(), uniformsWithLight({0, 0, 2}, {1, 0.5f, 0.25f}), &terms);
  EXPECT_NEAR(c.r, 0.35f, kEps);
  EXPECT_EQ(c.a, 1.0f);
  EXPECT_NEAR(terms.lights[0].distance, 2.0f, kEps);
  EXPECT_NEAR(terms.lights[0].attenuation, 1.0f / 3.0f, kEps);
  EXPECT_NEAR(terms.lights[0].nDotL, 1.0f, kEps);
  EXPECT_NEAR(terms.lights[0].rDotV, 1.0f, kEps);
  EXPECT_NEAR(terms.ambient.r, 0.1f, kEps);
}

TEST(Shade, PhongAtFortyFiveDegreesByHand) {
  // Light at (2,0,2): L = (1,0,1)/sqrt2, N.L = 1/sqrt2, R = 2 (N.L) N - L = (-1,0,1)/sqrt2,
  // R.V = 1/sqrt2, (R.V)^8 = 1/16, If = 1 (no attenuation):
  // C = 0.1 + 0.5 / sqrt2 + 0.25 / 16.
  ShadeTerms terms;
  const vec4 c = shadeFragment<PlainShaded>(surfaceFragment(), uniformsWithLight({2, 0, 2}, {1, 0, 0}), &terms);
  const float s = 1.0f / std::sqrt(2.0f);
  EXPECT_NEAR(terms.lights[0].r.x, -s, kEps);
  EXPECT_NEAR(terms.lights[0].r.z, s, kEps);
  EXPECT_NEAR(c.g, 0.1f + 0.5f * s + 0.25f / 16.0f, kEps);
}

TEST(Shade, DirectionalLightIsUnattenuatedAndTheSameEverywhere) {
  // Shining straight down the normal's opposite, (0, 0, -1): L = (0, 0, 1) at any point, d = 1,
  // If = 1 / (1 + 0 + 0) = 1 exactly: C = 0.2 * 0.5 + 0.5 * 1 + 0.25 * 1^8 = 0.85.
  Light sun;
  sun.type = LightType::Directional;
  sun.directionWorld = vec3(0.0f, 0.0f, -1.0f);
  sun.attenuation = vec3(1.0f, 0.5f, 0.25f);  // a point light's, ignored
  ShadeUniforms u = uniformsWithLight({0, 0, 0}, attenuationUsed(sun));
  u.lights[0].vectorWorld = lightVectorWorld(sun);
  EXPECT_EQ(u.lights[0].vectorWorld, vec4(0.0f, 0.0f, 1.0f, 0.0f));
  EXPECT_EQ(u.lights[0].attenuation, vec3(1.0f, 0.0f, 0.0f));
  ShadeTerms terms;
  const vec4 c = shadeFragment<PlainShaded>(surfaceFragment(), u, &terms);
  EXPECT_EQ(terms.lights[0].attenuation, 1.0f);
  EXPECT_EQ(terms.lights[0].distance, 1.0f);
  EXPECT_NEAR(c.r, 0.85f, kEps);
  Fragment moved = surfaceFragment();
  moved.posWorld = vec3(40.0f, -7.0f, 0.0f);  // the sun is as far from every point (the eye is not)
  ShadeTerms there;
  shadeFragment<PlainShaded>(moved, u, &there);
  EXPECT_EQ(there.lights[0].nDotL, terms.lights[0].nDotL);
  EXPECT_EQ(there.lights[0].attenuation, 1.0f);
  EXPECT_EQ(there.lights[0].lVec, terms.lights[0].lVec);
}

TEST(Shade, SpotConeScalesTheLightBySmoothstepOfTheAngle) {
  // A spot light 2 above the surface point, its axis tilted by a known angle from straight
  // down: full within 20 degrees, nothing beyond 30, smoothstep of the cosine between.
  const auto attenuationAt = [](float tiltDeg, float innerDeg = 20.0f) {
    Light light;
    light.posWorld = vec3(0.0f, 0.0f, 2.0f);
    const float a = tiltDeg * 3.14159265f / 180.0f;
    light.spot = SpotCone{vec3(std::sin(a), 0.0f, -std::cos(a)), innerDeg, 30.0f};
    ShadeUniforms u = uniformsWithLight(light.posWorld, {1, 0, 0});
    const SpotUniform spot = spotUniformOf(light);
    u.lights[0].spot = true;
    u.lights[0].spotAxis = vec3(spot.axis);
    u.lights[0].spotCosOuter = spot.cone.x;
    u.lights[0].spotCosRange = spot.cone.y;
    ShadeTerms terms;
    shadeFragment<PlainShaded>(surfaceFragment(), u, &terms);
    return terms.lights[0].attenuation;
  };
  EXPECT_NEAR(attenuationAt(0.0f), 1.0f, kEps);
  EXPECT_NEAR(attenuationAt(19.0f), 1.0f, kEps);
  EXPECT_EQ(attenuationAt(31.0f), 0.0f);
  EXPECT_EQ(attenuationAt(150.0f), 0.0f);  // pointing away
  const float c = std::cos(25.0f * 3.14159265f / 180.0f), lo = std::cos(30.0f * 3.14159265f / 180.0f),
              hi = std::cos(20.0f * 3.14159265f / 180.0f);
  const float x = (c - lo) / (hi - lo);
  EXPECT_NEAR(attenuationAt(25.0f), x * x * (3.0f - 2.0f * x), 1e-4f);
  // A hard-edged cone (inner == outer) is a step, not a division by zero.
  Light hard;
  hard.spot = SpotCone{vec3(0.0f, 0.0f, -1.0f), 30.0f, 30.0f};
  EXPECT_EQ(spotUniformOf(hard).cone.y, kMinSpotCosineRange);
  EXPECT_EQ(attenuationAt(29.0f, 30.0f), 1.0f);
  EXPECT_EQ(attenuationAt(31.0f, 30.0f), 0.0f);
  EXPECT_TRUE(std::isfinite(attenuationAt(30.0f, 30.0f)));
}

TEST(Shade, LightBehindTheSurfaceGivesOnlyAmbient) {
  const vec4 c = shadeFragment<PlainShaded>(surfaceFragment(), uniformsWithLight({0, 0, -2}, {1, 0, 0}), nullptr);
  EXPECT_NEAR(c.r, 0.1f, kEps);
}

TEST(Shade, LightAtTheSurfaceIsFinite) {
  // d = 0 and A_C = 0: L = safeNormalize(0) = (0,0,1), If = 1 / kMinAttenuationDenominator.
  ShadeTerms terms;
  const vec4 c = shadeFragment<PlainShaded>(surfaceFragment(), uniformsWithLight({0, 0, 0}, {0, 1, 1}), &terms);
  EXPECT_TRUE(std::isfinite(terms.lights[0].attenuation));
  EXPECT_EQ(terms.lights[0].distance, 0.0f);
  EXPECT_EQ(c, vec4(1.0f));  // saturated, never NaN
}

TEST(Shade, ZeroShininessAndZeroReflectionFollowTheContract) {
  EXPECT_EQ(lanes::phongPow(0.0f, 0.0f), 1.0f);
  EXPECT_EQ(lanes::phongPow(0.0f, 8.0f), 0.0f);
  EXPECT_NEAR(lanes::phongPow(0.5f, 2.0f), 0.25f, kEps);
  ShadeUniforms u = uniformsWithLight({2, 0, 2}, {1, 0, 0});
  u.shininess = 0.0f;  // specular = ks * 1 whenever N.L > 0
  ShadeTerms terms;
  shadeFragment<PlainShaded>(surfaceFragment(), u, &terms);
  EXPECT_NEAR(terms.lights[0].specular.r, 0.25f, kEps);
}

TEST(Shade, DegenerateFrameNeverMakesNaN) {
  Fragment f = surfaceFragment();
  f.nWorld = f.tWorld = f.bWorld = vec3(0.0f);
  ShadeUniforms u = uniformsWithLight({0, 0, 0}, {0, 0, 0});
  u.eyePosWorld = vec3(0.0f);
  Texture flat;
  flat.width = flat.height = 1;
  flat.rgba = {128, 128, 128, 255};  // decodes to a near-zero tangent-space vector
  u.normalMap = &flat;
  for (View view : kAllViews) {
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      ShaderKey key;
      key.normalMap = true;
      key.space = space;
      key.view = view;
      u.view = fragmentViewOf(view);
      const vec4 c = shadeFragmentDynamic(key, f, u, nullptr);
      for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isfinite(c[i])) << toString(view);
    }
  }
}

TEST(Shade, NormalMapTiltsTheNormalAlongTheTangentFrame) {
  // Texel (255, 128, 128): m = normalize(2 c - 1) ~ (1, 0.004, 0.004): Nl ~ T in world space.
  Texture map;
  map.width = map.height = 1;
  map.rgba = {255, 128, 128, 255};
  ShadeUniforms u = uniformsWithLight({0, 0, 2}, {1, 0, 0});
  u.normalMap = &map;
  ShadeTerms terms;
  shadeFragment<ShaderFeatures<true, LightingSpace::World>>(surfaceFragment(), u, &terms);
  EXPECT_NEAR(terms.nl.x, 1.0f, 1e-4f);
  EXPECT_NEAR(terms.lights[0].nDotL, terms.nl.z, kEps);
  // Tangent lighting space: Nl is the mapped vector itself.
  shadeFragment<ShaderFeatures<true, LightingSpace::Tangent>>(surfaceFragment(), u, &terms);
  EXPECT_NEAR(terms.nl.x, terms.mappedTangent.x, kEps);
  EXPECT_NEAR(terms.mappedTangent.x, 1.0f, 1e-4f);
}

TEST(Shade, TangentSpaceUsesTheInterpolatedDirections) {
  Fragment f = surfaceFragment();
  f.lightDirTangent[0] = vec3(0, 0, 3);  // straight above in tangent space
  f.eyeDirTangent = vec3(0, 0, 7);
  ShadeUniforms u = uniformsWithLight({0, 0, 2}, {1, 0, 0});  // d = 2 from posWorld, If = 1
  const vec4 c = shadeFragment<ShaderFeatures<false, LightingSpace::Tangent>>(f, u, nullptr);
  EXPECT_NEAR(c.r, 0.1f + 0.5f + 0.25f, kEps);
}

TEST(Shade, DiffuseAndSpecularMapsScaleTheirTerms) {
  Texture albedo, spec;
  albedo.width = albedo.height = spec.width = spec.height = 1;
  albedo.rgba = {255, 0, 51, 255};  // (1, 0, 0.2)
  spec.rgba = {0, 255, 0, 255};
  ShadeUniforms u = uniformsWithLight({0, 0, 2}, {1, 0, 0});
  u.diffuseMap = &albedo;
  u.specularMap = &spec;
  const vec4 c = shadeFragment<ShaderFeatures<false, LightingSpace::World>>(surfaceFragment(), u, nullptr);
  // r: 0.2*1*0.5 + 0.5*1 + 0.25*0 = 0.6; g: 0 + 0 + 0.25*1 = 0.25; b: 0.2*0.2*0.5 + 0.5*0.2 = 0.12.
  EXPECT_NEAR(c.r, 0.6f, kEps);
  EXPECT_NEAR(c.g, 0.25f, kEps);
  EXPECT_NEAR(c.b, 0.12f, kEps);
}

// The diffuse and specular maps are read at run time (materialTexels), so what the key's
// canonical form drops for a view must also be left unread by the shading itself: the trace
// of a view shows exactly the texels that view reads.
TEST(Shade, AViewReadsOnlyTheColourMapsItShows) {
  Texture albedo, spec;
  albedo.width = albedo.height = spec.width = spec.height = 1;
  albedo.rgba = {255, 0, 255, 255};  // (1, 0, 1): bytes 0 and 255 read back exactly
  spec.rgba = {0, 255, 0, 255};      // (0, 1, 0)
  ShadeUniforms u = uniformsWithLight({0, 0, 2}, {1, 0, 0});
  u.diffuseMap = &albedo;
  u.specularMap = &spec;
  const auto texelsIn = [&](View view) {
    u.view = view;
    ShadeTerms terms;
    shadeFragment<PlainShaded>(surfaceFragment(), u, &terms);
    return std::pair(terms.albedo, terms.specScale);
  };
  const vec3 white(1.0f), mappedAlbedo(1, 0, 1), mappedSpec(0, 1, 0);
  for (View view : {View::Shaded, View::Shadow, View::Specular, View::ReflectDir}) {
    SCOPED_TRACE(toString(view));
    EXPECT_EQ(texelsIn(view), std::pair(mappedAlbedo, mappedSpec));
  }
  for (View view : {View::Albedo, View::MipLevel}) {
    SCOPED_TRACE(toString(view));
    EXPECT_EQ(texelsIn(view), std::pair(mappedAlbedo, white));
  }
  for (View view : {View::Normal, View::MappedNormal, View::Uv, View::Height, View::SelfShadow}) {
    SCOPED_TRACE(toString(view));
    EXPECT_EQ(texelsIn(view), std::pair(white, white));
  }
  // And the key agrees, so equal pictures share one kernel.
  ShaderKey key;
  key.diffuseMap = key.specularMap = true;
  key.view = View::Albedo;
  EXPECT_TRUE(canonicalShaderKey(key).diffuseMap);
  EXPECT_FALSE(canonicalShaderKey(key).specularMap);
  key.view = View::Normal;
  EXPECT_FALSE(canonicalShaderKey(key).diffuseMap);
  EXPECT_FALSE(canonicalShaderKey(key).specularMap);
}

TEST(Shade, PhongTermViewsShowEachTermAloneSummedOverTheLights) {
  // Two lights: head-on at (0,0,2) with If 1/3 (PhongHeadOnByHand) and at (2,0,2) unattenuated
  // (PhongAtFortyFiveDegreesByHand). ambient 0.2 * 0.5 = 0.1; diffuse 0.5 / 3 + 0.5 / sqrt2;
  // specular 0.25 / 3 + 0.25 / 16; shaded = their sum, clamped.
  ShadeUniforms u = uniformsWithLight({0, 0, 2}, {1, 0.5f, 0.25f});
  u.lightCount = 2;
  u.lights[1] = u.lights[0];
  u.lights[1].vectorWorld = vec4(2, 0, 2, 1);
  u.lights[1].attenuation = vec3(1, 0, 0);
  const float s = 1.0f / std::sqrt(2.0f);
  const float ambient = 0.1f, diffuse = 0.5f / 3.0f + 0.5f * s, specular = 0.25f / 3.0f + 0.25f / 16.0f;
  ShaderKey key;
  const auto viewColour = [&](View v) {
    u.view = v;
    key.view = v;
    return shadeFragmentDynamic(key, surfaceFragment(), u, nullptr);
  };
  EXPECT_NEAR(viewColour(View::Ambient).g, ambient, kEps);
  EXPECT_NEAR(viewColour(View::Diffuse).g, diffuse, kEps);
  EXPECT_NEAR(viewColour(View::Specular).g, specular, kEps);
  EXPECT_EQ(viewColour(View::Specular).a, 1.0f);
  EXPECT_NEAR(viewColour(View::Shaded).g, std::min(ambient + diffuse + specular, 1.0f), kEps);
  // The trace keeps the sums the views show.
  ShadeTerms terms;
  u.view = View::Diffuse;
  shadeFragment<PlainShaded>(surfaceFragment(), u, &terms);
  EXPECT_NEAR(terms.diffuseSum.b, diffuse, kEps);
  EXPECT_NEAR(terms.specularSum.b, specular, kEps);
  EXPECT_NEAR(terms.colour.b, diffuse, kEps);
}

TEST(Shade, DebugViews) {
  ShadeUniforms u = uniformsWithLight({0, 3, 0}, {1, 0, 0});
  Fragment f = surfaceFragment();
  f.uv = vec2(2.25f, -0.25f);
  f.depth = 0.3f;
  auto view = [&](View v) {
    ShaderKey key;
    key.view = v;
    u.view = v;
    return shadeFragmentDynamic(key, f, u, nullptr);
  };
  EXPECT_EQ(view(View::Normal), vec4(0.5f, 0.5f, 1.0f, 1.0f));
  EXPECT_EQ(view(View::Tangent), vec4(1.0f, 0.5f, 0.5f, 1.0f));
  EXPECT_EQ(view(View::Bitangent), vec4(0.5f, 1.0f, 0.5f, 1.0f));
  EXPECT_EQ(view(View::Albedo), vec4(0.5f, 0.5f, 0.5f, 1.0f));  // white times kd
  const vec4 uv = view(View::Uv);
  EXPECT_NEAR(uv.r, 0.25f, kEps);  // fract(2.25)
  EXPECT_NEAR(uv.g, 0.75f, kEps);  // fract(-0.25)
  EXPECT_EQ(view(View::Depth), vec4(0.3f, 0.3f, 0.3f, 1.0f));
  // Light straight up the bitangent: tangent-space direction (0, 1, 0) shown as (0.5, 1, 0.5).
  const vec4 light = view(View::LightTangent);
  EXPECT_NEAR(light.g, 1.0f, kEps);
  EXPECT_NEAR(light.r, 0.5f, kEps);
  const vec4 eye = view(View::EyeTangent);  // eye straight above: (0, 0, 1)
  EXPECT_NEAR(eye.b, 1.0f, kEps);
  ShadeUniforms dark = u;
  dark.lightCount = 0;
  dark.view = View::LightTangent;
  ShaderKey key;
  key.view = View::LightTangent;
  EXPECT_EQ(shadeFragmentDynamic(key, f, dark, nullptr), vec4(0.5f, 0.5f, 0.5f, 1.0f));
}

}  // namespace
}  // namespace twr
