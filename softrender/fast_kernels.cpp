// The fast path's kernels (fast_kernels.h) and their dispatch, laid out as Highway's skeleton
// example: foreach_target.h re-includes this file for each target it can reach, with
// HWY_NAMESPACE naming that target's namespace and its instruction set switched on for the
// functions inside HWY_BEFORE_NAMESPACE / HWY_AFTER_NAMESPACE; each pass includes the kernel
// bodies (softrender/fast_kernels-inl.h) for that target, and the part under HWY_ONCE, compiled
// once, picks a target's kernels at run time.

// The kernels compile in four objects, side by side on a two-core machine: each
// fast_kernels_<group>.cpp defines TWR_FAST_KERNEL_TARGETS (a mask of Highway targets) and
// includes this file, and only its targets' kernels are defined there. Compiled by itself,
// this file defines no kernel: it holds the dispatch, which names every target's GetKernels.
// (One object of all four targets took over ten minutes of one core.)
//
// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "softrender/fast_kernels.cpp"
#include <hwy/foreach_target.h>  // re-includes this file, once per target
#include <hwy/highway.h>
// clang-format on

#include "softrender/fast_kernels.h"

#include "scene/errors.h"
#include "softrender/cpu_isa_targets.h"

#include <string>

// TWR_KERNEL_TARGETS (CMake's TWINRASTER_KERNEL_TARGETS): the targets given kernels at all; by
// default every one Highway compiles.
#ifndef TWR_KERNEL_TARGETS
#define TWR_KERNEL_TARGETS HWY_TARGETS
#endif

// This target's kernels (or, where another object compiles them, their declaration).
#include "softrender/fast_kernels-inl.h"

#if HWY_ONCE && !defined(TWR_FAST_KERNEL_TARGETS)
namespace twr {

#if TWR_KERNEL_TARGETS == HWY_TARGETS
HWY_EXPORT(GetKernels);
#endif

FastKernels fastKernelsFor(CpuIsa isa) {
  if (!cpuIsaSupported(isa)) throw InputError("cpu renderer: --cpu-isa " + cpuIsaUnsupportedReason(isa));
#if TWR_KERNEL_TARGETS == HWY_TARGETS
  if (isa == CpuIsa::Auto) return HWY_DYNAMIC_DISPATCH(GetKernels)();
#else
  // Highway's dispatch table would hold its portable target, which has no kernels here: the
  // best target with kernels, by name, with Highway's choice recorded as its dispatch does.
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
  isa = resolveCpuIsa(isa);
#endif
  // A named target: its namespace's kernels directly (each exists when HWY_TARGETS has it).
  switch (highwayTargetOf(isa)) {
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_AVX3
    case HWY_AVX3: return N_AVX3::GetKernels();
#endif
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_AVX2
    case HWY_AVX2: return N_AVX2::GetKernels();
#endif
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_SSE4
    case HWY_SSE4: return N_SSE4::GetKernels();
#endif
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_NEON
    case HWY_NEON: return N_NEON::GetKernels();
#endif
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_EMU128
    case HWY_EMU128: return N_EMU128::GetKernels();
#endif
#if HWY_TARGETS & TWR_KERNEL_TARGETS & HWY_SCALAR
    case HWY_SCALAR: return N_SCALAR::GetKernels();
#endif
    default: break;
  }
  throw InputError("cpu renderer: --cpu-isa " + std::string(toString(isa)) + ": no kernels compiled for it");
}

std::uint64_t exactSumPlaneBits(const BinTriangle& t) {
  const auto bit = [](const AttributePlaneT<float>& p, int at) {
    return planeSumsExactInDouble(p) ? std::uint64_t{1} << at : std::uint64_t{0};
  };
  std::uint64_t bits = bit(t.varyings.oneOverW, kExactSumOneOverWBit);
  for (int k = 0; k < t.varyings.count; ++k) {
    bits |= bit(t.varyings.overW[static_cast<std::size_t>(k)], kExactSumFirstVaryingBit + k);
  }
  return bits;
}

std::vector<RedFootprintLevel> makeRedFootprints(const Texture& texture) {
  std::vector<RedFootprintLevel> out;
  for (int l = 0; l < texture.levelCount(); ++l) {
    RedFootprintLevel level;
    level.width = texture.levelWidth(l);
    level.height = texture.levelHeight(l);
    const std::vector<std::uint8_t>& texels = texture.levelTexels(l);
    const auto red = [&](int x, int y) -> std::uint32_t {
      return texels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) + static_cast<std::size_t>(x)) * 4];
    };
    level.blocksPerRow = (level.width + kTexelBlockSide - 1) / kTexelBlockSide;
    const int blockRows = (level.height + kTexelBlockSide - 1) / kTexelBlockSide;
    level.blocks.resize(static_cast<std::size_t>(level.blocksPerRow) * static_cast<std::size_t>(blockRows));
    for (int y = 0; y < level.height; ++y) {
      const int y1 = y + 1 == level.height ? 0 : y + 1;
      for (int x = 0; x < level.width; ++x) {
        const int x1 = x + 1 == level.width ? 0 : x + 1;
        TexelBlock& block = level.blocks[static_cast<std::size_t>(y / kTexelBlockSide) * static_cast<std::size_t>(level.blocksPerRow) +
                                         static_cast<std::size_t>(x / kTexelBlockSide)];
        block.texels[static_cast<std::size_t>((y % kTexelBlockSide) * kTexelBlockSide + x % kTexelBlockSide)] =
            red(x, y) | red(x1, y) << 8 | red(x, y1) << 16 | red(x1, y1) << 24;
      }
    }
    out.push_back(std::move(level));
  }
  return out;
}

TiledTexture makeTiledTexture(const Texture& texture) {
  TiledTexture out;
  out.wrap = texture.options.wrap;
  out.srgb = texture.options.srgb;
  for (int l = 0; l < texture.levelCount(); ++l) {
    TiledLevel level;
    level.width = texture.levelWidth(l);
    level.height = texture.levelHeight(l);
    level.blocksPerRow = (level.width + kTexelBlockSide - 1) / kTexelBlockSide;
    const int blockRows = (level.height + kTexelBlockSide - 1) / kTexelBlockSide;
    level.blocks.resize(static_cast<std::size_t>(level.blocksPerRow) * static_cast<std::size_t>(blockRows));
    const std::vector<std::uint8_t>& texels = texture.levelTexels(l);
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        TexelBlock& block = level.blocks[static_cast<std::size_t>(y / kTexelBlockSide) * static_cast<std::size_t>(level.blocksPerRow) +
                                         static_cast<std::size_t>(x / kTexelBlockSide)];
        std::memcpy(&block.texels[static_cast<std::size_t>((y % kTexelBlockSide) * kTexelBlockSide + x % kTexelBlockSide)],
                    &texels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) + static_cast<std::size_t>(x)) * 4],
                    sizeof(std::uint32_t));
      }
    }
    out.levels.push_back(std::move(level));
  }
  return out;
}

}  // namespace twr
#endif  // HWY_ONCE && !defined(TWR_FAST_KERNEL_TARGETS)
