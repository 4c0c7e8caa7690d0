// The binary SAH tree the GPU layouts are made from (bvh.cpp flattens and collapses it): a binned build (Wald
// 2007) over triangle boxes, parallel and deterministic, or the full-sweep reference build.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh.h"

namespace vkmc {

struct BuildNode {
  Aabb bounds;
  uint32_t first = 0, count = 0;  // leaf range in BinaryTree::order, count > 0
  uint32_t child[2] = {0, 0};     // inner node
};

struct BinaryTree {
  std::vector<BuildNode> nodes;  // node 0 is the root
  std::vector<uint32_t> order;   // leaf ranges index this permutation of the input triangles
  uint32_t maxDepth = 0;
  uint32_t threads = 1;  // threads the build ran on
};

// The same tree for every thread count: work is divided by fixed rules, never by which thread is first.
BinaryTree buildBinaryTree(std::span<const Aabb> bounds, const BvhOptions& options);

}  // namespace vkmc
