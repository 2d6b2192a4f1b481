// Whether this test executable is built with AddressSanitizer (the sanitizer build, make
// sanitize): GCC says so with __SANITIZE_ADDRESS__, clang only through __has_feature.
#pragma once

namespace twr {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif
#else
inline constexpr bool kUnderSanitizers = false;
#endif

}  // namespace twr
