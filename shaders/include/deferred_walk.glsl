// Deferred deep walks for kernels that trace a queue of items (one ray per item). llvmpipe runs every line of a
// shader for all 8 lanes of a subgroup, so the rare walk that outgrows the register stack (traversal.glsl) would
// make every lane pay an idle pass of traceRayDeep. Instead the kernel's first dispatch appends such items to
// deepWalks and stops; the same kernel built with VKMC_DEEP_PASS then runs over just those items, dispatched
// indirectly through control.deepArgs (which the host or a prepare kernel resets before the first pass).
layout(binding = BINDING_DEEP_WALKS, std430) buffer DeepWalks { uint deepWalks[]; };

// The item this invocation handles: its own index among `count` in the first pass, a deferred one in the second.
bool walkItem(uint count, out uint item) {
  uint slot = invocationIndex();
#ifdef VKMC_DEEP_PASS
  if (slot >= min(control.deepArgs.w, uint(deepWalks.length()))) return false;
  item = deepWalks[slot];
#else
  if (slot >= count) return false;
  item = slot;
#endif
  return true;
}

// Queues an item for the deep pass; the appender that opens a workgroup's worth of items adds the group to the
// indirect dispatch. false when the queue is full (or the dispatch would pass the 65535-group limit).
bool deferWalk(uint item) {
  uint slot = atomicAdd(control.deepArgs.w, 1u);
  uint capacity = min(uint(deepWalks.length()), 65535u * gl_WorkGroupSize.x);
  if (slot >= capacity) return false;
  deepWalks[slot] = item;
  if (slot % gl_WorkGroupSize.x == 0u) atomicAdd(control.deepArgs.x, 1u);
  atomicAdd(control.deepWalksDeferred, 1u);
  return true;
}

// traceRay for a queued item: false when the walk was deferred to the deep pass (the caller then leaves the item
// alone). complete = false: the walk was cut short (loop limit, or no room to defer it); the caller reports it.
bool traceItem(uint item, vec3 origin, vec3 dir, float tMax, bool anyHit, out vec4 hit, out bool complete) {
#ifdef VKMC_DEEP_PASS
  hit = traceRayDeep(origin, dir, tMax, anyHit, complete);
  atomicAdd(control.deepWalksTraced, 1u);
  return true;
#else
  bool overflow;
  hit = traceRayShallow(origin, dir, tMax, anyHit, complete, overflow);
  if (!overflow) return true;
  complete = false;
  // kDeepWalks 0: the host proved no walk overflows (kBvhRegisterStackEntries); one that did is reported as cut.
  return kDeepWalks == 0u || !deferWalk(item);
#endif
}
