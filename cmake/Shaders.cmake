# canopy_add_shaders(TARGET <target> SOURCES <file.vert|.frag|.comp ...>)
# Compiles GLSL to SPIR-V at build time and embeds it: for shader `dir/name.stage`, the target
# gets the header `shaders/name_stage.h` declaring `const uint32_t name_stage[]`.
# Shaders #include files from harness/shaders and from their own folder (GL_GOOGLE_include_directive);
# a change to any file a shader includes (glslang's depfile, e.g. a family's common headers) rebuilds it.
function(canopy_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(out_dir ${CMAKE_BINARY_DIR}/generated/shaders)
  file(MAKE_DIRECTORY ${out_dir})
  file(GLOB shared_includes ${PROJECT_SOURCE_DIR}/harness/shaders/*.glsl ${PROJECT_SOURCE_DIR}/harness/shaders/*.h)
  set(headers)
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(src_dir ${abs} DIRECTORY)
    file(GLOB local_includes ${src_dir}/*.glsl ${src_dir}/*.h)  # includes beside the shader
    get_filename_component(name ${src} NAME_WE)
    get_filename_component(ext ${src} LAST_EXT)
    string(SUBSTRING ${ext} 1 -1 stage)
    set(var ${name}_${stage})
    string(REPLACE "-" "_" var ${var})
    set(header ${out_dir}/${var}.h)
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.3 -I${PROJECT_SOURCE_DIR}/harness/shaders
              -I${CMAKE_CURRENT_SOURCE_DIR} --vn ${var} --depfile ${header}.d -o ${header} ${abs}
      DEPENDS ${abs} ${shared_includes} ${local_includes}
      DEPFILE ${header}.d
      COMMENT "GLSL -> SPIR-V ${src}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${headers})
  target_include_directories(${ARG_TARGET} PUBLIC ${CMAKE_BINARY_DIR}/generated)
endfunction()
