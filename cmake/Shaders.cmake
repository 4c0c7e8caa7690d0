# add_kernel(): compiles one GLSL compute shader to SPIR-V and embeds it as a C array header,
# so the binary never looks up shader files at run time. Dependencies come from glslang's depfile.
set(VKMC_SHADER_DIR ${CMAKE_SOURCE_DIR}/shaders)
set(VKMC_SPIRV_DIR ${CMAKE_BINARY_DIR}/spirv)
file(MAKE_DIRECTORY ${VKMC_SPIRV_DIR})

# Extra arguments are preprocessor definitions (variants whose SPIR-V needs a capability, e.g. float atomics).
function(add_kernel out_list name source)
  set(header ${VKMC_SPIRV_DIR}/${name}_spv.h)
  set(defines)
  foreach(d ${ARGN})
    list(APPEND defines -D${d})
  endforeach()
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${GLSLANG_VALIDATOR} --target-env vulkan1.2 ${defines} -I${VKMC_SHADER_DIR}/shared -I${VKMC_SHADER_DIR}/include
            --vn kSpirv_${name} --depfile ${header}.d -o ${header} ${source}
    DEPENDS ${source}
    DEPFILE ${header}.d
    COMMENT "glslang ${name}"
    VERBATIM)
  set(${out_list} ${${out_list}} ${header} PARENT_SCOPE)
endfunction()
