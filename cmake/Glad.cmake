# Generates two glad 2 loaders at configure time, offline (--reproducible uses the
# gl.xml shipped in python3-glad):
#  - core:   GL 3.3 core, global function pointers (glad/gl.h), used by all GL code;
#  - compat: GL 3.3 compatibility with --mx (a GladGLContext struct instead of globals),
#            so its symbols never clash with the core loader's; only the immediate-mode
#            TBN lines use it, through glad_compat/gl.h.
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
foreach(flavour core compat)
  if(NOT EXISTS ${GLAD_OUT}/${flavour}/src/gl.c)
    if(flavour STREQUAL "core")
      set(api gl:core=3.3)
      set(extra)
    else()
      set(api gl:compatibility=3.3)
      set(extra --mx)
    endif()
    execute_process(
      COMMAND ${GLAD_EXECUTABLE} --api ${api} --out-path ${GLAD_OUT}/${flavour}-raw
              --reproducible --quiet c --loader ${extra}
      RESULT_VARIABLE glad_result OUTPUT_QUIET ERROR_VARIABLE glad_err)
    if(NOT glad_result EQUAL 0)
      message(FATAL_ERROR "glad (${flavour}) failed: ${glad_err}")
    endif()
    # Compat header lives under glad_compat/ so one translation unit can tell them apart.
    if(flavour STREQUAL "core")
      file(COPY ${GLAD_OUT}/${flavour}-raw/ DESTINATION ${GLAD_OUT}/${flavour})
    else()
      file(READ ${GLAD_OUT}/${flavour}-raw/src/gl.c compat_src)
      string(REPLACE "#include <glad/gl.h>" "#include <glad_compat/gl.h>" compat_src "${compat_src}")
      file(WRITE ${GLAD_OUT}/${flavour}/src/gl.c "${compat_src}")
      file(COPY ${GLAD_OUT}/${flavour}-raw/include/glad/gl.h DESTINATION ${GLAD_OUT}/${flavour}/include/glad_compat)
      file(COPY ${GLAD_OUT}/${flavour}-raw/include/KHR DESTINATION ${GLAD_OUT}/${flavour}/include)
    endif()
  endif()
endforeach()

add_library(twr_glad STATIC ${GLAD_OUT}/core/src/gl.c ${GLAD_OUT}/compat/src/gl.c)
set_source_files_properties(${GLAD_OUT}/compat/src/gl.c PROPERTIES
  INCLUDE_DIRECTORIES ${GLAD_OUT}/compat/include)
target_include_directories(twr_glad SYSTEM PUBLIC ${GLAD_OUT}/core/include ${GLAD_OUT}/compat/include)
target_link_libraries(twr_glad PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(twr_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
