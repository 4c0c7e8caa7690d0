// The BVH node encodings: the host writes them (host/bvh/bvh.cpp), the traversal reads them (traversal.glsl).
// Encode and decode side by side; both languages compile this file.
//
// 4-wide node (BvhWideNode, the layout the kernels walk): four RGBA32UI texels, one cache line. Child boxes are
// quantized to 8-bit steps on a grid over the node's box, rounded strictly outwards (Ylitie et al. 2017):
//   texel 0 (kBvhWideGridTexel):     the grid's origin xyz as float bits; w: the step exponents, biased as a
//                                    float's (step = 2^(e - 127)), in bytes 0, 1, 2 for x, y, z
//   texel 1 (kBvhWideXyPlanesTexel): the plane words lo.x, hi.x, lo.y, hi.y: child i's step count in byte i
//   texel 2 (kBvhWideZPlanesTexel):  the plane words lo.z, hi.z; zw unused
//   texel 3 (kBvhWideChildTexel):    the four child entries: a wide node index, a leaf entry or kBvhEmptySlot
// A plane's value is origin + steps * step.
//
// Binary node (BvhGpuNode, kept for side-by-side benchmarks with VKMC_BVH2): four RGBA32F texels; child c is
// (min.xyz, ref) in texel 2c and (max.xyz, count) in texel 2c + 1, ref and count as float bits; count > 0 is a
// leaf of triangles [ref, ref + count), count 0 the inner node ref.
#ifndef VKMC_BVH_LAYOUT_H
#define VKMC_BVH_LAYOUT_H
#include "glsl_cpp.h"
VKMC_BEGIN_NAMESPACE

VKMC_CONST uint kBvhNodeTexels = 4u;  // both layouts
VKMC_CONST uint kBvhWideGridTexel = 0u;
VKMC_CONST uint kBvhWideXyPlanesTexel = 1u;
VKMC_CONST uint kBvhWideZPlanesTexel = 2u;
VKMC_CONST uint kBvhWideChildTexel = 3u;

// Entries: a wide node's children and the walk's stack. A leaf is tagged in the top bit, holds its size - 1 in
// the next four and its first triangle below.
VKMC_CONST uint kBvhLeafTag = 0x80000000u;
VKMC_CONST uint kBvhMaxLeafSize = 8u;
VKMC_CONST uint kBvhLeafFirstLimit = 1u << 27u;  // a leaf's first triangle is below this
VKMC_CONST uint kBvhEmptySlot = 0x7f7fffffu;     // FLT_MAX's bits: no NaN on the way through a float texel
VKMC_CONST uint kBvhNoEntry = 0xffffffffu;       // the walk's empty stack slot
// The 4-wide walk's register stack (traversal.glsl RegisterStack: three uvec4). A walk pushes at most the
// children it does not enter next (at most kBvhWideChildren - 1) per inner node on its path; a tree whose paths
// pend no more than 4 or 8 of them gets a stack of that many (SPEC_REGISTER_STACK, registerStackEntries in
// bvh.h): fewer registers to shift and spill on every step of its walk.
VKMC_CONST uint kBvhWideChildren = 4u;
VKMC_CONST uint kBvhRegisterStackEntries = 12u;  // the most the walk holds in registers

VKMC_FN uint bvhLeafEntry(uint first, uint count) { return kBvhLeafTag | ((count - 1u) << 27u) | first; }
VKMC_FN uint bvhLeafFirst(uint entry) { return entry & 0x07ffffffu; }
VKMC_FN uint bvhLeafCount(uint entry) { return ((entry >> 27u) & 0xfu) + 1u; }
VKMC_FN bool bvhIsLeaf(uint entry) { return entry != kBvhNoEntry && (entry & kBvhLeafTag) != 0u; }

// Step exponents of texel 0's w: encode (biased exponents 1..254 per axis) and decode to the step sizes.
VKMC_FN uint bvhWideStepExponents(uvec3 biased) { return biased.x | (biased.y << 8u) | (biased.z << 16u); }
VKMC_FN uvec3 bvhWideStepBiased(uint exponents) { return (uvec3(exponents) >> uvec3(0u, 8u, 16u)) & 0xffu; }
VKMC_FN vec3 bvhWideStep(uint exponents) { return uintBitsToFloat(bvhWideStepBiased(exponents) << 23u); }

// A plane word: child i's step count in byte i. Encode one child's, decode all four.
VKMC_FN uint bvhWideSetPlaneSteps(uint word, uint child, uint steps) {
  return (word & ~(0xffu << (8u * child))) | (steps << (8u * child));
}
VKMC_FN uvec4 bvhWidePlaneSteps(uint word) { return (uvec4(word) >> uvec4(0u, 8u, 16u, 24u)) & 0xffu; }

// The plane words of one axis, (lo, hi), from texels 1 and 2.
VKMC_FN uvec2 bvhWidePlaneWords(uvec4 xyPlanes, uvec4 zPlanes, uint axis) {
  return axis == 0u ? uvec2(xyPlanes.x, xyPlanes.y) : axis == 1u ? uvec2(xyPlanes.z, xyPlanes.w) : uvec2(zPlanes.x, zPlanes.y);
}

// Empty plane words: lo = 255 > hi = 0, so an empty slot's box is empty even before its entry is checked.
VKMC_CONST uint kBvhWideEmptyLoWord = 0xffffffffu;
VKMC_CONST uint kBvhWideEmptyHiWord = 0u;

VKMC_END_NAMESPACE
#endif
