# Embeds every shaders/*.vert|*.frag|*.glsl into the binary at build time as C++ raw
# strings, so the programs run from any directory. The GUI can still reload from disk
# (TWINRASTER_SHADER_DIR points at the source folder).
file(GLOB TWINRASTER_SHADER_FILES CONFIGURE_DEPENDS
  ${CMAKE_SOURCE_DIR}/shaders/*.vert ${CMAKE_SOURCE_DIR}/shaders/*.frag ${CMAKE_SOURCE_DIR}/shaders/*.glsl)
set(TWINRASTER_SHADER_INCLUDE_DIR ${CMAKE_BINARY_DIR}/generated)
set(embedded_cpp ${TWINRASTER_SHADER_INCLUDE_DIR}/embedded_shaders.cpp)
add_custom_command(
  OUTPUT ${embedded_cpp}
  COMMAND ${CMAKE_COMMAND} -DOUT=${embedded_cpp} -DSHADER_DIR=${CMAKE_SOURCE_DIR}/shaders
          -P ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
  DEPENDS ${TWINRASTER_SHADER_FILES} ${CMAKE_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
  COMMENT "Embedding GLSL sources")
set(TWINRASTER_SHADER_SOURCES ${embedded_cpp})
add_compile_definitions(TWINRASTER_SHADER_DIR="${CMAKE_SOURCE_DIR}/shaders")
