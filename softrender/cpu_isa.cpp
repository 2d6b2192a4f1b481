// The fast path's Highway targets by name (cpu_renderer.h): which are compiled into this
// binary (HWY_TARGETS, set by the compile definitions in CMakeLists.txt), which this CPU runs
// (hwy::SupportedTargets), and the names the command line and reports use.
#include "softrender/cpu_isa_targets.h"
#include "softrender/cpu_renderer.h"

#include <hwy/targets.h>

#include <array>

namespace twr {

namespace {

struct IsaName {
  CpuIsa isa;
  std::string_view name;
};
constexpr std::array<IsaName, 6> kIsaNames = {{{CpuIsa::Auto, "auto"},
                                               {CpuIsa::Avx512, "avx512"},
                                               {CpuIsa::Avx2, "avx2"},
                                               {CpuIsa::Sse4, "sse4"},
                                               {CpuIsa::Neon, "neon"},
                                               {CpuIsa::Scalar, "scalar"}}};

// Best first, as supportedCpuIsas() lists them.
constexpr std::array<CpuIsa, 5> kTargetsBestFirst = {CpuIsa::Avx512, CpuIsa::Avx2, CpuIsa::Sse4, CpuIsa::Neon,
                                                     CpuIsa::Scalar};

}  // namespace

std::int64_t highwayTargetOf(CpuIsa isa) {
  switch (isa) {
    case CpuIsa::Avx512: return HWY_AVX3;
    case CpuIsa::Avx2: return HWY_AVX2;
    case CpuIsa::Sse4: return HWY_SSE4;
    case CpuIsa::Neon: return HWY_NEON;
    // Highway's portable target: EMU128 (four lanes emulated) where the compiler builds it,
    // otherwise SCALAR (one lane); GCC before 12.3 only gets SCALAR.
    case CpuIsa::Scalar: return (HWY_TARGETS & HWY_EMU128) != 0 ? HWY_EMU128 : HWY_SCALAR;
    case CpuIsa::Auto: break;
  }
  return 0;
}

std::string_view toString(CpuIsa isa) {
  for (const IsaName& n : kIsaNames) {
    if (n.isa == isa) return n.name;
  }
  return "auto";
}

bool parse(std::string_view name, CpuIsa& out) {
  for (const IsaName& n : kIsaNames) {
    if (n.name == name) {
      out = n.isa;
      return true;
    }
  }
  return false;
}

std::string allCpuIsaNames() {
  std::string names;
  for (const IsaName& n : kIsaNames) {
    if (!names.empty()) names += "|";
    names += n.name;
  }
  return names;
}

std::int64_t fastKernelTargets() {
#ifdef TWR_KERNEL_TARGETS
  return HWY_TARGETS & (TWR_KERNEL_TARGETS);
#else
  return HWY_TARGETS;
#endif
}

bool cpuIsaCompiled(CpuIsa isa) {
  const std::int64_t target = highwayTargetOf(isa);
  return target != 0 && (fastKernelTargets() & target) != 0;
}

std::vector<CpuIsa> supportedCpuIsas() {
  std::vector<CpuIsa> out;
  const std::int64_t supported = hwy::SupportedTargets();
  for (const CpuIsa isa : kTargetsBestFirst) {
    if (cpuIsaCompiled(isa) && (supported & highwayTargetOf(isa)) != 0) out.push_back(isa);
  }
  return out;
}

bool cpuIsaSupported(CpuIsa isa) {
  if (isa == CpuIsa::Auto) return true;
  for (const CpuIsa s : supportedCpuIsas()) {
    if (s == isa) return true;
  }
  return false;
}

CpuIsa resolveCpuIsa(CpuIsa isa) {
  if (isa != CpuIsa::Auto) return isa;
  const std::vector<CpuIsa> supported = supportedCpuIsas();
  return supported.empty() ? CpuIsa::Scalar : supported.front();
}

std::string cpuIsaUnsupportedReason(CpuIsa isa) {
  if (cpuIsaSupported(isa)) return "";
  std::string runs;
  for (const CpuIsa s : supportedCpuIsas()) {
    if (!runs.empty()) runs += ", ";
    runs += toString(s);
  }
  const std::string name(toString(isa));
  if (!cpuIsaCompiled(isa)) {
#ifdef TWR_KERNEL_TARGETS
    return name + ": not compiled into this binary (built with the kernels for " + TWR_KERNEL_TARGET_NAMES +
           " only, TWINRASTER_KERNEL_TARGETS; it runs " + runs + ")";
#else
    return name + ": not compiled into this binary (built for " + (HWY_ARCH_X86 ? "x86-64" : HWY_ARCH_ARM ? "Arm" : "another architecture") +
           "; it runs " + runs + ")";
#endif
  }
  return name + ": this CPU lacks it (it runs " + runs + ")";
}

}  // namespace twr
