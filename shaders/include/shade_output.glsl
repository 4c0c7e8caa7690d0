// Where a shaded vertex's results go in the wavefront (shade.comp, ears_copies.comp): radiance into its sample,
// continuations into the next bounce's queue.

// Under EARS a copy's radiance and its rays in one go: `value` into its sample (a non-finite one counted and
// poisoning it, as addToSample), and, for a training path, `trained` (if finite) and `rays` into its slot's sums:
// one read and one write of the slot.
#ifdef VKMC_FLOAT_ATOMICS
void atomicAddToRoot(uint root, vec3 value) {
  atomicAdd(paths[root].radiance.r, value.r);
  atomicAdd(paths[root].radiance.g, value.g);
  atomicAdd(paths[root].radiance.b, value.b);
}

void addToEarsSample(uint id, uint root, vec3 value, vec3 trained, float rays) {
  bool finite = allFinite(value);
  if (!finite) ++rareCounts.x;
  if (earsTrains()) earsSlots[id].gathered += vec4(allFinite(trained) ? trained : vec3(0.0), rays);
  if (finite && !(maxComponent(abs(value)) > 0.0)) return;
  atomicAddToRoot(root, value);
}
#endif

// Radiance of a sample accumulates in its root path. A non-finite value is counted here by kind and still
// added: the whole sample is then excluded (and counted) by accumulate, never written to the image. Without BSDF
// splitting a path is its own root and is alone in its slot during this dispatch; with splitting, siblings add
// concurrently, hence the atomics.
// Under EARS a training path's slot also sums what it gathered (finite values only), for the cache.
void addToSample(uint id, uint root, vec3 value) {
#ifdef VKMC_FLOAT_ATOMICS
  if (kRouletteMode == kRouletteEars) {
    addToEarsSample(id, root, value, value, 0.0);
    return;
  }
#endif
  if (!allFinite(value)) ++rareCounts.x;
  else if (!(maxComponent(abs(value)) > 0.0)) return;
#ifdef VKMC_FLOAT_ATOMICS
  if (kBsdfSamples > 1.0) {
    atomicAddToRoot(root, value);
    return;
  }
#endif
  vec4 radiance = loadRadiance(id);
  storeRadiance(id, vec4(radiance.rgb + value, radiance.w));
}

// Takes n path slots for split children from the pool (all of a pass's bounces share it): true and the first,
// or false, counted, when the pool cannot hold them; the caller then goes on unsplit (q = 1: decided before the
// draw, so unbiased).
bool reserveChildSlots(uint n, out uint first) {
  uint base = atomicAdd(control.splitChildren, n);
  first = 0u;
  if (pc.pathCount + base + n > pc.queueCapacity) {
    ++rareCounts.w;
    return false;
  }
  first = pc.pathCount + base;
  return true;
}

// Queue appends take one atomic per subgroup: an active lane's slot is the subgroup's base plus its rank among
// the active lanes. (llvmpipe runs a subgroup's atomics one lane after another, on counters its threads share.)
// Call where the appending lanes are exactly the active ones.
uint appendSlot(uint subgroupBase) { return subgroupBroadcastFirst(subgroupBase) + subgroupExclusiveAdd(1u); }

uint shadowQueueSlot() {
  uint n = subgroupAdd(1u), base = 0u;
  if (subgroupElect()) base = atomicAdd(control.shadowQueueCount, n);
  return appendSlot(base);
}

uint nextBounceQueueSlot() {
  uint n = subgroupAdd(1u), base = 0u;
  if (subgroupElect()) base = atomicAdd(control.rayQueueCount[(pc.bounce + 1u) & 1u], n);
  return appendSlot(base);
}

// Path `target`'s next ray, queued for the next bounce; a fresh split child starts with no radiance.
void queueContinuation(uint target, PathState next, bool fresh) {
  storePathRay(target, next);
  if (fresh) storeRadiance(target, vec4(0.0));
  rayQueues[outQueueBase() + nextBounceQueueSlot()] = target;
}

