# canopy_add_shaders(TARGET <target> OWNER <harness|family> [INCLUDE_DIRS <dir ...>]
#                    SOURCES <file.vert|.frag|.comp ...>)
# Compiles GLSL to SPIR-V at build time and embeds it: for shader `dir/name.stage`, the target
# gets the header `shaders/<owner>/name_stage.h` declaring `const uint32_t name_stage[]`. The
# owner is `harness` for the harness's own shaders and the folder name of a family
# (techniques/<family>/), so two families may each have a `blade.vert`; within one owner the
# names must differ.
# Shaders #include files from their own folder, then harness/shaders, then INCLUDE_DIRS (a
# family's shared shader folder, techniques/<family>/shaders), so one family's headers are not
# visible to another's shaders (GL_GOOGLE_include_directive). A change to any file a shader
# includes (glslang's depfile, e.g. a family's shared headers) rebuilds it.
function(canopy_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET;OWNER" "INCLUDE_DIRS;SOURCES" ${ARGN})
  if(NOT ARG_OWNER)
    message(FATAL_ERROR "canopy_add_shaders: OWNER (harness or the family's folder name) is required")
  endif()
  set(out_dir ${CMAKE_BINARY_DIR}/generated/shaders/${ARG_OWNER})
  file(MAKE_DIRECTORY ${out_dir})
  set(include_dirs ${PROJECT_SOURCE_DIR}/harness/shaders ${ARG_INCLUDE_DIRS})
  set(include_flags)
  set(shared_includes)
  foreach(dir IN LISTS include_dirs)
    list(APPEND include_flags -I${dir})
    file(GLOB dir_includes ${dir}/*.glsl ${dir}/*.h)
    list(APPEND shared_includes ${dir_includes})
  endforeach()
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
    if(header IN_LIST headers)
      message(FATAL_ERROR "canopy_add_shaders: two ${ARG_OWNER} shaders would both generate shaders/${ARG_OWNER}/${var}.h (${src})")
    endif()
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.3 ${include_flags}
              --vn ${var} --depfile ${header}.d -o ${header} ${abs}
      DEPENDS ${abs} ${shared_includes} ${local_includes}
      DEPFILE ${header}.d
      COMMENT "GLSL -> SPIR-V ${src}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${headers})
  target_include_directories(${ARG_TARGET} PUBLIC ${CMAKE_BINARY_DIR}/generated)
endfunction()
