// A light's shadow map as the shading reads it (shadow-inl.h; shade.h's LightUniformT holds
// one). Plain types, outside the per-target namespaces, so every lane type reads the same
// struct. scene/shadow_map.h has the test itself.
#pragma once

#include "scene/shadow_map.h"
#include "softrender/precision.h"

namespace twr {

template <typename S>
struct ShadowUniformT {
  // Null: the light casts no shadow; nothing is read.
  const float* depth = nullptr;  // ShadowMap::depth: layers * size * size window depths
  ShadowKind kind = ShadowKind::Orthographic;
  Mat4T<S> clipFromWorld{S(1)};  // orthographic and spot (perspective): the map's clip from world
  Vec3T<S> lightPosWorld{S(0)};  // cube: the light
  S depthA = S(0), depthB = S(0);  // cube and spot: the faces' depth terms (ShadowProjection)
  S size = S(1);                   // texels per side, as a lane value
  S biasConstant = S(0);  // world units along the light
  S biasSlope = S(0);     // texels of the surface's rise
  S texelWorld = S(0), depthPerWorld = S(0);  // ShadowProjection's bias scales
  int pcf = 1;            // 1, 3 or 5
};

// The uniform of `map` (null: none), in the lane scalar S (float values rounded once).
template <typename S>
ShadowUniformT<S> makeShadowUniform(const ShadowMap* map) {
  ShadowUniformT<S> u;
  if (!map) return u;
  const ShadowProjection& p = map->projection;
  u.depth = map->depth.data();
  u.kind = p.kind;
  u.clipFromWorld = Mat4T<S>(p.clipFromWorld[0]);
  u.lightPosWorld = Vec3T<S>(p.lightPosWorld);
  u.depthA = static_cast<S>(p.depthA);
  u.depthB = static_cast<S>(p.depthB);
  u.size = static_cast<S>(p.size);
  u.biasConstant = static_cast<S>(p.bias.x);
  u.biasSlope = static_cast<S>(p.bias.y);
  u.texelWorld = static_cast<S>(p.texelWorld);
  u.depthPerWorld = static_cast<S>(p.depthPerWorld);
  u.pcf = p.pcf;
  return u;
}

}  // namespace twr
