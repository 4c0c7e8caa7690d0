// Lets one source compile as GLSL and as C++ (glm): the shared headers use only the GLSL subset.
#ifndef VKMC_GLSL_CPP_H
#define VKMC_GLSL_CPP_H
#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>
namespace vkmc::gpu {
using namespace glm;
using uint = uint32_t;
}  // namespace vkmc::gpu
#define VKMC_BEGIN_NAMESPACE namespace vkmc::gpu {
#define VKMC_END_NAMESPACE }
#define VKMC_CONST inline constexpr
#define VKMC_FN inline
#define VKMC_STATIC_ASSERT(cond) static_assert(cond, #cond)
#define INOUT(T) T&
#else
#define VKMC_BEGIN_NAMESPACE
#define VKMC_END_NAMESPACE
#define VKMC_CONST const
#define VKMC_FN
#define VKMC_STATIC_ASSERT(cond)
#define INOUT(T) inout T
#endif
#endif
