// Debian ships stb_image and tinyobjloader as shared libraries, which a fuzzer cannot see
// into: no coverage feedback and no ASan checks on their arrays, though they parse the
// hostile bytes. Compiling the same Debian headers here puts an instrumented copy into each
// fuzz executable; the executable's definitions take precedence over the shared libraries'.
// Fuzz builds only (TWINRASTER_FUZZ=ON); compiled without our warning flags (third-party code).
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
