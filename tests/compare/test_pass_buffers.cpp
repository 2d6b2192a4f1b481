// compare/pass_buffers.h on outputs made here: a deferred frame's G-buffer as planes, as a
// picture and as a frame the GUI's buffer picker shows; what a forward frame cannot show.
#include "compare/pass_buffers.h"

#include <gtest/gtest.h>

#include <memory>

namespace twr {
namespace {

// A 2 x 1 frame: pixel 0 drawn (triangle 7, depth 0.25), pixel 1 empty.
RenderOutput twoPixelFrame(bool deferred) {
  RenderOutput out;
  out.width = 2;
  out.height = 1;
  out.rgba = {10, 20, 30, 255, 1, 2, 3, 255};
  out.depth = {0.25f, 1.0f};
  out.triangleId = {7, kNoTriangle};
  if (deferred) {
    auto g = std::make_shared<GBuffer>();
    g->width = 2;
    g->height = 1;
    g->normal = {vec4(0.0f, 1.0f, -1.0f, 32.0f), vec4(0.0f)};
    g->geometric = {vec4(0.0f, 1.0f, 0.0f, 1.0f), vec4(0.0f)};
    g->albedo = {vec4(0.5f, 0.25f, 2.0f, 1.0f), vec4(0.0f)};
    g->specular = {vec4(0.1f, 0.1f, 0.1f, 1.0f), vec4(0.0f)};
    g->emission = {vec4(0.0f, 0.0f, 0.2f, 1.0f), vec4(0.0f)};
    g->position = {vec4(1.25f, -0.75f, 3.0f, 1.0f), vec4(0.0f)};
    out.gbuffer = g;
  }
  return out;
}

TEST(PassBuffers, GBufferTargetsAsPicturesAndPlanes) {
  const RenderOutput frame = twoPixelFrame(true);
  const std::optional<RenderOutput> normal = bufferAsOutput(frame, PassBuffer::GbufferNormal);
  ASSERT_TRUE(normal);
  // (n + 1) / 2: 0 -> 128, 1 -> 255, -1 -> 0.
  EXPECT_EQ(normal->rgba[0], 128);
  EXPECT_EQ(normal->rgba[1], 255);
  EXPECT_EQ(normal->rgba[2], 0);
  EXPECT_EQ(normal->triangleId, frame.triangleId);
  EXPECT_EQ(normal->depth, frame.depth);
  const std::optional<RenderOutput> albedo = bufferAsOutput(frame, PassBuffer::GbufferAlbedo);
  ASSERT_TRUE(albedo);
  EXPECT_EQ(albedo->rgba[0], 128);
  EXPECT_EQ(albedo->rgba[1], 64);
  EXPECT_EQ(albedo->rgba[2], 255);  // clamped
  // A position's triangle wave |2 fract(p / 2) - 1|: 1.25 -> 0.25 -> 64, -0.75 -> 0.25 -> 64, 3 -> 0.
  const std::optional<RenderOutput> position = bufferAsOutput(frame, PassBuffer::GbufferPosition);
  ASSERT_TRUE(position);
  EXPECT_EQ(position->rgba[0], 64);
  EXPECT_EQ(position->rgba[1], 64);
  EXPECT_EQ(position->rgba[2], 0);
  // Continuous across whole units: a floor at y = 0 rounds to either side of it and shows the same.
  const Image across = gbufferImage({vec4(1e-7f, -1e-7f, 0.0f, 1.0f)}, 1, 1, PassBuffer::GbufferPosition);
  EXPECT_EQ(across.rgba[0], 255);
  EXPECT_EQ(across.rgba[1], 255);
  EXPECT_EQ(across.rgba[2], 255);
  EXPECT_EQ(position->rgba[4], 0);  // pixel 1: nothing drawn (w 0), black
  // Planes: x, y, z of every pixel, layer by layer.
  const std::vector<float> planes = gbufferPlanes(frame.gbuffer->albedo, 2, 1);
  ASSERT_EQ(planes.size(), 6u);
  EXPECT_EQ(planes[0], 0.5f);
  EXPECT_EQ(planes[2], 0.25f);
  EXPECT_EQ(planes[4], 2.0f);
  // Two G-buffers one channel apart by more than 1/255: one texel over the tolerance.
  RenderOutput other = twoPixelFrame(true);
  auto g = std::make_shared<GBuffer>(*other.gbuffer);
  g->albedo[0].y += 0.01f;
  const DepthBufferMetrics m =
      compareDepthBuffers(planes, gbufferPlanes(g->albedo, 2, 1), 2, 1, 3, kGBufferTolerance);
  EXPECT_EQ(m.overTolerance, 1u);
  EXPECT_EQ(m.maxLayer, 1);
}

TEST(PassBuffers, WhatAFrameCannotShow) {
  const RenderOutput forward = twoPixelFrame(false);
  EXPECT_FALSE(bufferAsOutput(forward, PassBuffer::GbufferNormal));
  EXPECT_FALSE(bufferAsOutput(forward, PassBuffer::GbufferEmission));
  EXPECT_FALSE(bufferAsOutput(forward, PassBuffer::GbufferPosition));
  // A deferred frame that rebuilds its positions from depth stores none.
  RenderOutput fromDepth = twoPixelFrame(true);
  auto g = std::make_shared<GBuffer>(*fromDepth.gbuffer);
  g->position.clear();
  fromDepth.gbuffer = g;
  EXPECT_EQ(gbufferTargetOf(*g, PassBuffer::GbufferPosition), nullptr);
  EXPECT_FALSE(bufferAsOutput(fromDepth, PassBuffer::GbufferPosition));
  EXPECT_TRUE(bufferAsOutput(fromDepth, PassBuffer::GbufferNormal));
  EXPECT_FALSE(bufferAsOutput(forward, PassBuffer::ShadowMap));
  const std::optional<RenderOutput> final = bufferAsOutput(forward, PassBuffer::Final);
  ASSERT_TRUE(final);
  EXPECT_EQ(final->rgba, forward.rgba);
  const std::optional<RenderOutput> depth = bufferAsOutput(forward, PassBuffer::GbufferDepth);
  ASSERT_TRUE(depth);
  EXPECT_EQ(depth->rgba[0], 64);  // 0.25 of 255
  EXPECT_EQ(depth->rgba[4], 255);
  EXPECT_EQ(gbufferTargetOf(*twoPixelFrame(true).gbuffer, PassBuffer::Lighting), nullptr);
}

}  // namespace
}  // namespace twr
